# Warnings are errors in Glint's own code only; third-party headers come in as SYSTEM.
function(glint_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()
