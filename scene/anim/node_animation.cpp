#include "node_animation.h"

#include "camera_path_sampling.h"
#include "channel_sampling.h"

#include <algorithm>
#include <optional>

namespace glint {

namespace {

std::pair<double, double> unite(std::pair<double, double> a, std::pair<double, double> b) {
    return {std::min(a.first, b.first), std::max(a.second, b.second)};
}

void applyChannel(const AnimationChannel& channel, double t, Transform& local) {
    switch (channel.path) {
    case AnimationPath::Translation: local.translation = sampleVec3Channel(channel, t); break;
    case AnimationPath::Rotation: local.rotation = sampleRotationChannel(channel, t); break;
    case AnimationPath::Scale: local.scale = sampleVec3Channel(channel, t); break;
    case AnimationPath::Weights: break; // morph targets are not animated by Glint
    }
}

const CameraPath* cameraPathOf(const Node& node) {
    const Camera* camera = node.get<Camera>();
    return camera && !camera->path.empty() ? &camera->path : nullptr;
}

// A baked track only approximates the camera path it came from; the path itself is exact.
bool appliesTo(const Animation& animation, const AnimationChannel& channel, const Scene& scene) {
    const Node* target = scene.node(channel.node);
    return target && isWellFormed(channel) && !(animation.bakedCameraPath && cameraPathOf(*target));
}

// Camera paths are in world space: the local transform that puts the node on its path under its
// parent's stored world transform.
Transform localOnCameraPath(const Scene& scene, const Node& node, const CameraPath& path, double t) {
    const CameraKey key = sampleCameraPath(path, t);
    Transform world = node.local;
    world.translation = glm::vec3(key.position);
    world.rotation = glm::normalize(glm::quat(key.orientation));
    if (!node.parent) return world;
    return fromMatrix(glm::inverse(scene.worldFromNode(node.parent)) * toMatrix(world));
}

} // namespace

std::pair<double, double> animationTimeSpan(const Animation& animation) {
    std::optional<std::pair<double, double>> span;
    for (const AnimationChannel& channel : animation.channels) {
        if (channel.times.empty()) continue;
        const std::pair<double, double> own{channel.times.front(), channel.times.back()};
        span = span ? unite(*span, own) : own;
    }
    return span.value_or(std::pair<double, double>{0.0, 0.0});
}

std::pair<double, double> sceneAnimationTimeSpan(const Scene& scene) {
    std::optional<std::pair<double, double>> span;
    auto include = [&](std::pair<double, double> own) { span = span ? unite(*span, own) : own; };
    for (const auto& [id, animation] : scene.animations)
        if (std::any_of(animation.channels.begin(), animation.channels.end(),
                        [](const AnimationChannel& c) { return !c.times.empty(); }))
            include(animationTimeSpan(animation));
    for (const auto& [id, node] : scene.nodes())
        if (const CameraPath* path = cameraPathOf(node)) include({path->keys.front().time, path->keys.back().time});
    return span.value_or(std::pair<double, double>{0.0, 0.0});
}

Transform sampleLocalTransform(const Scene& scene, NodeId node, double t) {
    Transform local = scene.at(node).local;
    for (const auto& [id, animation] : scene.animations)
        for (const AnimationChannel& channel : animation.channels)
            if (channel.node == node && appliesTo(animation, channel, scene)) applyChannel(channel, t, local);
    if (const CameraPath* path = cameraPathOf(scene.at(node))) return localOnCameraPath(scene, scene.at(node), *path, t);
    return local;
}

std::map<NodeId, Transform> sampleAnimatedTransforms(const Scene& scene, double t) {
    std::map<NodeId, Transform> result;
    for (const auto& [id, animation] : scene.animations)
        for (const AnimationChannel& channel : animation.channels)
            if (appliesTo(animation, channel, scene)) result.try_emplace(channel.node);
    for (const auto& [id, node] : scene.nodes())
        if (cameraPathOf(node)) result.try_emplace(id);
    for (auto& [id, local] : result) local = sampleLocalTransform(scene, id, t);
    return result;
}

} // namespace glint
