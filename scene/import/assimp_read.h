#pragma once
// Reads a file with Assimp (triangulated, joined vertices, smooth normals where missing, validated)
// and converts it. Runs inside glint-import-worker.
#include "assimp_convert.h"

namespace glint {

// Throws FileError ("import-failed" with Assimp's message, or convertAssimpScene's errors).
LoadResult readWithAssimp(const std::filesystem::path& file, const ConvertOptions& options);

} // namespace glint
