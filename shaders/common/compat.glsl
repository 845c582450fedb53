// Shared-source conventions: files under common/, sampling/ and bsdf/ compile as GLSL 4.10 and, through
// renderer/cpu_twin/glsl_twin.h, as C++ with GLM. Out-parameters go through these macros because
// GLSL writes `out T` where C++ needs `T&`; components are read as .x/.y/.z/.w only (no swizzles);
// float literals carry an `f` so GLM's templates see float, not double; constant tables go
// through FLOAT_TABLE (GLSL array constructor, std::array in C++).
#ifdef __cplusplus
#pragma once
#else
#ifndef OUT
#define OUT(T) out T
#endif
#ifndef INOUT
#define INOUT(T) inout T
#endif
// A constant float table: FLOAT_TABLE(NAME, 4)(1.0f, 2.0f, 3.0f, 4.0f); indexed as NAME[i].
#ifndef FLOAT_TABLE
#define FLOAT_TABLE(name, n) const float name[n] = float[n]
#endif
#endif
