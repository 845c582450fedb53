#pragma once
// Runs body(i) for i in [0, count) on up to `threads` threads (the caller's included). Which thread
// runs which index varies; callers make each index write only its own outputs, so results never
// depend on it.
#include <cstddef>
#include <functional>

namespace glint::bvh {

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

} // namespace glint::bvh
