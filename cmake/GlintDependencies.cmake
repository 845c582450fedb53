# One place that finds every third-party package, so each layer links targets, not paths.
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(assimp REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)

# OpenImageIO's CMake config references packages we do not need (opencv include path,
# iconvert); pkg-config gives the library without them.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)

if(NOT GLINT_SCENE_ONLY)
  find_package(OpenEXR REQUIRED)
  pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
  find_package(OpenGL REQUIRED COMPONENTS EGL)
  find_package(Qt6 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Test LinguistTools)
endif()
