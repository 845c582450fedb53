#pragma once
// Writing rendered images (docs/CLI.md, "Images"):
// - EXR: 32-bit float, ZIP, linear Rec.709; beauty R,G,B,A (A = coverage) and AOVs albedo.R/G/B,
//   N.X/Y/Z, Z, id in the same file, with metadata.
// - PNG/JPEG/TIFF: the tonemapped sRGB image, 8 bits.
// Every file is written under a temporary name in the target folder and renamed into place, so a
// crash or a full disk never leaves a partial file under the final name.
#include "renderer/offline_render.h"

#include <array>
#include <filesystem>
#include <map>
#include <string>

namespace glint::renderer {

enum class ImageFormat { Exr, Png, Jpeg, Tiff };

// From the extension (case-insensitive); throws std::invalid_argument naming the accepted ones.
ImageFormat imageFormatFor(const std::filesystem::path& file);

// The EXR's render passes (docs/CLI.md, "Render passes"): the light passes DiffDir, DiffInd,
// GlossDir, GlossInd, Emit and Env, which sum to the beauty R, G, B, and the motion vectors Vector.
struct RenderPasses {
    std::array<bool, lightPassCount> light{}; // indexed by LightPass
    bool vector = false;
    bool any() const;
    friend bool operator==(const RenderPasses&, const RenderPasses&) = default;
};

// The EXR layer name of a light pass ("DiffDir", ...).
const char* lightPassName(LightPass pass);

// Parses --passes and the project's output.passes: "all", "none" (or empty), "light" (the six
// light passes) or a comma list of their layer names and Vector, any case. Throws
// std::invalid_argument naming an unknown pass.
RenderPasses parsePassList(const std::string& list);
// The canonical list, as the metadata records it: "DiffDir,DiffInd,...,Vector"; "" for none.
std::string passListName(const RenderPasses& passes);

struct ExrLayers {
    bool albedo = true;
    bool normal = true;
    bool depth = true;
    bool objectId = true;
    bool variance = false; // optional: only when listed
    bool bvhCost = false;  // optional debug AOV `bvh_cost` (one float channel): only when listed
    bool samples = false;  // optional AOV `samples`: each pixel's sample count (adaptive sampling), when listed
    RenderPasses passes;   // --passes: none unless asked for
};

// Parses --aovs: "all" (every layer but the optional variance), "none" or a comma list of albedo,
// normal, depth, id, variance, bvh_cost, samples.
ExrLayers parseAovList(const std::string& list);

using ImageMetadata = std::map<std::string, std::string>; // written as string attributes "glint:<key>"

// Every format also gets ImageDescription = this prefix + the "settingsHash" entry.
inline constexpr const char* kSettingsHashPrefix = "glint:settingsHash=";

// Makes sure the folder of `file` exists and is writable, creating the missing folders on its path
// (as mkdir -p does), so a long render is not wasted on an output that cannot be saved. FileError
// naming the file when a part of the path is a file, or the folder cannot be made or written.
void prepareOutputFolder(const std::filesystem::path& file);

// Throws FileError(file, ...) when the file cannot be written.
void writeRenderImage(const std::filesystem::path& file, const RenderOutput& image, const ExrLayers& layers,
                      const ImageMetadata& metadata);

} // namespace glint::renderer
