// Meshes and primitives: vertex attributes in a fixed order, then indices, all in mesh id order.
#include "gltf_writer_context.h"

#include <glm/gtc/type_ptr.hpp>

namespace glint {

namespace {

template <class Vec>
std::span<const float> flatFloats(const std::vector<Vec>& values)
{
    static_assert(sizeof(Vec) == Vec::length() * sizeof(float), "glm vectors must be tightly packed");
    if (values.empty()) return {};
    return {glm::value_ptr(values.front()), values.size() * Vec::length()};
}

template <class Vec>
void addAttribute(GltfWriteContext& ctx, nlohmann::json& attributes, const char* name, const std::vector<Vec>& values,
                  bool withBounds = false)
{
    if (values.empty()) return;
    attributes[name] = ctx.buffers.addFloatAccessor(flatFloats(values), Vec::length(), ViewTarget::Vertices, withBounds);
}

nlohmann::json primitiveJson(GltfWriteContext& ctx, const Primitive& p)
{
    nlohmann::json attributes = nlohmann::json::object();
    addAttribute(ctx, attributes, "POSITION", p.positions.vector(), true);
    addAttribute(ctx, attributes, "NORMAL", p.normals.vector());
    addAttribute(ctx, attributes, "TANGENT", p.tangents.vector());
    addAttribute(ctx, attributes, "TEXCOORD_0", p.uv0.vector());
    addAttribute(ctx, attributes, "TEXCOORD_1", p.uv1.vector());
    addAttribute(ctx, attributes, "COLOR_0", p.colors.vector());
    nlohmann::json primitive{{"attributes", std::move(attributes)}};
    if (!p.indices.empty()) primitive["indices"] = ctx.buffers.addIndexAccessor(p.indices);
    if (p.material.valid()) {
        if (auto it = ctx.materials.find(p.material); it != ctx.materials.end())
            primitive["material"] = it->second;
        else
            ctx.drop("dangling-material", "a primitive refers to material " + std::to_string(p.material.value) +
                                              ", which does not exist: written without a material");
    }
    mergeUnknown(primitive, p.unknown);
    return primitive;
}

} // namespace

nlohmann::json meshJson(GltfWriteContext& ctx, const Mesh& mesh, const std::string& what)
{
    nlohmann::json primitives = nlohmann::json::array();
    for (const Primitive& p : mesh.primitives) {
        if (p.positions.empty()) {
            ctx.drop("empty-primitive", what + " has a primitive without vertices: not written");
            continue;
        }
        primitives.push_back(primitiveJson(ctx, p));
    }
    nlohmann::json out{{"primitives", std::move(primitives)}};
    if (!mesh.name.empty()) out["name"] = mesh.name;
    mergeUnknown(out, mesh.unknown);
    return out;
}

void writeMeshes(GltfWriteContext& ctx)
{
    for (const auto& [id, mesh] : ctx.scene.meshes)
        ctx.root["meshes"].push_back(meshJson(ctx, mesh, "mesh " + std::to_string(id.value)));
}

} // namespace glint
