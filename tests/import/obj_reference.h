#pragma once
// An independent count of what an OBJ file holds, to check the importer against: triangles, and the
// distinct positions its faces use (what joining identical vertices must arrive at when the file has
// no normals or UVs).
#include <glm/glm.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace glint::test {

struct ObjCounts {
    std::size_t triangles = 0;
    std::size_t distinctPositions = 0;
};

inline ObjCounts countObj(const std::filesystem::path& file) {
    std::ifstream in(file);
    using Position = std::tuple<float, float, float>; // -0 and 0 compare equal, as in Assimp
    std::vector<Position> positions;
    std::set<Position> used;
    ObjCounts counts;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "v") {
            std::string x, y, z;
            words >> x >> y >> z;
            positions.emplace_back(std::stof(x), std::stof(y), std::stof(z));
        } else if (tag == "f") {
            std::size_t corners = 0;
            for (std::string corner; words >> corner; ++corners)
                used.insert(positions.at(std::stoul(corner.substr(0, corner.find('/'))) - 1));
            counts.triangles += corners >= 3 ? corners - 2 : 0;
        }
    }
    counts.distinctPositions = used.size();
    return counts;
}

// The bounding box of the file's texture coordinates (min, max).
inline std::pair<glm::vec2, glm::vec2> objUvBounds(const std::filesystem::path& file) {
    std::ifstream in(file);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag, u, v;
        words >> tag >> u >> v;
        if (tag != "vt") continue;
        const glm::vec2 uv(std::stof(u), std::stof(v));
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
    }
    return {lo, hi};
}

} // namespace glint::test
