#pragma once
// Random commands that fit the scene they are made for (valid targets, no cycles, no removal
// of assets in use, free camera-key times), for the undo property test.
#include "random_source.h"
#include "scene/history/command.h"

namespace glint::test {

// Any one command; never null.
CommandPtr randomCommand(RandomSource& random, const Scene& scene);

// A new local transform for a random node (the node is returned through `node`).
CommandPtr randomTransformEdit(RandomSource& random, const Scene& scene, NodeId node);
// A new value for a random material; none if the scene has no material.
CommandPtr randomMaterialEdit(RandomSource& random, const Scene& scene, MaterialId material);

Transform randomTransform(RandomSource& random);

} // namespace glint::test
