#include "common_options.h"

#include "cli_validators.h"
#include "size_option.h"
#include "scene/core/settings.h"
#include "scene/core/tonemapper_names.h"

#include <stdexcept>

namespace glint::cli {

namespace {

const char* kConfigs = "baseline, realistic, full, heavy, accumulate, reference";

} // namespace

Size parseSize(const std::string& text) {
    try {
        const WidthHeight size = parseWidthHeight(text);
        return {size.width, size.height};
    } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError("--size", e.what());
    }
}

void addCommonRenderOptions(CLI::App& cmd, CommonRenderOptions& o) {
    cmd.add_option_function<std::string>("--size", [&o](const std::string& s) { o.size = parseSize(s); },
                                         "Image size WxH in pixels (default: the project's render size)");
    cmd.add_option("--spp", o.spp, "Samples per pixel (per frame with --config; default: the project's)")
        ->check(CLI::Range(1, 1 << 20));
    cmd.add_option("--seed", o.seed, "Random seed; animation frame k uses seed + k (default: 0)");
    cmd.add_option("--bounces", o.bounces, "Maximum path length in bounces; 0 = emitters and direct light only "
                                          "(default: the project's)")
        ->check(CLI::Range(0, 1024));
    cmd.add_option("--config", o.config, std::string("Configuration, case-insensitive: ") + kConfigs +
                                            " (default: the project's)")
        ->transform(CLI::IsMember({"baseline", "realistic", "full", "heavy", "accumulate", "reference"},
                                  CLI::ignore_case));
    cmd.add_option("--camera", o.camera, "Camera by glTF node name, else camera name (default: the active camera, "
                                         "else the first; a scene with none is seen from a default view that frames "
                                         "it, with a warning)");
    cmd.add_option("--exposure", o.exposure, "Exposure in stops, + brighter, added to the camera's, -64 to 64 "
                                             "(default: 0)")
        ->check(finiteIn(-64.0, 64.0));
    cmd.add_option("--tonemap", o.tonemap,
                   std::string("Tonemapper, as the project file spells it: ") + std::string(tonemapperNames()) +
                       "; case-insensitive (default: the project's)")
        ->transform(CLI::Validator(
            [](std::string& name) {
                const auto tonemapper = parseTonemapper(name);
                if (!tonemapper) return "unknown tonemapper '" + name + "' (" + std::string(tonemapperNames()) + ")";
                name = std::string(tonemapperName(*tonemapper));
                return std::string();
            },
            "TONEMAPPER"));
    cmd.add_option("--env", o.env, "Environment map (.hdr, .exr), anywhere on disk (default: the project's)");
    cmd.add_option("--bloom", o.bloom, "Bloom strength, the share of light spread into glare, 0 (off) to 1 (default: the "
                                       "project's, 0)")
        ->check(finiteIn(0.0, 1.0));
    cmd.add_option("--bloom-radius", o.bloomRadius, "Bloom's widest blur as a fraction of the image height, above 0 to 1 "
                                                    "(default: the project's, 0.05)")
        ->check(finiteIn(1e-6, 1.0));
    cmd.add_option("--shutter", o.shutter, "Motion blur: the shutter's open time in frames, 0 (off) to 1, centred on the "
                                           "frame; Accumulate and Reference (default: the project's, 0)")
        ->check(finiteIn(0.0, 1.0));
    cmd.add_option("--sample-block", o.sampleBlock,
                   "Pixels per side of the aligned blocks that share one sample sequence: 1 (off), 2, 4 or 8. Their "
                   "paths stay together, which SIMD lanes and GPUs trace faster; each pixel's error is the same, but "
                   "it correlates within a block (as Cycles' scrambling distance); Accumulate and Reference "
                   "(default: the project's, 1)")
        ->check(CLI::IsMember(std::vector<int>(kSampleBlockSizes.begin(), kSampleBlockSizes.end())));
    cmd.add_option("--adaptive-threshold", o.adaptiveThreshold,
                   "Adaptive sampling: a pixel stops once its noise is below this, 0 (off) to 1; Cycles' default is "
                   "0.01; Accumulate and Reference (default: the project's, 0)")
        ->check(finiteIn(0.0, 1.0));
    cmd.add_option("--adaptive-min-spp", o.adaptiveMinSpp,
                   "Adaptive sampling: samples every pixel takes before its first test, 0 = automatic "
                   "(even: 16 / threshold^0.3; mean: 16) (default: the project's, 0)")
        ->check(CLI::Range(0, 1 << 20));
    cmd.add_option("--adaptive-goal", o.adaptiveGoal,
                   "Adaptive sampling's goal: even (every pixel's noise below the threshold, as Cycles) or mean (the "
                   "least mean error for the samples taken: an 8x8 tile stops once one more sample would lower its "
                   "relMSE by less than threshold^2) (default: the project's, even)")
        ->check(CLI::IsMember(std::vector<std::string>{adaptiveGoalName(AdaptiveGoal::Even), adaptiveGoalName(AdaptiveGoal::Mean)}));
    cmd.add_flag("--bloom-exr", o.bloomLinear, "Bloom the EXR's radiance too (default: off, EXR stays unbloomed)");
    cmd.add_flag("--require-gpu", o.requireGpu, "Fail instead of falling back to software rendering (default: off)");
    cmd.add_flag("--strict", o.strict, "Treat warnings as failures (default: off)");
}

} // namespace glint::cli
