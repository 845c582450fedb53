// TRS animations, one channel per target with its sampler folded in. Weights (morph) channels are
// named as dropped; a GLINT_baked_camera_path animation is dropped silently because the save bakes
// it again from the camera path.
#include "gltf_read_accessors.h"
#include "gltf_read_json.h"
#include "gltf_reader.h"

#include <cmath>

namespace glint {

namespace {

std::optional<AnimationPath> pathFrom(const std::string& path)
{
    if (path == "translation") return AnimationPath::Translation;
    if (path == "rotation") return AnimationPath::Rotation;
    if (path == "scale") return AnimationPath::Scale;
    if (path == "weights") return AnimationPath::Weights;
    return std::nullopt;
}

Interpolation interpolationFrom(const GltfReadContext& ctx, const std::string& name, const std::string& where)
{
    if (name.empty() || name == "LINEAR") return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    ctx.fail("wrong-type", where + ".interpolation is \"" + name + "\" (LINEAR, STEP or CUBICSPLINE)");
}

void requireFinite(const GltfReadContext& ctx, const std::vector<float>& values, const std::string& what)
{
    for (float v : values)
        if (!std::isfinite(v)) ctx.fail("non-finite-value", what + " holds a value that is not a finite number");
}

void fillChannel(const GltfReadContext& ctx, const Json& sampler, const std::string& where, AnimationChannel& channel)
{
    const JsonReader json{ctx.file};
    channel.interpolation = interpolationFrom(ctx, json.string(sampler, "interpolation", where), where);
    const AccessorValues times = readAccessorFloats(ctx, json.index(sampler, "input", where), 1, "the times of " + where);
    const int width = channel.path == AnimationPath::Rotation ? 4 : 3;
    const AccessorValues values = readAccessorFloats(ctx, json.index(sampler, "output", where), width, "the values of " + where);
    const std::size_t perKey = channel.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (values.count != times.count * perKey)
        ctx.fail("animation-count-mismatch", where + " has " + std::to_string(times.count) + " times but " + std::to_string(values.count) + " values");
    requireFinite(ctx, times.values, "the times of " + where);
    requireFinite(ctx, values.values, "the values of " + where);
    channel.times = times.values;
    channel.values = values.values;
}

bool isBakedCameraPath(const Json& animation)
{
    return animation.contains("extensions") && animation["extensions"].is_object() && animation["extensions"].contains("GLINT_baked_camera_path");
}

Animation readAnimation(GltfReadContext& ctx, std::size_t index)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["animations"][index];
    const std::string where = "animations[" + std::to_string(index) + "]";
    Animation animation;
    animation.name = json.string(source, "name", where);
    animation.unknown = unknownMembers(source);
    const Json* channels = json.member(source, "channels");
    for (std::size_t c = 0; channels && c < channels->size(); ++c) {
        const Json& channelJson = (*channels)[c];
        const std::string at = where + ".channels[" + std::to_string(c) + "]";
        const Json* target = json.member(channelJson, "target");
        if (!target || !target->is_object()) ctx.fail("wrong-type", at + ".target must be an object");
        const auto path = pathFrom(json.string(*target, "path", at + ".target"));
        const int node = json.index(*target, "node", at + ".target");
        if (!path || *path == AnimationPath::Weights || node < 0 || !ctx.nodeIds.at(static_cast<std::size_t>(node)).valid()) {
            ctx.drop("animation-channel-dropped", at + " animates " + (path == AnimationPath::Weights ? "morph weights" : "something other than a loaded node's TRS"));
            continue;
        }
        AnimationChannel channel;
        channel.node = ctx.nodeIds[static_cast<std::size_t>(node)];
        channel.path = *path;
        const int sampler = json.index(channelJson, "sampler", at);
        fillChannel(ctx, source["samplers"][static_cast<std::size_t>(sampler)], where + ".samplers[" + std::to_string(sampler) + "]", channel);
        animation.channels.push_back(std::move(channel));
    }
    return animation;
}

} // namespace

void readAnimations(GltfReadContext& ctx)
{
    const std::size_t count = ctx.doc.contains("animations") ? ctx.doc["animations"].size() : 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (isBakedCameraPath(ctx.doc["animations"][i])) continue;
        Animation animation = readAnimation(ctx, i);
        if (animation.channels.empty()) ctx.drop("animation-dropped", "animation " + std::to_string(i) + " has no channel Glint can play");
        else ctx.scene.animations.add(std::move(animation));
    }
}

} // namespace glint
