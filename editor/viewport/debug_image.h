#pragma once
// Turns a read-back G-buffer image into something a person can look at: normals as 0.5 + 0.5 n,
// albedo as is, motion vectors as a signed red/green map, variance and depth normalised by their
// largest finite value. Values are clamped to [0, 1] and shown without tonemapping.
#include "editor/viewport/view_modes.h"
#include "renderer/frame_renderer.h"

#include <QImage>

namespace glint::editor {

QImage debugImage(const renderer::FrameImages& images, ViewMode mode);

} // namespace glint::editor
