#pragma once
// A small scene with one of everything commands edit: nested nodes, shapes, a mesh, lights,
// two cameras (one with a path), materials, a texture with its image and sampler.
#include "scene/core/scene.h"

namespace glint::test {

struct SampleIds {
    NodeId world, floor, ball, triangle, sun, lamp, camera, topCamera;
    MaterialId red, glass, textured;
    MeshId triangleMesh;
    TextureId checker;
    ImageId checkerImage;
    SamplerId clamped;
};

Scene sampleScene(SampleIds* ids = nullptr);

// A 1x1 RGBA PNG (generated for these tests).
std::vector<std::uint8_t> tinyPng();

} // namespace glint::test
