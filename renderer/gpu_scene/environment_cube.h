#pragma once
// Cube-map environments, turned into the equirectangular image the renderer samples. A cube map
// comes as one image holding six square faces, recognised by its shape (docs/UNITS.md,
// "Environment"): a horizontal cross (4:3), a vertical cross (3:4, the -Z face upside down below
// -Y), or a strip of the faces +X, -X, +Y, -Y, +Z, -Z in a row (6:1) or a column (1:6). Faces are
// named as cube maps name them, in a left-handed frame (DirectX's, Unity's): glTF's +X and +Y, and
// +Z towards glTF's -Z, so the cross's centre (+Z) is in front of the default camera; each face
// reads unmirrored from inside, the side faces' tops towards +Y.
#include "renderer/gpu_scene/environment_image.h"

#include <optional>

namespace glint::renderer {

enum class CubeLayout { HorizontalCross, VerticalCross, HorizontalStrip, VerticalStrip };

// The layout an image of this size holds, if it is one (face sides of at least 1 pixel).
std::optional<CubeLayout> cubeLayoutOf(int width, int height);

// The side of one face of a cube map `width` pixels wide in this layout.
int cubeFaceSide(CubeLayout layout, int width);

// The cube resampled (bilinear within each face) to an equirectangular image 4 faces wide and 2
// high, in the orientation of docs/UNITS.md.
EnvironmentImage equirectFromCube(const EnvironmentImage& cube, CubeLayout layout);

} // namespace glint::renderer
