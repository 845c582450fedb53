// Constants of the path tracer beyond common/math.glsl.
#include "common/math.glsl"

const float RAY_MAX = 3.0e38;
