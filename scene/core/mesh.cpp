#include "mesh.h"

namespace glint {

std::size_t Mesh::triangleCount() const {
    std::size_t n = 0;
    for (const auto& p : primitives) n += p.triangleCount();
    return n;
}

} // namespace glint
