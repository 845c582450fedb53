#pragma once
// Scenes built in code for the writer's tests: one that uses every feature Glint writes, and a
// large one for timing and the kill test.
#include "scene/core/scene.h"

#include <cstdint>
#include <vector>

namespace glint::test {

// Two tiny PNGs generated for these tests (2x2 checker, 1x1 blue); the validator decodes them.
std::vector<std::uint8_t> checkerPng();
std::vector<std::uint8_t> bluePng();

// Shapes, lights with GLINT_light, cameras with GLINT_camera and a path, textures with transforms,
// every KHR material extension, node animations in all interpolations, unknown extensions and
// extras, an unsupported item, project settings.
Scene featureScene();

// One mesh of `gridSize` x `gridSize` quads plus the feature scene; `variant` changes positions and
// settings so two variants give different files.
Scene largeScene(int gridSize, int variant);

} // namespace glint::test
