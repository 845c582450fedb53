#pragma once
// What the viewport shows. The path-traced view is the default; the others are preview and debug
// views: ambient occlusion comes from the path tracer, the G-buffer views from its read-back
// images (shading normal, albedo, motion vectors, variance, depth, object ids), and the raster
// ones (solid, wireframe, and the solid view under the BVH's instance boxes) from renderer/raster.
// The BVH heat map is a path-tracer variant that counts the camera ray's BVH work per pixel
// (nodes visited + primitives tested, both levels), shown colour-mapped with a legend.
#include <array>

namespace glint::editor {

enum class ViewMode { PathTraced, Solid, Wireframe, Normals, Albedo, AmbientOcclusion, Motion, Variance, Depth, BvhBoxes,
                      BvhCost };

inline constexpr std::array<ViewMode, 11> kViewModes{ViewMode::PathTraced, ViewMode::Solid,    ViewMode::Wireframe,
                                                     ViewMode::Normals,    ViewMode::Albedo,   ViewMode::AmbientOcclusion,
                                                     ViewMode::Motion,     ViewMode::Variance, ViewMode::Depth,
                                                     ViewMode::BvhBoxes,   ViewMode::BvhCost};

// Views that show a read-back G-buffer image instead of the tonemapped frame.
inline bool showsReadBack(ViewMode mode) {
    return mode == ViewMode::Normals || mode == ViewMode::Albedo || mode == ViewMode::Motion || mode == ViewMode::Variance ||
           mode == ViewMode::Depth || mode == ViewMode::BvhCost;
}

// Views drawn by the raster preview pass instead of the path tracer.
inline bool showsRaster(ViewMode mode) { return mode == ViewMode::Solid || mode == ViewMode::Wireframe || mode == ViewMode::BvhBoxes; }

} // namespace glint::editor
