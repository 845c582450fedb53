#pragma once
// The named render configurations (docs/CLI.md, --config) and what each one turns on. Real-time ones render
// a few samples per frame and reconstruct with history (TAA, SVGF); Accumulate and Reference keep a
// running mean instead and converge to the exact image.
#include <optional>
#include <string>
#include <string_view>

namespace glint::renderer {

enum class Configuration { Baseline, Realistic, Full, Heavy, Accumulate, Reference };

struct ConfigurationTraits {
    int sppPerFrame = 1;     // samples per pixel per frame unless the caller overrides it
    bool gi = true;          // indirect bounces (false: direct light only)
    bool ao = false;         // ambient-occlusion term where paths are cut short
    bool taa = false;
    bool svgf = false;
    bool accumulate = false; // running mean, no history reprojection
};

ConfigurationTraits traitsOf(Configuration configuration);
// Lower-case name as the command line spells it ("full").
std::string_view configurationName(Configuration configuration);
// Case-insensitive; nullopt for an unknown name.
std::optional<Configuration> parseConfiguration(std::string_view name);
// "baseline, realistic, full, heavy, accumulate, reference" for messages and --help.
std::string configurationNames();

} // namespace glint::renderer
