#pragma once
// One command of every registered type, in an order in which each applies to the state the
// previous ones left, starting from sampleScene().
#include "sample_scene.h"
#include "scene/history/command.h"

#include <vector>

namespace glint::test {

std::vector<CommandPtr> oneOfEachCommand(const SampleIds& ids);

} // namespace glint::test
