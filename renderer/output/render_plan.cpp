#include "renderer/output/render_plan.h"

#include "renderer/configuration.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/passes/adaptive_sampling.h"
#include "scene/core/tonemapper_names.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace glint::renderer {

namespace {

std::optional<Tonemapper> tonemapperFromName(const std::optional<std::string>& name) {
    if (!name) return std::nullopt;
    return parseTonemapper(*name).value_or(Tonemapper::None);
}

// FNV-1a over the canonical description: the same settings give the same hash on every machine.
std::string hashHex(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

Configuration configurationOf(const Scene& scene, const RenderOverrides& o) {
    const std::string config = o.config.value_or(scene.settings.render.configuration);
    const auto parsed = parseConfiguration(config);
    if (!parsed) throw std::runtime_error("unknown configuration '" + config + "' (use one of " + configurationNames() + ")");
    return *parsed;
}

// The project's TAA and SVGF parameters change the pixels of the configurations that use them.
// Named only where they differ from the defaults, so earlier frames keep their settings hash.
void addReconstruction(ImageMetadata& metadata, const RenderSettings& project, Configuration configuration) {
    const ConfigurationTraits traits = traitsOf(configuration);
    const auto number = [](float v) { return formatNumber(double(v)); };
    if (traits.taa && project.taa != TaaParameters{}) {
        const TaaParameters& t = project.taa;
        metadata["taa"] = "blend=" + number(t.blend) + " clip=" + std::to_string(static_cast<int>(t.clip)) +
                          " clipGamma=" + number(t.clipGamma) +
                          " perceptualBlend=" + (t.perceptualBlend ? "1" : "0");
    }
    if (traits.svgf && project.svgf != SvgfParameters{}) {
        const SvgfParameters& s = project.svgf;
        metadata["svgf"] = "iterations=" + std::to_string(s.iterations) + " alpha=" + number(s.alpha) +
                           " momentsAlpha=" + number(s.momentsAlpha) + " sigmaLuminance=" + number(s.sigmaLuminance) +
                           " sigmaNormal=" + number(s.sigmaNormal) + " sigmaDepth=" + number(s.sigmaDepth) +
                           " fireflyRatio=" + number(s.fireflyRatio);
    }
}

// The shortest text that reads back as `value`, locale-independent: "0.01" for 0.01f, where
// formatNumber(double(0.01f)) would spell out the float's binary value.
template <class T> std::string shortest(T value) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

} // namespace

void planRenderPasses(RenderPlan& plan, const RenderPasses& passes) {
    if (!passes.any()) return;
    plan.request.renderPasses = true;
    plan.metadata["passes"] = passListName(passes);
    if (passes.vector) plan.metadata["vectorSeconds"] = formatNumber(plan.request.motionSeconds);
}

void sealSettings(ImageMetadata& metadata) {
    std::string canonical;
    for (const auto& [k, v] : metadata)
        if (k != "settingsHash" && k != "renderTimeMs" && k != "version") canonical += k + "=" + v + ";";
    metadata["settingsHash"] = hashHex(canonical);
}

std::string formatNumber(double value) { return shortest(value); }

RenderPlan planRender(const Scene& scene, const std::filesystem::path& sceneFile, const RenderOverrides& o) {
    const RenderSettings& project = scene.settings.render;
    RenderPlan plan;
    auto& r = plan.request;
    r.width = o.size ? o.size->width : project.width;
    r.height = o.size ? o.size->height : project.height;
    r.spp = o.spp.value_or(project.spp);
    r.seed = o.seed;
    r.bounces = o.bounces.value_or(project.bounces);
    r.cameraName = o.camera.value_or("");
    r.exposure = float(project.exposure + o.exposure);
    r.tonemapper = tonemapperFromName(o.tonemap);
    r.envFile = o.env.value_or("");
    r.sceneFolder = sceneFile.parent_path();
    r.requireGpu = o.requireGpu;
    r.clamp = project.clamp;
    r.sampleBlock = o.sampleBlock.value_or(project.sampleBlock);
    r.configuration = configurationOf(scene, o);
    r.bloom.strength = o.bloom.value_or(project.bloom.strength);
    r.bloom.radius = o.bloomRadius.value_or(project.bloom.radius);
    r.bloomLinear = o.bloomLinear && r.bloom.strength > 0.0f;
    const Timeline& timeline = scene.settings.timeline;
    const double frameSeconds = timeline.fpsNumerator > 0 && timeline.fpsDenominator > 0
                                    ? double(timeline.fpsDenominator) / double(timeline.fpsNumerator)
                                    : 1.0 / 24.0;
    r.shutterSeconds = double(o.shutter.value_or(project.shutter)) * frameSeconds;
    r.motionSeconds = frameSeconds;
    r.adaptive.threshold = o.adaptiveThreshold.value_or(project.adaptive.threshold);
    r.adaptive.minSamples = o.adaptiveMinSpp.value_or(project.adaptive.minSamples);
    r.adaptive.goal = o.adaptiveGoal ? parseAdaptiveGoal(*o.adaptiveGoal).value_or(AdaptiveGoal::Even) : project.adaptive.goal;

    const Tonemapper tonemapper = r.tonemapper.value_or(project.tonemapper);
    // The camera's own exposure is part of what the PNG shows and what `glint encode` applies to EXRs.
    const float cameraExposure = resolveCamera(scene, r.cameraName, r.width, r.height).exposure;
    plan.metadata = {{"scene", sceneFile.filename().string()},
                     {"camera", r.cameraName.empty() ? "(active)" : r.cameraName},
                     {"spp", std::to_string(r.spp)},
                     {"seed", std::to_string(r.seed)},
                     {"configuration", std::string(configurationName(r.configuration))},
                     {"size", std::to_string(r.width) + "x" + std::to_string(r.height)},
                     {"bounces", std::to_string(r.bounces)},
                     {"clamp", formatNumber(r.clamp)},
                     {"env", r.envFile.string()},
                     {"tonemap", std::string(tonemapperName(tonemapper))},
                     {"exposureEv", formatNumber(double(cameraExposure) + double(r.exposure))}};
    // Only when on (as bloom below): frames rendered before sample blocks existed keep their hash.
    if (r.sampleBlock != 1) plan.metadata["sampleBlock"] = std::to_string(r.sampleBlock);
    if (r.bloom.strength > 0.0f) { // only when on: frames rendered before bloom existed keep their hash
        plan.metadata["bloom"] = formatNumber(r.bloom.strength);
        plan.metadata["bloomRadius"] = formatNumber(r.bloom.radius);
        if (r.bloomLinear) plan.metadata["bloomLinear"] = "1";
    }
    if (r.shutterSeconds > 0.0) plan.metadata["shutterSeconds"] = formatNumber(r.shutterSeconds); // as bloom: only when on
    if (r.adaptive.threshold > 0.0f && traitsOf(r.configuration).accumulate) { // as bloom; the minimum as resolved
        plan.metadata["adaptiveThreshold"] = shortest(r.adaptive.threshold);
        plan.metadata["adaptiveMinSpp"] = std::to_string(adaptiveMinSamples(r.adaptive, r.spp));
        if (r.adaptive.goal != AdaptiveGoal::Even) plan.metadata["adaptiveGoal"] = adaptiveGoalName(r.adaptive.goal); // as bloom
    }
    if (const Fog& fog = scene.settings.fog; fog.enabled()) // as bloom: only when on
        plan.metadata["fog"] = "density=" + shortest(fog.density) + " color=" + shortest(fog.color.x) + "," +
                               shortest(fog.color.y) + "," + shortest(fog.color.z) + " anisotropy=" + shortest(fog.anisotropy) +
                               " heightFalloff=" + shortest(fog.heightFalloff) + " baseHeight=" + shortest(fog.baseHeight);
    addReconstruction(plan.metadata, project, r.configuration);
    return plan;
}

} // namespace glint::renderer
