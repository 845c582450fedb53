#include "render_setup.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace glint::cli {

namespace {

std::optional<Tonemapper> tonemapperFromName(const std::optional<std::string>& name) {
    if (!name) return std::nullopt;
    if (*name == "aces") return Tonemapper::AcesFitted;
    if (*name == "neutral") return Tonemapper::PbrNeutral;
    return Tonemapper::None;
}

// FNV-1a over the canonical description: the same settings give the same hash on every machine.
std::string hashHex(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

renderer::Configuration configurationOf(const Scene& scene, const CommonRenderOptions& o) {
    const std::string config = o.config.value_or(scene.settings.render.configuration);
    const auto parsed = renderer::parseConfiguration(config);
    if (!parsed)
        throw std::runtime_error("unknown configuration '" + config + "' (use one of " + renderer::configurationNames() + ")");
    return *parsed;
}

} // namespace

std::string formatNumber(double value) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

RenderPlan planRender(const Scene& scene, const std::string& sceneFile, const CommonRenderOptions& o) {
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
    r.sceneFolder = std::filesystem::path(sceneFile).parent_path();
    r.requireGpu = o.requireGpu;
    r.clamp = project.clamp;

    r.configuration = configurationOf(scene, o);
    const std::string config(renderer::configurationName(r.configuration));
    plan.metadata = {{"scene", std::filesystem::path(sceneFile).filename().string()},
                     {"camera", r.cameraName.empty() ? "(active)" : r.cameraName},
                     {"spp", std::to_string(r.spp)},
                     {"seed", std::to_string(r.seed)},
                     {"configuration", config}};
    std::string canonical;
    for (const auto& [k, v] : plan.metadata) canonical += k + "=" + v + ";";
    canonical += "size=" + std::to_string(r.width) + "x" + std::to_string(r.height) + ";bounces=" +
                 std::to_string(r.bounces) + ";env=" + r.envFile.string();
    plan.metadata["settingsHash"] = hashHex(canonical);
    return plan;
}

} // namespace glint::cli
