#include "editor/export/export_plan.h"

#include "renderer/configuration.h"
#include "renderer/gpu_scene/camera_setup.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace glint::editor {

namespace {

const char* tonemapperName(Tonemapper t) {
    switch (t) {
    case Tonemapper::AcesFitted: return "aces";
    case Tonemapper::PbrNeutral: return "neutral";
    case Tonemapper::None: break;
    }
    return "none";
}

// FNV-1a over the canonical description, as the command line seals its settings.
std::string hashHex(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

void seal(renderer::ImageMetadata& metadata) {
    std::string canonical;
    for (const auto& [k, v] : metadata)
        if (k != "settingsHash" && k != "renderTimeMs" && k != "version") canonical += k + "=" + v + ";";
    metadata["settingsHash"] = hashHex(canonical);
}

// The request and metadata `glint render --size --spp --config --seed [--camera]` makes.
ExportFrame planBase(const Scene& scene, const ExportSettings& s) {
    const RenderSettings& project = scene.settings.render;
    ExportFrame f;
    auto& r = f.request;
    r.width = s.width;
    r.height = s.height;
    r.spp = s.spp;
    r.seed = s.seed;
    r.bounces = project.bounces;
    r.cameraName = s.camera;
    r.exposure = float(project.exposure + 0.0f);
    r.sceneFolder = s.sceneFile.parent_path();
    r.clamp = project.clamp;
    const auto configuration = renderer::parseConfiguration(s.configuration);
    if (!configuration)
        throw std::runtime_error("unknown configuration '" + s.configuration + "' (use one of " + renderer::configurationNames() + ")");
    r.configuration = *configuration;
    const float cameraExposure = renderer::resolveCamera(scene, r.cameraName, r.width, r.height).exposure;
    f.metadata = {{"scene", s.sceneFile.filename().string()},
                  {"camera", r.cameraName.empty() ? "(active)" : r.cameraName},
                  {"spp", std::to_string(r.spp)},
                  {"seed", std::to_string(r.seed)},
                  {"configuration", std::string(renderer::configurationName(r.configuration))},
                  {"size", std::to_string(r.width) + "x" + std::to_string(r.height)},
                  {"bounces", std::to_string(r.bounces)},
                  {"clamp", formatNumber(r.clamp)},
                  {"env", ""},
                  {"tonemap", tonemapperName(project.tonemapper)},
                  {"exposureEv", formatNumber(double(cameraExposure) + double(r.exposure))}};
    return f;
}

} // namespace

std::string formatNumber(double value) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

double exportFrameTime(const Scene& scene, const ExportSettings& s, int frame) {
    return scene.settings.timeline.start + double(frame) * double(s.fpsDenominator) / double(s.fpsNumerator);
}

std::filesystem::path framePath(const std::filesystem::path& pattern, int frame) {
    const std::string name = pattern.filename().string();
    const auto first = name.find('#');
    if (first == std::string::npos) throw std::invalid_argument("the output name needs a '#' run for the frame number: " + name);
    const auto last = name.find_first_not_of('#', first);
    const std::size_t digits = (last == std::string::npos ? name.size() : last) - first;
    std::string number = std::to_string(frame);
    if (number.size() < digits) number.insert(0, digits - number.size(), '0');
    return pattern.parent_path() / (name.substr(0, first) + number + (last == std::string::npos ? "" : name.substr(last)));
}

std::vector<ExportFrame> planExport(const Scene& scene, const ExportSettings& s) {
    const bool exr = renderer::imageFormatFor(s.out) == renderer::ImageFormat::Exr;
    std::vector<ExportFrame> frames;
    if (!s.animation) {
        ExportFrame f = planBase(scene, s);
        f.out = s.out;
        f.time = s.time;
        if (s.time) f.metadata["time"] = formatNumber(*s.time);
        if (exr) f.metadata["aovs"] = s.aovs;
        seal(f.metadata);
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
        f.metadata["time"] = formatNumber(*f.time);
        if (exr) f.metadata["aovs"] = s.aovs;
        seal(f.metadata);
        frames.push_back(std::move(f));
    }
    return frames;
}

} // namespace glint::editor
