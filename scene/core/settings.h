#pragma once
// What glTF has no place for; saved in the project file <basename>.glint.json.
#include "ids.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace glint {

enum class LightUnits { Blender, Raw };
// Display transforms (shaders/passes/tonemap_curves.glsl; names: tonemapper_names.h). AgX is the
// published minimal AgX (Blender's default view since 4.0, approximated); Reinhard is the extended
// operator on luminance with white at 4; Hable is John Hable's Uncharted 2 filmic curve.
enum class Tonemapper { None, AcesFitted, PbrNeutral, AgX, Reinhard, Hable };

struct Environment {
    std::string file;       // relative to the project folder; empty = uniform colour
    glm::vec3 color{0.0f};  // radiance when no file is set (black by default: docs/UNITS.md)
    float intensity = 1.0f; // plain multiplier
    float rotationDegrees = 0.0f; // about +Y
    friend bool operator==(const Environment&, const Environment&) = default;
};

// Fog filling the scene (docs/MEDIA.md): a participating medium that scatters light, so suns, spots
// and area lights draw shafts through gaps. Its extinction is `density` per metre at `baseHeight`
// and falls as exp(-heightFalloff x (y - baseHeight)) with world height y (0: homogeneous). Of the
// light it extinguishes, `color` per channel is scattered (the single-scattering albedo) and the
// rest absorbed. A homogeneous fog fills all space, so the environment reaches the scene only
// through a height falloff. density 0: no fog, and the renderer compiles no medium code.
struct Fog {
    float density = 0.0f;        // 1/m, >= 0
    glm::vec3 color{1.0f};       // single-scattering albedo, each channel in [0, 1]
    float anisotropy = 0.0f;     // Henyey-Greenstein g in (-1, 1): > 0 scatters forward
    float heightFalloff = 0.0f;  // 1/m, >= 0
    float baseHeight = 0.0f;     // metres, world Y
    bool enabled() const { return density > 0.0f; }
    friend bool operator==(const Fog&, const Fog&) = default;
};

// Real-time reconstruction of the configurations with history (baseline, realistic, full, heavy;
// docs/DENOISING.md). Part of the project because it changes the pixels: the editor and the command
// line render a project with the same values. Written only where they differ from these defaults.
// How TAA keeps reprojected history close to this frame: clip it towards the YCoCg variance box of
// the 3x3 neighbourhood, clamp it to the neighbourhood's min/max box, or leave it (ghosts).
enum class TaaClip { Variance, MinMax, None };

struct TaaParameters {
    float blend = 0.1f;           // the current frame's weight on a long still history, (0, 1]
    TaaClip clip = TaaClip::Variance;
    float clipGamma = 1.25f;      // variance-clipping box half-size in standard deviations, (0, 16]
    bool perceptualBlend = false; // blend tonemapped colour (bounds fireflies, darkens noisy input)
    friend bool operator==(const TaaParameters&, const TaaParameters&) = default;
};

// Bloom on the displayed image (renderer/passes/bloom_pass.h): the share of light spread into
// glare, 0 (off) to 1, and the widest blur as a fraction of the image height.
struct BloomParameters {
    float strength = 0.0f;
    float radius = 0.05f;
    friend bool operator==(const BloomParameters&, const BloomParameters&) = default;
};

// What adaptive sampling stops tiles for (docs/CLI.md, "Adaptive sampling"):
// - Even: every pixel's noise below the threshold (Cycles' rule); the noise ends even over the image.
// - Mean: the least mean relMSE for the samples taken; a tile stops once one more sample would
//   lower its relMSE by less than threshold^2, so tiles end with samples in proportion to the
//   standard deviation of their relative noise (Neyman allocation).
enum class AdaptiveGoal { Even, Mean };

// The goals' names, one spelling everywhere: the project file, `--adaptive-goal` and EXR metadata.
constexpr const char* adaptiveGoalName(AdaptiveGoal goal) { return goal == AdaptiveGoal::Mean ? "mean" : "even"; }
inline std::optional<AdaptiveGoal> parseAdaptiveGoal(std::string_view name) {
    if (name == adaptiveGoalName(AdaptiveGoal::Even)) return AdaptiveGoal::Even;
    if (name == adaptiveGoalName(AdaptiveGoal::Mean)) return AdaptiveGoal::Mean;
    return std::nullopt;
}

// Adaptive sampling of stills (Accumulate and Reference; docs/CLI.md, "Adaptive sampling"):
// pixels stop taking samples by tiles of 8x8, by the goal's rule: Even, once the standard error of
// every mean in the tile, summed over R, G and B, is below threshold x sqrt(R + G + B of that
// mean); Mean, once sqrt(a) / n < threshold, a being the tile's relative variance per sample (the
// mean over its pixels and channels of the sample variance over mean^2 + 0.01) and n its samples.
// A tile decides from its own pixels alone, so a region or a shard renders the pixels of the whole
// image. threshold 0: off (every pixel takes every sample).
struct AdaptiveSampling {
    float threshold = 0.0f; // 0 (off) or above 0, at most 1; Cycles' default noise threshold is 0.01
    int minSamples = 0;     // samples before the first test; 0: automatic (Even: 16 / threshold^0.3 as Cycles; Mean: 16)
    AdaptiveGoal goal = AdaptiveGoal::Even;
    friend bool operator==(const AdaptiveSampling&, const AdaptiveSampling&) = default;
};

struct SvgfParameters {
    int iterations = 5;            // a-trous passes, 1..10 (the first also filters the history)
    float alpha = 0.2f;            // the current frame's minimum weight in the temporal mean, (0, 1]
    float momentsAlpha = 0.2f;     // the same for the luminance moments, (0, 1]
    float sigmaLuminance = 4.0f;   // edge-stopping: luminance, in standard deviations, > 0
    float sigmaNormal = 128.0f;    // edge-stopping: exponent on the normals' cosine, >= 0
    float sigmaDepth = 1.0f;       // edge-stopping: depth, > 0
    float fireflyRatio = 8.0f;     // a pixel may be this many times brighter than its neighbours, >= 1
    friend bool operator==(const SvgfParameters&, const SvgfParameters&) = default;
};

// The sample block sizes RenderSettings::sampleBlock allows.
inline constexpr std::array<int, 4> kSampleBlockSizes{1, 2, 4, 8};
inline bool isSampleBlock(int size) { return std::find(kSampleBlockSizes.begin(), kSampleBlockSizes.end(), size) != kSampleBlockSizes.end(); }

struct RenderSettings {
    std::string configuration = "accumulate"; // baseline, realistic, full, heavy, accumulate, reference
    int width = 640;
    int height = 360;
    int spp = 64;
    int bounces = 4;
    std::uint32_t seed = 0;
    float exposure = 0.0f;  // EV added to the camera's
    Tonemapper tonemapper = Tonemapper::AcesFitted;
    float clamp = 0.0f;     // radiance clamp for fireflies; 0 = off (unbiased)
    float shutter = 0.0f;   // motion blur: the shutter's open time in frames (0..1), centred on the frame; 0 = off
    // Accumulate and Reference: the pixels of each aligned sampleBlock x sampleBlock block share one
    // sample sequence (1 = every pixel its own; 2, 4 or 8). Neighbouring paths then take the same
    // directions, which a SIMD or GPU group traces faster; each pixel's error is unchanged, but it
    // correlates within a block. As Cycles' scrambling distance.
    int sampleBlock = 1;
    TaaParameters taa;
    SvgfParameters svgf;
    BloomParameters bloom;
    AdaptiveSampling adaptive;
    friend bool operator==(const RenderSettings&, const RenderSettings&) = default;
};

struct Timeline {
    double start = 0.0; // seconds
    double end = 0.0;   // 0 = the animation's own span
    int fpsNumerator = 24;
    int fpsDenominator = 1;
    friend bool operator==(const Timeline&, const Timeline&) = default;
};

struct OutputSettings {
    std::string path;   // e.g. "frames/shot_####.exr"
    std::string aovs = "all";
    std::string passes; // EXR render passes, as --passes; empty: none (docs/CLI.md, "Render passes")
    std::string codec = "h264";
    friend bool operator==(const OutputSettings&, const OutputSettings&) = default;
};

struct ProjectSettings {
    RenderSettings render;
    Environment environment;
    Fog fog;
    NodeId activeCamera{};
    Timeline timeline;
    OutputSettings output;
    LightUnits lightUnits = LightUnits::Blender;
    nlohmann::json unknown; // keys of the project file Glint does not understand, kept on save
    friend bool operator==(const ProjectSettings&, const ProjectSettings&) = default;
};

} // namespace glint
