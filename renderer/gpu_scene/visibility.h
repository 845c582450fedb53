#pragma once
// The renderer draws what the scene core calls visible (scene/core/visibility.h).
#include "scene/core/visibility.h"

namespace glint::renderer {
using glint::visibleInWorld;
} // namespace glint::renderer
