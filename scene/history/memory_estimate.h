#pragma once
// Rough sizes of what commands hold, for History's memory bound. Big arrays (mesh attributes,
// encoded images) dominate; JSON kept for unknown extensions is not counted.
#include "scene/core/scene.h"

#include <cstddef>

namespace glint {

std::size_t approxBytes(const Node& node);
std::size_t approxBytes(const Mesh& mesh);
std::size_t approxBytes(const Image& image);
std::size_t approxBytes(const Material& material);
std::size_t approxBytes(const Texture& texture);
std::size_t approxBytes(const Sampler& sampler);
std::size_t approxBytes(const Animation& animation);

} // namespace glint
