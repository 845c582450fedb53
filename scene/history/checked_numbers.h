#pragma once
// Numbers from an untrusted command log, converted without undefined behaviour. nlohmann converts
// a JSON number to any arithmetic type with a plain cast, and a cast of a floating-point value that
// the target cannot hold (8e85 to a byte, -1.5 to an unsigned, 1e300 to a float) is undefined: a
// fuzzed log found it. checkedNumber converts one value or throws; safeNumbers prepares a whole log
// entry for the macro-generated readers, which cast as nlohmann does.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace glint {

template <class T>
T checkedNumber(const nlohmann::json& j) {
    static_assert(std::is_arithmetic_v<T>);
    if constexpr (std::is_same_v<T, bool>) {
        return j.get<bool>();
    } else if constexpr (std::is_integral_v<T>) {
        if (j.is_number_unsigned()) {
            const auto v = j.get<std::uint64_t>();
            if (std::in_range<T>(v)) return static_cast<T>(v);
        } else if (j.is_number_integer()) {
            const auto v = j.get<std::int64_t>();
            if (std::in_range<T>(v)) return static_cast<T>(v);
        } else if (j.is_number_float()) {
            const double v = j.get<double>();
            if (std::isfinite(v) && v == std::trunc(v) && v >= double(std::numeric_limits<T>::min()) &&
                v <= double(std::numeric_limits<T>::max()))
                return static_cast<T>(v);
        }
        throw std::invalid_argument("number out of range: " + j.dump());
    } else {
        if (!j.is_number()) throw std::invalid_argument("not a number: " + j.dump());
        const double v = j.get<double>();
        if (std::isfinite(v) && std::abs(v) > double(std::numeric_limits<T>::max()))
            throw std::invalid_argument("number out of range: " + j.dump());
        return static_cast<T>(v);
    }
}

// A copy of `j` in which every floating-point number is one that any field may take: integral
// values become integers (so an integer field reads them without a float cast); a value beyond a
// float's range, or non-integral beyond +-2^31 (no command value is either), is refused.
inline nlohmann::json safeNumbers(nlohmann::json j) {
    if (j.is_structured()) {
        for (auto& element : j) element = safeNumbers(std::move(element));
        return j;
    }
    if (!j.is_number_float()) return j;
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > double(std::numeric_limits<float>::max()))
        throw std::invalid_argument("number out of range: " + j.dump());
    if (v == 0.0 && std::signbit(v)) return j; // -0 stays a float: its sign is part of the value
    if (v == std::trunc(v) && std::abs(v) < 9.2e18) return v < 0 ? nlohmann::json(std::int64_t(v)) : nlohmann::json(std::uint64_t(v));
    if (std::abs(v) >= 2147483648.0) throw std::invalid_argument("number out of range: " + j.dump());
    return j;
}

} // namespace glint
