#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace glint {

// A node's local transform as glTF stores it: translation, rotation, scale (TRS).
struct Transform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // w, x, y, z
    glm::vec3 scale{1.0f};

    friend bool operator==(const Transform&, const Transform&) = default;
};

// parentFromLocal: the matrix T * R * S.
glm::mat4 toMatrix(const Transform& t);

// Best-effort TRS decomposition (glTF allows a matrix on a node; shear is lost).
Transform fromMatrix(const glm::mat4& m);

// A transform whose determinant is negative mirrors geometry: triangle winding flips.
bool flipsWinding(const glm::mat4& m);

} // namespace glint
