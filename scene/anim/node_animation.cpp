#include "node_animation.h"

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
    for (const auto& [id, animation] : scene.animations) {
        if (std::none_of(animation.channels.begin(), animation.channels.end(),
                         [](const AnimationChannel& c) { return !c.times.empty(); }))
            continue;
        const auto own = animationTimeSpan(animation);
        span = span ? unite(*span, own) : own;
    }
    return span.value_or(std::pair<double, double>{0.0, 0.0});
}

// Animations apply in id order, channels in file order: a later channel on the same node and
// path wins, which is what a viewer playing all animations at once shows.
Transform sampleLocalTransform(const Scene& scene, NodeId node, double t) {
    Transform local = scene.at(node).local;
    for (const auto& [id, animation] : scene.animations)
        for (const AnimationChannel& channel : animation.channels)
            if (channel.node == node && isWellFormed(channel)) applyChannel(channel, t, local);
    return local;
}

std::map<NodeId, Transform> sampleAnimatedTransforms(const Scene& scene, double t) {
    std::map<NodeId, Transform> result;
    for (const auto& [id, animation] : scene.animations)
        for (const AnimationChannel& channel : animation.channels) {
            if (!isWellFormed(channel) || !scene.contains(channel.node)) continue;
            auto it = result.try_emplace(channel.node, scene.at(channel.node).local).first;
            applyChannel(channel, t, it->second);
        }
    return result;
}

} // namespace glint
