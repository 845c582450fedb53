// tinygltf's implementation, compiled into sanitizer and fuzz builds only (see ../CMakeLists.txt).
// Images never go through stb: Glint installs its own image loader and writer callbacks.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
