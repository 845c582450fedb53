#include "renderer/bvh/aabb.h"

namespace glint::bvh {

Aabb transformed(const Aabb& local, const glm::mat4& worldFromLocal)
{
    Aabb world;
    if (local.empty()) return world;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{(corner & 1) ? local.hi.x : local.lo.x, (corner & 2) ? local.hi.y : local.lo.y,
                          (corner & 4) ? local.hi.z : local.lo.z};
        world.grow(glm::vec3(worldFromLocal * glm::vec4(p, 1.0f)));
    }
    return world;
}

} // namespace glint::bvh
