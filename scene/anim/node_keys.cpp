#include "scene/anim/node_keys.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

constexpr double kSameTime = 1e-6;

int componentsOf(AnimationPath path) { return path == AnimationPath::Rotation ? 4 : 3; }

// A channel's keys as plain values (one per key), whatever its interpolation stores.
struct Keys {
    std::vector<float> times;
    std::vector<std::vector<float>> values;
};

Keys keysOf(const AnimationChannel& c) {
    Keys k;
    const std::size_t n = std::size_t(componentsOf(c.path));
    const std::size_t stride = c.interpolation == Interpolation::CubicSpline ? 3 * n : n;
    const std::size_t offset = c.interpolation == Interpolation::CubicSpline ? n : 0; // (in, value, out)
    for (std::size_t i = 0; i < c.times.size() && (i + 1) * stride <= c.values.size(); ++i) {
        k.times.push_back(c.times[i]);
        k.values.emplace_back(c.values.begin() + std::ptrdiff_t(i * stride + offset),
                              c.values.begin() + std::ptrdiff_t(i * stride + offset + n));
    }
    return k;
}

// Rotations keep to one hemisphere, so each step turns the short way.
void alignRotations(Keys& k) {
    for (std::size_t i = 1; i < k.values.size(); ++i) {
        double dot = 0.0;
        for (int c = 0; c < 4; ++c) dot += double(k.values[i - 1][std::size_t(c)]) * k.values[i][std::size_t(c)];
        if (dot < 0.0)
            for (float& v : k.values[i]) v = -v;
    }
}

// Writes `k` into `c` in c.interpolation; cubic keys get Catmull-Rom tangents (per second, as glTF
// scales them by the key interval), zero at the ends.
void store(AnimationChannel& c, Keys k) {
    if (c.path == AnimationPath::Rotation) alignRotations(k);
    const std::size_t n = std::size_t(componentsOf(c.path));
    c.times = k.times;
    c.values.clear();
    for (std::size_t i = 0; i < k.times.size(); ++i) {
        if (c.interpolation != Interpolation::CubicSpline) {
            c.values.insert(c.values.end(), k.values[i].begin(), k.values[i].end());
            continue;
        }
        std::vector<float> tangent(n, 0.0f);
        if (i > 0 && i + 1 < k.times.size()) {
            const double span = double(k.times[i + 1]) - double(k.times[i - 1]);
            for (std::size_t j = 0; j < n; ++j) tangent[j] = float((double(k.values[i + 1][j]) - k.values[i - 1][j]) / span);
        }
        c.values.insert(c.values.end(), tangent.begin(), tangent.end());
        c.values.insert(c.values.end(), k.values[i].begin(), k.values[i].end());
        c.values.insert(c.values.end(), tangent.begin(), tangent.end());
    }
}

std::vector<float> valueOf(const Transform& local, AnimationPath path) {
    switch (path) {
    case AnimationPath::Translation: return {local.translation.x, local.translation.y, local.translation.z};
    case AnimationPath::Rotation: return {local.rotation.x, local.rotation.y, local.rotation.z, local.rotation.w};
    case AnimationPath::Scale: return {local.scale.x, local.scale.y, local.scale.z};
    case AnimationPath::Weights: break;
    }
    return {};
}

void setKey(Keys& k, double t, std::vector<float> value) {
    const auto at = std::lower_bound(k.times.begin(), k.times.end(), float(t - kSameTime));
    const std::size_t i = std::size_t(at - k.times.begin());
    if (at != k.times.end() && std::abs(double(*at) - t) <= kSameTime) {
        k.values[i] = std::move(value);
        return;
    }
    k.times.insert(at, float(t));
    k.values.insert(k.values.begin() + std::ptrdiff_t(i), std::move(value));
}

bool removeKey(Keys& k, double t) {
    for (std::size_t i = 0; i < k.times.size(); ++i)
        if (std::abs(double(k.times[i]) - t) <= kSameTime) {
            k.times.erase(k.times.begin() + std::ptrdiff_t(i));
            k.values.erase(k.values.begin() + std::ptrdiff_t(i));
            return true;
        }
    return false;
}

bool isNodeTrack(const AnimationChannel& c, NodeId node) {
    return c.node == node && c.path != AnimationPath::Weights;
}

} // namespace

std::optional<AnimationId> nodeKeyAnimation(const Scene& scene, NodeId node) {
    for (const auto& [id, animation] : scene.animations) {
        if (animation.bakedCameraPath) continue;
        for (const AnimationChannel& c : animation.channels)
            if (isNodeTrack(c, node)) return id;
    }
    return std::nullopt;
}

std::vector<double> nodeKeyTimes(const Animation& animation, NodeId node) {
    std::vector<double> times;
    for (const AnimationChannel& c : animation.channels)
        if (isNodeTrack(c, node)) times.insert(times.end(), c.times.begin(), c.times.end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return std::abs(a - b) <= kSameTime; }), times.end());
    return times;
}

Interpolation nodeKeyInterpolation(const Animation& animation, NodeId node) {
    for (const AnimationChannel& c : animation.channels)
        if (isNodeTrack(c, node)) return c.interpolation;
    return Interpolation::Linear;
}

Animation withNodeKey(Animation animation, NodeId node, double t, const Transform& local, Interpolation interpolation) {
    for (const AnimationPath path : {AnimationPath::Translation, AnimationPath::Rotation, AnimationPath::Scale}) {
        auto c = std::find_if(animation.channels.begin(), animation.channels.end(),
                              [&](const AnimationChannel& ch) { return ch.node == node && ch.path == path; });
        if (c == animation.channels.end()) {
            AnimationChannel made;
            made.node = node;
            made.path = path;
            made.interpolation = interpolation;
            animation.channels.push_back(made);
            c = animation.channels.end() - 1;
        }
        Keys keys = keysOf(*c);
        setKey(keys, t, valueOf(local, path));
        store(*c, std::move(keys));
    }
    return animation;
}

Animation withoutNodeKey(Animation animation, NodeId node, double t) {
    for (AnimationChannel& c : animation.channels) {
        if (!isNodeTrack(c, node)) continue;
        Keys keys = keysOf(c);
        if (removeKey(keys, t)) store(c, std::move(keys));
    }
    std::erase_if(animation.channels, [&](const AnimationChannel& c) { return isNodeTrack(c, node) && c.times.empty(); });
    return animation;
}

Animation withNodeKeyMoved(Animation animation, NodeId node, double from, double to) {
    for (AnimationChannel& c : animation.channels) {
        if (!isNodeTrack(c, node)) continue;
        Keys keys = keysOf(c);
        for (std::size_t i = 0; i < keys.times.size(); ++i) {
            if (std::abs(double(keys.times[i]) - from) > kSameTime) continue;
            std::vector<float> value = keys.values[i];
            removeKey(keys, from);
            removeKey(keys, to);
            setKey(keys, to, std::move(value));
            store(c, std::move(keys));
            break;
        }
    }
    return animation;
}

Animation withNodeInterpolation(Animation animation, NodeId node, Interpolation interpolation) {
    for (AnimationChannel& c : animation.channels) {
        if (!isNodeTrack(c, node) || c.interpolation == interpolation) continue;
        Keys keys = keysOf(c);
        c.interpolation = interpolation;
        store(c, std::move(keys));
    }
    return animation;
}

} // namespace glint
