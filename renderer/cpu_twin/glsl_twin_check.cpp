// Compiles the shared GLSL as C++ in the library itself, so a change that breaks the C++ side of a
// shader file fails the renderer's build, not only the tests.
#include "renderer/cpu_twin/glsl_twin.h"
