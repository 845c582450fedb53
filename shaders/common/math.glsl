// Constants and small helpers shared by the sampling and BSDF code.
#ifdef __cplusplus
#pragma once
#endif
#include "common/compat.glsl"

const float PI = 3.14159265358979f;
const float TWO_PI = 6.28318530717959f;
const float INV_PI = 0.318309886183791f;
const float INV_TWO_PI = 0.159154943091895f;
const float INV_FOUR_PI = 0.0795774715459477f;
const float PI_OVER_TWO = 1.5707963267949f;
const float PI_OVER_FOUR = 0.785398163397448f;

float sqr(float x) { return x * x; }

// sqrt that tolerates rounding just below zero (1 - cos^2 can come out as -1e-8).
float safeSqrt(float x) { return sqrt(max(x, 0.0f)); }

float maxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }

// Rec. 709 luminance of linear RGB.
float luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

// isnan/isinf may be optimised away by GLSL compilers: test the exponent bits instead.
bool isFiniteFloat(float x) { return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u; }

bool isFiniteVec3(vec3 v) { return isFiniteFloat(v.x) && isFiniteFloat(v.y) && isFiniteFloat(v.z); }
