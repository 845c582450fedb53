#pragma once
// Turns a read-back G-buffer image into something a person can look at: normals as 0.5 + 0.5 n,
// albedo as is, motion vectors as a signed red/green map, variance and depth normalised by their
// largest finite value. Values are clamped to [0, 1] and shown without tonemapping. The BVH heat
// map colours the cost (radiance.r of the BvhCost variant) from black (0: nothing walked) through
// blue, green and yellow to red at the legend's top value.
#include "editor/viewport/view_modes.h"
#include "renderer/frame_renderer.h"

#include <QColor>
#include <QImage>

namespace glint::editor {

// The BVH heat map's image carries its scale (bvhCostScale) as this text key, for the legend.
inline constexpr const char* kCostScaleKey = "glint:bvhCostScale";

QImage debugImage(const renderer::FrameImages& images, ViewMode mode);

// The heat map's colour at t in [0, 1] (clamped); black exactly at 0.
QColor heatColour(float t);
// The top of the heat map's scale: the largest cost in the image rounded up to 1, 2 or 5 x 10^k
// (at least 1), so the legend reads in round numbers and does not flicker with every sample.
float bvhCostScale(const renderer::FrameImages& images);

} // namespace glint::editor
