#pragma once
// Random numbers that are the same on every standard library: std::mt19937's output is fixed by
// the standard, but std::uniform_*_distribution is not, so the mapping to ranges is our own.
#include <cstdint>
#include <random>
#include <vector>

namespace glint::test {

class RandomSource {
public:
    explicit RandomSource(std::uint32_t seed) : engine_(seed) {}

    // Uniform in [0, n) by fixed-point multiplication (bias below 2^-32 n, fine for tests).
    std::uint32_t below(std::uint32_t n) {
        return static_cast<std::uint32_t>((static_cast<std::uint64_t>(engine_()) * n) >> 32);
    }
    // Uniform in [lo, hi) with 24 random bits.
    float between(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(engine_() >> 8) * 0x1p-24f; }
    bool chance(std::uint32_t percent) { return below(100) < percent; }

    template <class T>
    const T& pick(const std::vector<T>& values) {
        return values[below(static_cast<std::uint32_t>(values.size()))];
    }

private:
    std::mt19937 engine_;
};

} // namespace glint::test
