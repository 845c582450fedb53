#include "material_commands.h"

#include "value_json.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace glint {
namespace {

Primitive& primitiveOf(Scene& scene, MeshId mesh, std::size_t primitive) {
    Mesh& m = scene.meshes.at(mesh);
    if (primitive >= m.primitives.size())
        throw std::out_of_range("mesh " + std::to_string(mesh.value) + " has no primitive " + std::to_string(primitive));
    return m.primitives[primitive];
}

} // namespace

ChangeSet SetPrimitiveMaterial::apply(Scene& scene) {
    if (new_ && !scene.materials.contains(new_))
        throw std::invalid_argument("no material " + std::to_string(new_.value));
    Primitive& p = primitiveOf(scene, mesh_, primitive_);
    old_ = p.material;
    p.material = new_;
    return changes();
}

ChangeSet SetPrimitiveMaterial::revert(Scene& scene) {
    primitiveOf(scene, mesh_, primitive_).material = old_;
    return changes();
}

// Which material a triangle uses is part of the packed geometry: a geometry change of the mesh.
ChangeSet SetPrimitiveMaterial::changes() const {
    ChangeSet c;
    c.add(Change::Geometry);
    c.meshes.insert(mesh_);
    if (old_) c.materials.insert(old_);
    if (new_) c.materials.insert(new_);
    return c;
}

std::string SetPrimitiveMaterial::mergeKey() const {
    return typeName() + ":" + std::to_string(mesh_.value) + ":" + std::to_string(primitive_);
}

bool SetPrimitiveMaterial::mergeWith(const Command& next) {
    const auto* same = dynamic_cast<const SetPrimitiveMaterial*>(&next);
    if (!same || same->mesh_ != mesh_ || same->primitive_ != primitive_) return false;
    new_ = same->new_;
    return true;
}

nlohmann::json SetPrimitiveMaterial::toJson() const {
    return {{"mesh", mesh_}, {"primitive", primitive_}, {"material", new_}};
}

CommandPtr SetPrimitiveMaterial::fromJson(const nlohmann::json& j) {
    return std::make_unique<SetPrimitiveMaterial>(j.at("mesh").get<MeshId>(), j.at("primitive").get<std::size_t>(),
                                                  j.at("material").get<MaterialId>());
}

} // namespace glint
