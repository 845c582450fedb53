#pragma once
// Units and axes: glTF is metres and +Y up.
// - FBX says both in its metadata (UnitScaleFactor in centimetres per unit; UpAxis, FrontAxis,
//   CoordAxis and their signs), which Assimp passes on but does not apply: this does.
// - Collada's <unit> and <up_axis>, and 3DS's Z-up, Assimp already applies to the root node.
// - OBJ, PLY and STL carry neither. STL and PLY files are often Z-up in millimetres, but nothing in
//   the file says so, so they are kept as they are (1 unit = 1 metre, +Y up); re-orient after import.
#include "scene/core/diagnostics.h"

#include <glm/glm.hpp>

struct aiMetadata;

namespace glint {

// glintFromFile: maps file coordinates to metres, +Y up, +Z front. Identity without metadata.
glm::mat4 glintFromFileAxes(const aiMetadata* metadata, const std::string& file, Warnings& warnings);

} // namespace glint
