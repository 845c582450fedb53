#pragma once
// One still render of a test scene at size x size through the offline renderer, the way most
// renderer tests ask for it. stillRequest is the same request for tests that set one more field
// (an environment, a tonemapper, the independent sampler).
#include "renderer/offline_render.h"

#include <cstdint>

namespace glint::test {

inline renderer::RenderRequest stillRequest(int size, int spp, std::uint32_t seed, int bounces = 0) {
    renderer::RenderRequest request;
    request.width = size;
    request.height = size;
    request.spp = spp;
    request.seed = seed;
    request.bounces = bounces;
    return request;
}

inline renderer::RenderOutput renderScene(renderer::OfflineRenderer& r, const Scene& scene, int size, int spp, std::uint32_t seed,
                                          int bounces = 0) {
    return r.render(scene, stillRequest(size, spp, seed, bounces));
}

} // namespace glint::test
