# Warnings are errors in Glint's own code only; third-party headers come in as SYSTEM.
function(glint_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  # GCC 12 reports -Wrestrict inside libstdc++'s std::string concatenation at -O3 (GCC bug 105329),
  # a false positive in code that is correct; keep it visible as a warning, not an error.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-error=restrict)
  endif()
endfunction()
