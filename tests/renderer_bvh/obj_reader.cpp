#include "obj_reader.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace glint::bvh::test {
namespace {

std::uint32_t vertexIndex(const std::string& token, std::size_t vertexCount, const std::string& where)
{
    const long index = std::stol(token.substr(0, token.find('/')));
    const long resolved = index < 0 ? static_cast<long>(vertexCount) + index : index - 1;
    if (index == 0 || resolved < 0 || resolved >= static_cast<long>(vertexCount))
        throw std::runtime_error(where + ": vertex index " + token + " out of range");
    return static_cast<std::uint32_t>(resolved);
}

} // namespace

MeshTriangles readObjTriangles(const std::filesystem::path& file)
{
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open");
    MeshTriangles mesh;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string kind;
        words >> kind;
        const std::string where = file.string() + ":" + std::to_string(number);
        if (kind == "v") {
            glm::vec3 p;
            if (!(words >> p.x >> p.y >> p.z)) throw std::runtime_error(where + ": bad vertex");
            mesh.positions.push_back(p);
        } else if (kind == "f") {
            std::vector<std::uint32_t> face;
            for (std::string token; words >> token;) face.push_back(vertexIndex(token, mesh.positions.size(), where));
            if (face.size() < 3) throw std::runtime_error(where + ": a face needs three vertices");
            for (std::size_t k = 2; k < face.size(); ++k) {
                mesh.triangles.emplace_back(face[0], face[k - 1], face[k]);
                mesh.materials.push_back(0);
                mesh.primitiveOf.push_back(0);
            }
        }
    }
    return mesh;
}

} // namespace glint::bvh::test
