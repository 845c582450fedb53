// Meshes as indexed float triangle lists: non-indexed primitives get sequential indices, strips and
// fans become lists, points and lines are skipped with a warning. Missing normals become flat
// normals (the glTF rule); a normal-mapped material without tangents gets MikkTSpace tangents.
#include "gltf_read_accessors.h"
#include "gltf_read_json.h"
#include "gltf_read_mesh_fixes.h"
#include "gltf_reader.h"

#include "scene/geometry/geometry.h"

#include <cmath>
#include <numeric>

namespace glint {

namespace {

template <class Vec>
std::vector<Vec> attribute(const GltfReadContext& ctx, const tinygltf::Primitive& source, const char* name, int components,
                           std::size_t vertexCount, const std::string& where)
{
    auto it = source.attributes.find(name);
    if (it == source.attributes.end()) return {};
    const std::string what = std::string(name) + " of " + where;
    const AccessorValues values = readAccessorFloats(ctx, it->second, components, what);
    if (vertexCount != SIZE_MAX && values.count != vertexCount)
        ctx.fail("attribute-count-mismatch", what + " has " + std::to_string(values.count) + " elements, POSITION has " + std::to_string(vertexCount));
    std::vector<Vec> out(values.count, Vec(1.0f));
    for (std::size_t i = 0; i < values.count; ++i)
        for (int c = 0; c < components; ++c) out[i][c] = values.values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
    return out;
}

std::vector<glm::vec4> colors(const GltfReadContext& ctx, const tinygltf::Primitive& source, std::size_t vertexCount, const std::string& where)
{
    auto it = source.attributes.find("COLOR_0");
    if (it == source.attributes.end()) return {};
    const bool rgb = ctx.model.accessors.at(static_cast<std::size_t>(it->second)).type == TINYGLTF_TYPE_VEC3;
    return rgb ? std::vector<glm::vec4>(attribute<glm::vec4>(ctx, source, "COLOR_0", 3, vertexCount, where)) // alpha stays 1
               : attribute<glm::vec4>(ctx, source, "COLOR_0", 4, vertexCount, where);
}

void requireFinitePositions(const GltfReadContext& ctx, const std::vector<glm::vec3>& positions, const std::string& where)
{
    for (std::size_t i = 0; i < positions.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(positions[i][c]))
                ctx.fail("non-finite-position", "POSITION of " + where + ": vertex " + std::to_string(i) + " is not a finite number");
}

std::vector<std::uint32_t> indicesOf(const GltfReadContext& ctx, const tinygltf::Primitive& source, std::size_t vertexCount, const std::string& where)
{
    std::vector<std::uint32_t> indices(vertexCount);
    if (source.indices < 0) {
        std::iota(indices.begin(), indices.end(), 0u);
        return triangleListFrom(source.mode, indices);
    }
    indices = readAccessorIndices(ctx, source.indices, "the indices of " + where);
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertexCount)
            ctx.fail("index-out-of-range", "index " + std::to_string(i) + " of " + where + " is " + std::to_string(indices[i]) + ", but there are " +
                                               std::to_string(vertexCount) + " vertices");
    return triangleListFrom(source.mode, indices);
}

bool isNormalMapped(const GltfReadContext& ctx, MaterialId material)
{
    const Material* m = ctx.scene.materials.find(material);
    return m && m->normalTexture.valid();
}

void completeShading(GltfReadContext& ctx, Primitive& p, const std::string& where)
{
    if (p.normals.empty()) {
        generateFlatNormals(p);
    } else if (const std::size_t repaired = repairZeroNormals(p)) {
        ctx.warn("zero-normal", where + ": " + std::to_string(repaired) + " normals of zero length replaced by face normals");
    }
    if (p.tangents.empty() && isNormalMapped(ctx, p.material) && !p.uv0.empty()) generateTangents(p);
}

Primitive readPrimitive(GltfReadContext& ctx, const tinygltf::Primitive& source, const Json& json, const std::string& where)
{
    Primitive p;
    p.positions = attribute<glm::vec3>(ctx, source, "POSITION", 3, SIZE_MAX, where);
    requireFinitePositions(ctx, p.positions, where);
    const std::size_t n = p.positions.size();
    p.normals = attribute<glm::vec3>(ctx, source, "NORMAL", 3, n, where);
    p.tangents = attribute<glm::vec4>(ctx, source, "TANGENT", 4, n, where);
    p.uv0 = attribute<glm::vec2>(ctx, source, "TEXCOORD_0", 2, n, where);
    p.uv1 = attribute<glm::vec2>(ctx, source, "TEXCOORD_1", 2, n, where);
    p.colors = colors(ctx, source, n, where);
    p.indices = indicesOf(ctx, source, n, where);
    if (source.material >= 0) p.material = ctx.materialIds.at(static_cast<std::size_t>(source.material));
    p.unknown = unknownMembers(json);
    completeShading(ctx, p, where);
    return p;
}

// Why a primitive is skipped, or empty to read it.
std::string skipReason(const tinygltf::Primitive& source)
{
    if (source.mode < 4 || source.mode > 6) return "is made of points or lines (mode " + std::to_string(source.mode) + "), which Glint does not render";
    if (!source.attributes.count("POSITION")) return "has no POSITION";
    return {};
}

Mesh readMesh(GltfReadContext& ctx, std::size_t index)
{
    const tinygltf::Mesh& source = ctx.model.meshes.at(index);
    const Json& json = ctx.doc["meshes"][index];
    Mesh mesh;
    mesh.name = source.name;
    mesh.unknown = unknownMembers(json);
    bool hasTargets = false;
    for (std::size_t i = 0; i < source.primitives.size(); ++i) {
        const std::string where = "primitive " + std::to_string(i) + " of mesh " + std::to_string(index);
        hasTargets = hasTargets || !source.primitives[i].targets.empty();
        if (const std::string reason = skipReason(source.primitives[i]); !reason.empty()) {
            ctx.drop("primitive-skipped", where + " " + reason);
            continue;
        }
        mesh.primitives.push_back(readPrimitive(ctx, source.primitives[i], json["primitives"][i], where));
    }
    if (hasTargets) ctx.drop("morph-targets-dropped", "mesh " + std::to_string(index) + " has morph targets: loaded as its static base shape");
    return mesh;
}

bool isShapeFallback(const Json& mesh)
{
    return mesh.contains("extensions") && mesh["extensions"].is_object() && mesh["extensions"].contains("GLINT_shape_fallback");
}

} // namespace

void readMeshes(GltfReadContext& ctx)
{
    for (std::size_t i = 0; i < ctx.model.meshes.size(); ++i) {
        const bool fallback = isShapeFallback(ctx.doc["meshes"][i]);
        ctx.meshIds.push_back(fallback ? MeshId{} : ctx.scene.meshes.add(readMesh(ctx, i)));
    }
}

} // namespace glint
