#pragma once
// The display transform of shaders/passes/tonemap*.glsl on the CPU: exposure, tone curve (ACES
// fitted, Khronos PBR Neutral, AgX, Reinhard extended, Hable, none), explicit sRGB encode, 8-bit round to nearest. Used to put
// EXR frames into a video as the PNG path would have shown them; a value may differ from the
// GPU's by one code where the GPU's pow() rounds differently.
#include "scene/core/settings.h"

#include <cstdint>
#include <vector>

namespace glint::video {

// `rgba` is linear radiance, 4 floats per pixel; alpha passes through clamped.
std::vector<std::uint8_t> tonemapToSrgb8(const std::vector<float>& rgba, float exposureEv, Tonemapper tonemapper);

} // namespace glint::video
