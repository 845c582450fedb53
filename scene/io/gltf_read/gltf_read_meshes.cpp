// Meshes as indexed float triangle lists: non-indexed primitives get sequential indices, strips and
// fans become lists, points and lines are skipped with a warning. Missing normals become flat
// normals (the glTF rule); a normal-mapped material without tangents gets MikkTSpace tangents.
#include "gltf_read_accessors.h"
#include "gltf_read_json.h"
#include "gltf_read_mesh_fixes.h"
#include "gltf_reader.h"

#include "scene/geometry/geometry.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
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

// Adds weight x the target's displacement of one attribute (POSITION, NORMAL, or TANGENT's xyz).
template <class Vec>
void addDisplacement(const GltfReadContext& ctx, const std::map<std::string, int>& target, const char* name, float weight,
                     std::vector<Vec>& values, const std::string& where)
{
    auto it = target.find(name);
    if (it == target.end() || values.empty()) return;
    const std::string what = std::string(name) + " displacement of " + where;
    const AccessorValues delta = readAccessorFloats(ctx, it->second, 3, what);
    if (delta.count != values.size())
        ctx.fail("attribute-count-mismatch", what + " has " + std::to_string(delta.count) + " elements, POSITION has " + std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) values[i][c] += weight * delta.values[3 * i + static_cast<std::size_t>(c)];
}

// The primitive at the mesh's default morph weights: what a glTF viewer shows without animation.
void applyMorphWeights(const GltfReadContext& ctx, const tinygltf::Primitive& source, const std::vector<float>& weights, Primitive& p,
                       const std::string& where)
{
    for (std::size_t t = 0; t < source.targets.size() && t < weights.size(); ++t) {
        if (weights[t] == 0.0f) continue;
        const std::string target = "morph target " + std::to_string(t) + " of " + where;
        addDisplacement(ctx, source.targets[t], "POSITION", weights[t], p.positions.edit(), target);
        if (!p.normals.empty()) addDisplacement(ctx, source.targets[t], "NORMAL", weights[t], p.normals.edit(), target);
        if (!p.tangents.empty()) addDisplacement(ctx, source.targets[t], "TANGENT", weights[t], p.tangents.edit(), target);
    }
}

Primitive readPrimitive(GltfReadContext& ctx, const tinygltf::Primitive& source, const Json& json, const std::vector<float>& morphWeights,
                        const std::string& where)
{
    Primitive p;
    p.positions = attribute<glm::vec3>(ctx, source, "POSITION", 3, SIZE_MAX, where);
    requireFinitePositions(ctx, p.positions, where);
    const std::size_t n = p.positions.size();
    p.normals = attribute<glm::vec3>(ctx, source, "NORMAL", 3, n, where);
    p.tangents = attribute<glm::vec4>(ctx, source, "TANGENT", 4, n, where);
    if (!morphWeights.empty()) {
        applyMorphWeights(ctx, source, morphWeights, p, where);
        requireFinitePositions(ctx, p.positions, where + " at its default morph weights");
    }
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

// The mesh's `weights` as floats, or empty where every weight is zero (the base shape). Weights
// past the primitives' targets have nothing to move and are left out.
std::vector<float> defaultMorphWeights(const GltfReadContext& ctx, const tinygltf::Mesh& source, std::size_t index)
{
    std::vector<float> weights;
    bool any = false;
    for (std::size_t k = 0; k < source.weights.size(); ++k) {
        const double w = source.weights[k];
        if (!(std::abs(w) <= std::numeric_limits<float>::max())) // NaN too; checked before the cast, which would be undefined
            ctx.fail("non-finite-value", "meshes[" + std::to_string(index) + "].weights[" + std::to_string(k) + "] is not a finite float");
        weights.push_back(static_cast<float>(w));
        any = any || w != 0.0;
    }
    return any ? weights : std::vector<float>{};
}

std::string weightList(const std::vector<float>& weights)
{
    std::string list;
    for (float w : weights) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%g", list.empty() ? "" : ", ", static_cast<double>(w));
        list += text;
    }
    return list;
}

Mesh readMesh(GltfReadContext& ctx, std::size_t index)
{
    const tinygltf::Mesh& source = ctx.model.meshes.at(index);
    const Json& json = ctx.doc["meshes"][index];
    Mesh mesh;
    mesh.name = source.name;
    mesh.unknown = unknownMembers(json);
    bool hasTargets = false;
    const std::vector<float> weights = defaultMorphWeights(ctx, source, index);
    for (std::size_t i = 0; i < source.primitives.size(); ++i) {
        const std::string where = "primitive " + std::to_string(i) + " of mesh " + std::to_string(index);
        hasTargets = hasTargets || !source.primitives[i].targets.empty();
        if (const std::string reason = skipReason(source.primitives[i]); !reason.empty()) {
            ctx.drop("primitive-skipped", where + " " + reason);
            continue;
        }
        mesh.primitives.push_back(readPrimitive(ctx, source.primitives[i], json["primitives"][i], weights, where));
    }
    if (hasTargets) {
        const std::string shape = weights.empty() ? "its base shape" : "its shape at the default weights (" + weightList(weights) + ")";
        ctx.drop("morph-targets-dropped", "mesh " + std::to_string(index) + " has morph targets: loaded as " + shape + ", static");
    }
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
