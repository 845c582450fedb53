#pragma once
// Four floats in one register for the BVH build's inner loops: SSE2 where the target has it, plain
// floats elsewhere. Both give the same bits: every operation is one IEEE operation per lane, and
// min and max follow the SSE rule (min(a, b) = a < b ? a : b, so a NaN in either picks b).
#include <cstdint>
#include <cstring>

#if (defined(__SSE2__) || defined(_M_X64)) && !defined(GLINT_BVH_NO_SIMD)
#include <emmintrin.h>
#define GLINT_BVH_SSE2 1
#endif

namespace glint::bvh::simd {

#if GLINT_BVH_SSE2

struct F4 {
    __m128 v;
};

inline F4 load(const float* p) { return {_mm_loadu_ps(p)}; }
inline void store(float* p, F4 a) { _mm_storeu_ps(p, a.v); }
inline F4 splat(float x) { return {_mm_set1_ps(x)}; }
inline F4 set(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
inline F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline F4 min(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
inline F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
// Lanes 0-2 kept, lane 3 zero.
inline F4 xyz(F4 a) { return {_mm_and_ps(a.v, _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)))}; }
// Lanes where a > b, as a bit mask (bit i: lane i).
inline int greaterMask(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmpgt_ps(a.v, b.v)); }
// All lanes zero where `zero` is true.
inline F4 zeroIf(bool zero, F4 a) { return {_mm_andnot_ps(_mm_castsi128_ps(_mm_set1_epi32(zero ? -1 : 0)), a.v)}; }
// `pick ? a : b`, without a branch.
inline F4 select(bool pick, F4 a, F4 b)
{
    const __m128 mask = _mm_castsi128_ps(_mm_set1_epi32(pick ? -1 : 0));
    return {_mm_or_ps(_mm_and_ps(mask, a.v), _mm_andnot_ps(mask, b.v))};
}
// Lanes truncated towards zero (the caller keeps them within int range).
inline void truncate(F4 a, std::int32_t out[4]) { _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(a.v)); }
inline float lane(F4 a, int i)
{
    float out[4];
    _mm_storeu_ps(out, a.v);
    return out[i];
}
// (a.y, a.z, a.x, a.w)
inline F4 yzx(F4 a) { return {_mm_shuffle_ps(a.v, a.v, _MM_SHUFFLE(3, 0, 2, 1))}; }

// Lane masks (all bits set where true) and their operations.
inline F4 lessMask(F4 a, F4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline F4 greaterMaskLanes(F4 a, F4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline F4 operator&(F4 a, F4 b) { return {_mm_and_ps(a.v, b.v)}; }
inline F4 operator|(F4 a, F4 b) { return {_mm_or_ps(a.v, b.v)}; }
inline F4 andNot(F4 mask, F4 a) { return {_mm_andnot_ps(mask.v, a.v)}; } // a where mask is clear, else 0
inline F4 select(F4 mask, F4 a, F4 b) { return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))}; }
inline int bits(F4 mask) { return _mm_movemask_ps(mask.v); }

// Four 32-bit integers.
struct I4 {
    __m128i v;
};
inline I4 seti(std::int32_t x, std::int32_t y, std::int32_t z, std::int32_t w) { return {_mm_setr_epi32(x, y, z, w)}; }
inline I4 splati(std::int32_t x) { return {_mm_set1_epi32(x)}; }
inline I4 operator+(I4 a, I4 b) { return {_mm_add_epi32(a.v, b.v)}; }
inline F4 equalMask(I4 a, I4 b) { return {_mm_castsi128_ps(_mm_cmpeq_epi32(a.v, b.v))}; }
inline F4 toFloat(I4 a) { return {_mm_cvtepi32_ps(a.v)}; } // exact below 2^24, rounded to nearest above
inline I4 select(F4 mask, I4 a, I4 b)
{
    const __m128i m = _mm_castps_si128(mask.v);
    return {_mm_or_si128(_mm_and_si128(m, a.v), _mm_andnot_si128(m, b.v))};
}
inline std::int32_t lanei(I4 a, int i)
{
    std::int32_t out[4];
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), a.v);
    return out[i];
}

// Rows a, b, c to columns: x = (a0, b0, c0, 0), y = (a1, b1, c1, 0), z = (a2, b2, c2, 0) and
// w = (a3, b3, c3, 0).
inline void transpose3(F4 a, F4 b, F4 c, F4& x, F4& y, F4& z, F4& w)
{
    const __m128 zero = _mm_setzero_ps();
    const __m128 ab01 = _mm_unpacklo_ps(a.v, b.v); // a0 b0 a1 b1
    const __m128 c01 = _mm_unpacklo_ps(c.v, zero); // c0 0 c1 0
    const __m128 ab23 = _mm_unpackhi_ps(a.v, b.v); // a2 b2 a3 b3
    const __m128 c23 = _mm_unpackhi_ps(c.v, zero); // c2 0 c3 0
    x = {_mm_movelh_ps(ab01, c01)};
    y = {_mm_movehl_ps(c01, ab01)};
    z = {_mm_movelh_ps(ab23, c23)};
    w = {_mm_movehl_ps(c23, ab23)};
}
inline void transpose3(F4 a, F4 b, F4 c, F4& x, F4& y, F4& z)
{
    F4 w;
    transpose3(a, b, c, x, y, z, w);
}
// Lanes truncated towards zero, as integers (the caller keeps them within int range).
inline I4 truncatei(F4 a) { return {_mm_cvttps_epi32(a.v)}; }
// Lanes truncated towards zero and multiplied by 2^shift, as unsigned integers (the caller keeps
// them within range).
template <int Shift>
inline void truncateShifted(F4 a, std::uint32_t out[4])
{
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_slli_epi32(_mm_cvttps_epi32(a.v), Shift));
}

// Lanes truncated towards zero (each within [0, 128)): times 2^Shift into `out`, and lanes 0-3 as
// the bytes of the result, lane 0 lowest.
template <int Shift>
inline std::uint32_t truncateShiftedAndBytes(F4 a, std::uint32_t out[4])
{
    const __m128i whole = _mm_cvttps_epi32(a.v);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_slli_epi32(whole, Shift));
    const __m128i halves = _mm_packs_epi32(whole, whole);
    return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(halves, halves)));
}
// Bit i set where byte `byte` of words[i] is below k, for 16 words whose bytes are below 128.
inline std::uint32_t bytesBelow16(const std::uint32_t* words, int byte, std::uint8_t k)
{
    const __m128i shift = _mm_cvtsi32_si128(8 * byte), low = _mm_set1_epi32(0xFF);
    const auto column = [&](int i) {
        return _mm_and_si128(_mm_srl_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(words + 4 * i)), shift), low);
    };
    const __m128i bytes = _mm_packs_epi16(_mm_packs_epi32(column(0), column(1)), _mm_packs_epi32(column(2), column(3)));
    return static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmplt_epi8(bytes, _mm_set1_epi8(static_cast<char>(k)))));
}

#else

struct F4 {
    float v[4];
};

inline F4 load(const float* p)
{
    F4 r;
    std::memcpy(r.v, p, sizeof(r.v));
    return r;
}
inline void store(float* p, F4 a) { std::memcpy(p, a.v, sizeof(a.v)); }
inline F4 splat(float x) { return {{x, x, x, x}}; }
inline F4 set(float x, float y, float z, float w) { return {{x, y, z, w}}; }
template <class Op>
inline F4 lanes(F4 a, F4 b, Op op)
{
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
inline F4 operator+(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return x + y; }); }
inline F4 operator-(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return x - y; }); }
inline F4 operator*(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return x * y; }); }
inline F4 min(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline F4 max(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline F4 xyz(F4 a)
{
    a.v[3] = 0.0f;
    return a;
}
inline int greaterMask(F4 a, F4 b)
{
    int mask = 0;
    for (int i = 0; i < 4; ++i) mask |= a.v[i] > b.v[i] ? 1 << i : 0;
    return mask;
}
inline F4 zeroIf(bool zero, F4 a) { return zero ? splat(0.0f) : a; }
inline F4 select(bool pick, F4 a, F4 b) { return pick ? a : b; }
inline void truncate(F4 a, std::int32_t out[4])
{
    for (int i = 0; i < 4; ++i) out[i] = static_cast<std::int32_t>(a.v[i]);
}
inline float lane(F4 a, int i) { return a.v[i]; }
inline F4 yzx(F4 a) { return {{a.v[1], a.v[2], a.v[0], a.v[3]}}; }

inline float maskLane(bool set)
{
    const std::uint32_t bits = set ? 0xFFFFFFFFu : 0u;
    float f;
    std::memcpy(&f, &bits, sizeof(f));
    return f;
}
inline bool isSet(float lane)
{
    std::uint32_t bits;
    std::memcpy(&bits, &lane, sizeof(bits));
    return bits != 0;
}
inline F4 lessMask(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return maskLane(x < y); }); }
inline F4 greaterMaskLanes(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return maskLane(x > y); }); }
inline F4 operator&(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return maskLane(isSet(x) && isSet(y)); }); }
inline F4 operator|(F4 a, F4 b) { return lanes(a, b, [](float x, float y) { return maskLane(isSet(x) || isSet(y)); }); }
inline F4 andNot(F4 mask, F4 a) { return lanes(mask, a, [](float m, float x) { return isSet(m) ? 0.0f : x; }); }
inline F4 select(F4 mask, F4 a, F4 b)
{
    return {{isSet(mask.v[0]) ? a.v[0] : b.v[0], isSet(mask.v[1]) ? a.v[1] : b.v[1], isSet(mask.v[2]) ? a.v[2] : b.v[2],
             isSet(mask.v[3]) ? a.v[3] : b.v[3]}};
}
inline int bits(F4 mask)
{
    int out = 0;
    for (int i = 0; i < 4; ++i) out |= isSet(mask.v[i]) ? 1 << i : 0;
    return out;
}

struct I4 {
    std::int32_t v[4];
};
inline I4 seti(std::int32_t x, std::int32_t y, std::int32_t z, std::int32_t w) { return {{x, y, z, w}}; }
inline I4 splati(std::int32_t x) { return {{x, x, x, x}}; }
inline I4 operator+(I4 a, I4 b)
{
    I4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = static_cast<std::int32_t>(static_cast<std::uint32_t>(a.v[i]) + static_cast<std::uint32_t>(b.v[i]));
    return r;
}
inline F4 equalMask(I4 a, I4 b) { return {{maskLane(a.v[0] == b.v[0]), maskLane(a.v[1] == b.v[1]), maskLane(a.v[2] == b.v[2]), maskLane(a.v[3] == b.v[3])}}; }
inline F4 toFloat(I4 a) { return {{static_cast<float>(a.v[0]), static_cast<float>(a.v[1]), static_cast<float>(a.v[2]), static_cast<float>(a.v[3])}}; }
inline I4 select(F4 mask, I4 a, I4 b)
{
    I4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = isSet(mask.v[i]) ? a.v[i] : b.v[i];
    return r;
}
inline std::int32_t lanei(I4 a, int i) { return a.v[i]; }
inline void transpose3(F4 a, F4 b, F4 c, F4& x, F4& y, F4& z, F4& w)
{
    x = {{a.v[0], b.v[0], c.v[0], 0.0f}};
    y = {{a.v[1], b.v[1], c.v[1], 0.0f}};
    z = {{a.v[2], b.v[2], c.v[2], 0.0f}};
    w = {{a.v[3], b.v[3], c.v[3], 0.0f}};
}
inline void transpose3(F4 a, F4 b, F4 c, F4& x, F4& y, F4& z)
{
    F4 w;
    transpose3(a, b, c, x, y, z, w);
}
inline I4 truncatei(F4 a) { return {{static_cast<std::int32_t>(a.v[0]), static_cast<std::int32_t>(a.v[1]), static_cast<std::int32_t>(a.v[2]), static_cast<std::int32_t>(a.v[3])}}; }
template <int Shift>
inline void truncateShifted(F4 a, std::uint32_t out[4])
{
    for (int i = 0; i < 4; ++i) out[i] = static_cast<std::uint32_t>(static_cast<std::int32_t>(a.v[i])) << Shift;
}
template <int Shift>
inline std::uint32_t truncateShiftedAndBytes(F4 a, std::uint32_t out[4])
{
    std::uint32_t bytes = 0;
    for (int i = 0; i < 4; ++i) {
        const auto whole = static_cast<std::uint32_t>(static_cast<std::int32_t>(a.v[i]));
        out[i] = whole << Shift;
        bytes |= whole << (8 * i);
    }
    return bytes;
}
inline std::uint32_t bytesBelow16(const std::uint32_t* words, int byte, std::uint8_t k)
{
    std::uint32_t mask = 0;
    for (std::uint32_t i = 0; i < 16; ++i) mask |= std::uint32_t{((words[i] >> (8 * byte)) & 0xFF) < k} << i;
    return mask;
}

#endif

} // namespace glint::bvh::simd
