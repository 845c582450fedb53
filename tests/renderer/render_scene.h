#pragma once
// One still render of a test scene at size x size through the offline renderer, the way most
// renderer tests ask for it.
#include "renderer/offline_render.h"

#include <cstdint>

namespace glint::test {

inline renderer::RenderOutput renderScene(renderer::OfflineRenderer& r, const Scene& scene, int size, int spp, std::uint32_t seed,
                                          int bounces = 0) {
    renderer::RenderRequest request;
    request.width = size;
    request.height = size;
    request.spp = spp;
    request.seed = seed;
    request.bounces = bounces;
    return r.render(scene, request);
}

} // namespace glint::test
