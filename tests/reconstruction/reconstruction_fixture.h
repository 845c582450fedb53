#pragma once
// Shared pieces of the reconstruction stability tests: a small lit scene with an occluder, a
// mirror and a glass ball, a headless context with one FrameRenderer, per-frame converged
// references, and the error measures of docs/CLI.md (relMSE).
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/passes/reconstruction.h"
#include "renderer/scene_builder.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <memory>
#include <vector>

namespace glint::test {

inline constexpr int imageSize = 48;
inline constexpr int referenceSpp = 48; // per-frame converged references (noise well below the errors measured)

struct RoomScene {
    Scene scene;
    NodeId occluder, mirrorBall, glassBall, sun, camera;
};

// A grey ground plane and back wall, a red box in front of the wall (the occluder), a mirror ball,
// a glass ball, a sun and a dim sky; the camera looks at the wall from 4 m.
inline RoomScene makeRoom() {
    RoomScene room;
    Scene& s = room.scene;
    const MaterialId grey = s.materials.add(lambert(glm::vec3(0.6f)));
    const MaterialId red = s.materials.add(lambert({0.7f, 0.15f, 0.1f}));
    const MaterialId chrome = s.materials.add(mirror());
    const MaterialId clear = s.materials.add(glass(1.5f, 0.0f));
    addShape(s, ShapeKind::GroundPlane, grey, glm::vec3(0.0f));
    addShape(s, ShapeKind::Box, grey, {0.0f, 1.5f, -2.0f}, 0.5f, {6.0f, 3.0f, 0.2f});
    room.occluder = addShape(s, ShapeKind::Box, red, {-0.6f, 0.5f, -0.5f}, 0.5f, {0.6f, 1.0f, 0.6f});
    room.mirrorBall = addShape(s, ShapeKind::Sphere, chrome, {0.7f, 0.45f, -0.8f}, 0.45f);
    room.glassBall = addShape(s, ShapeKind::Sphere, clear, {0.1f, 0.3f, 0.6f}, 0.3f);
    room.sun = addSun(s, {-0.4f, -1.0f, -0.5f}, 1500.0f);
    room.camera = addPerspectiveCamera(s, {0.0f, 1.2f, 4.0f}, {0.0f, 0.8f, 0.0f}, 0.9f);
    s.settings.activeCamera = room.camera;
    s.settings.environment.color = glm::vec3(0.15f, 0.18f, 0.25f);
    return room;
}

// The scene's camera moved sideways by `x` metres (a pan keeps the view direction).
inline renderer::CameraSetup cameraAt(const Scene& scene, float x) {
    renderer::CameraSetup camera = renderer::resolveCamera(scene, {}, imageSize, imageSize);
    camera.worldFromCamera = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)) * camera.worldFromCamera;
    return camera;
}

inline renderer::FrameSettings settingsFor(renderer::Configuration configuration, int bounces = 2) {
    renderer::FrameSettings s;
    s.configuration = configuration;
    s.bounces = bounces;
    s.width = imageSize;
    s.height = imageSize;
    s.tonemapper = Tonemapper::None;
    return s;
}

// relMSE of docs/CLI.md over RGB, optionally only where `mask` is true.
inline double relMse(const std::vector<float>& image, const std::vector<float>& reference, const std::vector<bool>& mask = {}) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p * 4 < image.size(); ++p) {
        if (!mask.empty() && !mask[p]) continue;
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image[p * 4 + c];
            const double r = reference[p * 4 + c];
            sum += (x - r) * (x - r) / (r * r + 0.01);
            ++count;
        }
    }
    return count ? sum / static_cast<double>(count) : 0.0;
}

// Writes radiance as a plain PPM (x / (1 + x), gamma 2.2) when GLINT_RECONSTRUCTION_DUMP names a
// folder: for looking at failures, never needed by the assertions.
inline void dump(const std::vector<float>& radiance, const std::string& name) {
    const char* folder = std::getenv("GLINT_RECONSTRUCTION_DUMP");
    if (!folder) return;
    std::FILE* f = std::fopen((std::string(folder) + "/" + name + ".ppm").c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "P6 %d %d 255\n", imageSize, imageSize);
    for (std::size_t i = 0; i < radiance.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) {
            const double v = std::pow(std::max(0.0, double(radiance[i + c])) / (1.0 + std::max(0.0, double(radiance[i + c]))), 1.0 / 2.2);
            std::fputc(static_cast<int>(std::lround(v * 255.0)), f);
        }
    std::fclose(f);
}

// The per-pixel relMSE terms as an image (for dump()).
inline std::vector<float> errorImage(const std::vector<float>& image, const std::vector<float>& reference) {
    std::vector<float> out(image.size(), 0.0f);
    for (std::size_t p = 0; p * 4 < image.size(); ++p) {
        double sum = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = image[p * 4 + c] - reference[p * 4 + c];
            sum += d * d / (reference[p * 4 + c] * reference[p * 4 + c] + 0.01);
        }
        out[p * 4] = out[p * 4 + 1] = out[p * 4 + 2] = static_cast<float>(sum / 3.0);
    }
    return out;
}

// A headless context and two renderers: one under test, one for converged references.
struct Harness {
    gl::HeadlessContext context;
    renderer::FrameRenderer frames;
    renderer::FrameRenderer reference;

    // Converged radiance for `scene` seen by `camera`.
    std::vector<float> converged(const Scene& scene, const renderer::CameraSetup& camera, int spp = referenceSpp) {
        renderer::FrameSettings s = settingsFor(renderer::Configuration::Accumulate);
        s.spp = spp;
        s.seed = 7; // independent of the frames under test
        reference.setSettings(s);
        reference.setScene(scene);
        reference.setCamera(camera);
        reference.renderFrame();
        return reference.readImages().radiance;
    }
    std::vector<float> frame(const renderer::CameraSetup& camera) {
        frames.setCamera(camera);
        frames.renderFrame();
        return frames.readImages().radiance;
    }
};

} // namespace glint::test
