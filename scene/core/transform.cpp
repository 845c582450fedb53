#include "transform.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

namespace glint {

glm::mat4 toMatrix(const Transform& t) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), t.translation);
    m *= glm::mat4_cast(t.rotation);
    return glm::scale(m, t.scale);
}

Transform fromMatrix(const glm::mat4& m) {
    Transform t;
    glm::vec3 skew;
    glm::vec4 perspective;
    if (!glm::decompose(m, t.scale, t.rotation, t.translation, skew, perspective)) return Transform{};
    t.rotation = glm::normalize(t.rotation);
    return t;
}

bool flipsWinding(const glm::mat4& m) { return glm::determinant(glm::mat3(m)) < 0.0f; }

} // namespace glint
