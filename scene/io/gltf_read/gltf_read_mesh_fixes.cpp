#include "gltf_read_mesh_fixes.h"

#include <cmath>

namespace glint {

std::vector<std::uint32_t> triangleListFrom(int mode, const std::vector<std::uint32_t>& indices)
{
    if (mode == 4) return {indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(indices.size() / 3 * 3)};
    std::vector<std::uint32_t> out;
    for (std::size_t i = 2; i < indices.size(); ++i) {
        if (mode == 6) {
            out.insert(out.end(), {indices[0], indices[i - 1], indices[i]});
        } else if (i % 2 == 0) {
            out.insert(out.end(), {indices[i - 2], indices[i - 1], indices[i]});
        } else {
            out.insert(out.end(), {indices[i - 1], indices[i - 2], indices[i]});
        }
    }
    return out;
}

namespace {

bool isUsable(const glm::vec3& n)
{
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) && glm::dot(n, n) > 1e-20f;
}

} // namespace

std::size_t repairZeroNormals(Primitive& p)
{
    std::vector<bool> broken(p.normals.size());
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.normals.size(); ++i) count += (broken[i] = !isUsable(p.normals[i])) ? 1 : 0;
    if (count == 0) return 0;
    std::vector<glm::vec3> summed(p.normals.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const std::uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
        const glm::vec3 face = glm::cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
        for (std::uint32_t v : {a, b, c}) summed[v] += face;
    }
    for (std::size_t i = 0; i < p.normals.size(); ++i)
        if (broken[i]) p.normals[i] = isUsable(summed[i]) ? glm::normalize(summed[i]) : glm::vec3(0.0f, 1.0f, 0.0f);
    return count;
}

} // namespace glint
