#pragma once
// The `bvh_cost` AOV: the BVH heat map rendered headless. Per pixel, the mean over the request's
// samples (jittered camera rays, as the beauty pass uses) of the camera ray's closest-hit work:
// BVH nodes visited (both levels) plus primitives tested. 0 where the rays miss the scene's
// bounds and in scenes without meshes. A second render of its own shader variant
// (DebugView::BvhCost, Accumulate): the beauty render is not touched by it.
#include "renderer/offline_render.h"

#include <vector>

namespace glint::renderer {

// One float per pixel, rows top-down. Deterministic: the same scene and request give the same values.
std::vector<float> renderBvhCost(OfflineRenderer& renderer, const Scene& scene, RenderRequest request);

} // namespace glint::renderer
