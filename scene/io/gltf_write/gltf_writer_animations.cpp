// Animations in id order, one sampler per channel; then, for every camera with a path (node id
// order), a LINEAR animation baked at the project fps and marked GLINT_baked_camera_path, so other
// tools play the same motion. Baked animations already in the scene are stale copies: re-baked.
#include "gltf_writer_context.h"
#include "scene/io/json/json_numbers.h"

#include "scene/anim/camera_path_sampling.h"

#include <exception>

namespace glint {

namespace {

const char* pathName(AnimationPath path)
{
    switch (path) {
    case AnimationPath::Translation: return "translation";
    case AnimationPath::Rotation: return "rotation";
    case AnimationPath::Scale: return "scale";
    case AnimationPath::Weights: return "weights";
    }
    return "translation";
}

const char* interpolationName(Interpolation interpolation)
{
    switch (interpolation) {
    case Interpolation::Step: return "STEP";
    case Interpolation::Linear: return "LINEAR";
    case Interpolation::CubicSpline: return "CUBICSPLINE";
    }
    return "LINEAR";
}

int componentsOf(AnimationPath path) { return path == AnimationPath::Rotation ? 4 : 3; }

bool writable(GltfWriteContext& ctx, const AnimationChannel& channel, const std::string& what)
{
    if (channel.path == AnimationPath::Weights) {
        ctx.drop("weights-animation-dropped", what + " animates morph target weights, which Glint does not keep");
        return false;
    }
    if (!ctx.nodes.count(channel.node)) {
        ctx.drop("dangling-node", what + " animates node " + std::to_string(channel.node.value) + ", which does not exist");
        return false;
    }
    const std::size_t perKey = static_cast<std::size_t>(componentsOf(channel.path)) *
                               (channel.interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (channel.times.empty() || channel.values.size() != channel.times.size() * perKey) {
        ctx.drop("malformed-animation", what + " has no keys or a value count that does not match its times");
        return false;
    }
    return true;
}

void writeAnimation(GltfWriteContext& ctx, const Animation& animation, const std::string& what)
{
    nlohmann::json channels = nlohmann::json::array();
    nlohmann::json samplers = nlohmann::json::array();
    for (const AnimationChannel& channel : animation.channels) {
        if (!writable(ctx, channel, what)) continue;
        const int input = ctx.buffers.addFloatAccessor(channel.times, 1, ViewTarget::None, true);
        const int output = ctx.buffers.addFloatAccessor(channel.values, componentsOf(channel.path), ViewTarget::None, false);
        channels.push_back({{"sampler", samplers.size()},
                            {"target", {{"node", ctx.nodes.at(channel.node)}, {"path", pathName(channel.path)}}}});
        samplers.push_back({{"input", input}, {"output", output}, {"interpolation", interpolationName(channel.interpolation)}});
    }
    if (channels.empty()) {
        ctx.drop("empty-animation", what + " has no channel Glint can write: not written");
        return;
    }
    nlohmann::json out{{"channels", std::move(channels)}, {"samplers", std::move(samplers)}};
    if (!animation.name.empty()) out["name"] = animation.name;
    if (animation.bakedCameraPath) out["extensions"]["GLINT_baked_camera_path"] = nlohmann::json::object();
    mergeUnknown(out, animation.unknown);
    ctx.root["animations"].push_back(std::move(out));
}

double projectFps(const Timeline& timeline)
{
    if (timeline.fpsNumerator <= 0 || timeline.fpsDenominator <= 0) return 24.0;
    return static_cast<double>(timeline.fpsNumerator) / static_cast<double>(timeline.fpsDenominator);
}

} // namespace

void writeAnimations(GltfWriteContext& ctx)
{
    for (const auto& [id, animation] : ctx.scene.animations) {
        if (!animation.bakedCameraPath) writeAnimation(ctx, animation, "animation " + std::to_string(id.value));
    }
    const double fps = projectFps(ctx.scene.settings.timeline);
    for (const auto& [id, node] : ctx.scene.nodes()) {
        const auto* camera = node.get<Camera>();
        if (!camera || camera->path.empty()) continue;
        const std::string what = "the baked camera path of node " + std::to_string(id.value);
        try {
            Animation baked = bakeCameraPath(camera->path, id, fps);
            baked.bakedCameraPath = true;
            writeAnimation(ctx, baked, what);
        } catch (const std::exception& e) {
            // The exact path is still saved in GLINT_camera_path; only other tools miss the motion.
            ctx.drop("camera-path-not-baked", what + " was not written: " + e.what());
        }
    }
}

} // namespace glint
