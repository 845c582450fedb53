#include "renderer/bvh/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace glint::bvh {

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& body)
{
    const std::size_t workers = std::min<std::size_t>(count, static_cast<std::size_t>(std::max(threads, 1)));
    if (workers <= 1) {
        for (std::size_t i = 0; i < count; ++i) body(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    const auto drain = [&] {
        for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1)) body(i);
    };
    std::vector<std::thread> helpers;
    helpers.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) helpers.emplace_back(drain);
    drain();
    for (auto& helper : helpers) helper.join();
}

} // namespace glint::bvh
