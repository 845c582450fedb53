#include "editor/export/export_plan.h"

#include "renderer/output/frame_pattern.h"
#include "renderer/output/render_plan.h"

#include <stdexcept>

namespace glint::editor {

namespace {

// The request and metadata `glint render --size --spp --config --seed [--camera]` makes: the same
// planner as the command line's, so both describe and hash the same settings alike.
ExportFrame planBase(const Scene& scene, const ExportSettings& s) {
    renderer::RenderOverrides overrides;
    overrides.size = renderer::ImageSize{s.width, s.height};
    overrides.spp = s.spp;
    overrides.seed = s.seed;
    overrides.config = s.configuration;
    if (!s.camera.empty()) overrides.camera = s.camera;
    // An image chosen in an untitled scene is stored absolute until the first save copies it: it
    // is read where it is, as `glint render --env` does (the project's own paths stay in its folder).
    if (const std::string& env = scene.settings.environment.file; !env.empty() && std::filesystem::path(env).is_absolute())
        overrides.env = env;
    renderer::RenderPlan plan = renderer::planRender(scene, s.sceneFile, overrides);
    ExportFrame f;
    f.request = std::move(plan.request);
    f.metadata = std::move(plan.metadata);
    return f;
}

// The EXR's AOVs and render passes, as `glint render --aovs --passes` records them. Throws
// std::invalid_argument for an unknown pass name, and for passes with a real-time configuration.
void addExrLayers(ExportFrame& f, const ExportSettings& s) {
    f.metadata["aovs"] = s.aovs;
    renderer::RenderPlan plan{std::move(f.request), std::move(f.metadata)};
    renderer::planRenderPasses(plan, renderer::parsePassList(s.passes));
    if (plan.request.renderPasses && !traitsOf(plan.request.configuration).accumulate)
        throw std::invalid_argument("render passes need the accumulate or reference configuration, not '" + s.configuration + "'");
    f.request = std::move(plan.request);
    f.metadata = std::move(plan.metadata);
}

} // namespace

double exportFrameTime(const Scene& scene, const ExportSettings& s, int frame) {
    return scene.settings.timeline.start + double(frame) * double(s.fpsDenominator) / double(s.fpsNumerator);
}

std::filesystem::path framePath(const std::filesystem::path& pattern, int frame) {
    return renderer::parseFramePattern(pattern).frame(frame);
}

std::vector<ExportFrame> planExport(const Scene& scene, const ExportSettings& s) {
    const bool exr = renderer::imageFormatFor(s.out) == renderer::ImageFormat::Exr;
    std::vector<ExportFrame> frames;
    if (!s.animation) {
        ExportFrame f = planBase(scene, s);
        f.out = s.out;
        f.time = s.time;
        if (s.time) f.metadata["time"] = formatNumber(*s.time);
        if (exr) addExrLayers(f, s);
        renderer::sealSettings(f.metadata);
        frames.push_back(std::move(f));
        return frames;
    }
    if (s.lastFrame < s.firstFrame || s.firstFrame < 0) throw std::invalid_argument("bad frame range");
    if (s.fpsNumerator <= 0 || s.fpsDenominator <= 0) throw std::invalid_argument("bad fps");
    for (int k = s.firstFrame; k <= s.lastFrame; ++k) {
        ExportFrame f = planBase(scene, s);
        f.frame = k;
        f.time = exportFrameTime(scene, s, k);
        f.out = framePath(s.out, k);
        // Each frame its own noise, the same in every run and shard (as the command line does).
        f.request.seed = s.seed + static_cast<std::uint32_t>(k);
        f.metadata["seed"] = std::to_string(f.request.seed);
        f.metadata["frame"] = std::to_string(k);
        f.metadata["fps"] = std::to_string(s.fpsNumerator) + "/" + std::to_string(s.fpsDenominator);
        f.request.motionSeconds = double(s.fpsDenominator) / double(s.fpsNumerator);
        f.metadata["time"] = formatNumber(*f.time);
        if (exr) addExrLayers(f, s);
        renderer::sealSettings(f.metadata);
        frames.push_back(std::move(f));
    }
    return frames;
}

} // namespace glint::editor
