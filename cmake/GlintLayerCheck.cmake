# Dependencies point one way: app -> editor -> renderer -> scene. This check keeps the
# scene libraries free of Qt and GL by inspecting what each one links, directly or through
# other Glint libraries.
function(glint_check_layer)
  foreach(target ${ARGN})
    get_target_property(libs ${target} LINK_LIBRARIES)
    get_target_property(ilibs ${target} INTERFACE_LINK_LIBRARIES)
    foreach(lib ${libs} ${ilibs})
      if(lib MATCHES "Qt[0-9]*::|OpenGL::|EPOXY|epoxy|EGL|glint_renderer|glint_editor")
        message(FATAL_ERROR "Layering: ${target} links ${lib}; scene/ must not depend on Qt, GL or higher layers")
      endif()
    endforeach()
  endforeach()
endfunction()
