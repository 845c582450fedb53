#pragma once
// Assimp cameras and lights as Glint components. Assimp attaches each to the node of the same
// name and gives it a frame of its own inside that node (position, look-at/direction, up); glTF's
// camera looks along -Z with +Y up and lights shine along -Z, so that frame becomes a transform.
#include "scene/core/components.h"
#include "scene/core/diagnostics.h"

#include <glm/glm.hpp>

#include <optional>

struct aiCamera;
struct aiLight;

namespace glint {

struct ImportedComponent {
    Component component;
    glm::mat4 nodeFromComponent{1.0f}; // the component's frame inside its Assimp node
};

ImportedComponent convertCamera(const aiCamera& camera);
// Area and ambient lights have no glTF counterpart: nullopt, and the caller reports them.
std::optional<ImportedComponent> convertLight(const aiLight& light);

} // namespace glint
