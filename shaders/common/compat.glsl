// Shared-source conventions: files under common/, sampling/ and bsdf/ compile as GLSL 4.10 and, through
// renderer/cpu_twin/glsl_twin.h, as C++ with GLM. Out-parameters go through these macros because
// GLSL writes `out T` where C++ needs `T&`; components are read as .x/.y/.z/.w only (no swizzles);
// float literals carry an `f` so GLM's templates see float, not double.
#ifdef __cplusplus
#pragma once
#else
#ifndef OUT
#define OUT(T) out T
#endif
#ifndef INOUT
#define INOUT(T) inout T
#endif
#endif
