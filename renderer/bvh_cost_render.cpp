#include "renderer/bvh_cost_render.h"

#include <algorithm>

namespace glint::renderer {

std::vector<float> renderBvhCost(OfflineRenderer& renderer, const Scene& scene, RenderRequest request) {
    // The cost is a property of the camera rays alone: accumulate its mean over the same number
    // of jittered rays, without reconstruction (TAA/SVGF would blur counts with history).
    const bool accumulate = traitsOf(request.configuration).accumulate;
    request.spp = accumulate ? request.spp : std::max(1, request.spp * request.frames);
    request.configuration = Configuration::Accumulate;
    request.frames = 1;
    request.view = DebugView::BvhCost;
    request.progress = {};
    request.clamp = 0.0f; // counts, not radiance
    const RenderOutput out = renderer.render(scene, request);
    std::vector<float> cost;
    cost.reserve(out.radiance.size() / 4);
    for (std::size_t i = 0; i < out.radiance.size(); i += 4) cost.push_back(out.radiance[i]);
    return cost;
}

} // namespace glint::renderer
