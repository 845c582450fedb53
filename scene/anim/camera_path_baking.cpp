#include "camera_path_sampling.h"

#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

// A bound on the baked track so a hostile path (times 1e30 apart) cannot exhaust memory.
constexpr double kMaxBakedSamples = 1e7;

// Sample times from the first key every 1/fps, the last key always included. Times are stored as
// glTF floats, so a sample that rounds onto the previous one is dropped.
std::vector<double> bakeTimes(const CameraPath& path, double fps) {
    const double start = path.keys.front().time, end = path.keys.back().time;
    const double steps = (end - start) * fps;
    if (steps > kMaxBakedSamples) throw std::length_error("bakeCameraPath: too many samples at this frame rate");
    std::vector<double> times;
    for (std::size_t k = 0; start + double(k) / fps < end; ++k) times.push_back(start + double(k) / fps);
    if (times.empty() || float(times.back()) < float(end)) times.push_back(end);
    else times.back() = end;
    return times;
}

AnimationChannel emptyChannel(NodeId node, AnimationPath path) {
    AnimationChannel channel;
    channel.node = node;
    channel.path = path;
    channel.interpolation = Interpolation::Linear;
    return channel;
}

} // namespace

Animation bakeCameraPath(const CameraPath& path, NodeId cameraNode, double fps) {
    if (path.keys.empty()) throw std::logic_error("bakeCameraPath: the path has no keys");
    if (!(fps > 0.0) || !std::isfinite(fps)) throw std::invalid_argument("bakeCameraPath: fps must be positive");
    AnimationChannel translation = emptyChannel(cameraNode, AnimationPath::Translation);
    AnimationChannel rotation = emptyChannel(cameraNode, AnimationPath::Rotation);
    glm::dquat previous{1.0, 0.0, 0.0, 0.0};
    for (const CameraKey& key : sampleCameraPath(path, bakeTimes(path, fps))) {
        const double t = key.time;
        // Keep neighbouring samples in one hemisphere so every tool's LINEAR slerp agrees.
        const glm::dquat q = glm::dot(previous, key.orientation) < 0.0 ? -key.orientation : key.orientation;
        previous = q;
        translation.times.push_back(float(t));
        rotation.times.push_back(float(t));
        translation.values.insert(translation.values.end(),
                                  {float(key.position.x), float(key.position.y), float(key.position.z)});
        rotation.values.insert(rotation.values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
    }
    Animation animation;
    animation.name = "Camera path";
    animation.channels = {std::move(translation), std::move(rotation)};
    animation.bakedCameraPath = true;
    return animation;
}

} // namespace glint
