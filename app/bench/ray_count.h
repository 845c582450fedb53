#pragma once
// How many rays the path tracer casts per camera path, counted on the CPU: the GPU integrator keeps
// no counter (the fragment shader path has no atomics in GL 4.1), so the bench replays its path
// structure (shaders/pathtrace/integrator.glsl) with the CPU twin of the BVH traversal over the same
// flattened scene: one closest-hit ray per segment (the camera ray, one per bounce and the last one
// that looks for emission, which the shader leaves out where light sampling reaches every emitter),
// one shadow ray per vertex for the emissive-triangle sample when the light
// point lies on the side the path arrived from, the bounce limit and Russian roulette from bounce 3
// with survival min(max albedo, 0.95). Surfaces are treated as Lambertian in their base colour
// (exact for the bench's all-diffuse scenes); punctual lights and the environment are counted as
// one shadow ray per vertex each. An estimate of what the shader does, not a measurement of it.
#include "scene/core/scene.h"

#include <cstdint>

namespace glint::bench {

struct RayCount {
    std::uint64_t paths = 0;
    std::uint64_t closestRays = 0; // camera rays included
    std::uint64_t shadowRays = 0;
    double raysPerPath() const {
        return paths ? static_cast<double>(closestRays + shadowRays) / static_cast<double>(paths) : 0.0;
    }
};

// Traces `pathsPerPixel` paths through each pixel of a width x height image from the scene's active
// camera (pinhole), `bounces` as in FrameSettings. Deterministic (fixed seed).
RayCount countRays(const Scene& scene, int width, int height, int bounces, int pathsPerPixel);

} // namespace glint::bench
