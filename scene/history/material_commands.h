#pragma once
// Material assignment to one primitive of a mesh. A shape's material is part of its component
// (SetComponent); a mesh's are per primitive, in the mesh asset, and SetAsset<Mesh> would carry (and
// count against the history's memory bound) every vertex array twice for a change of one id.
#include "command.h"

#include <cstddef>

namespace glint {

// Points primitive `primitive` of `mesh` at `material` (none: glTF's default material). Every
// instance of the mesh shows it, as in glTF. Edits of the same primitive within one interaction merge.
class SetPrimitiveMaterial final : public Command {
public:
    SetPrimitiveMaterial(MeshId mesh, std::size_t primitive, MaterialId material)
        : mesh_(mesh), primitive_(primitive), new_(material) {}

    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Assign material"; }
    std::string typeName() const override { return "set_primitive_material"; }
    std::string mergeKey() const override;
    bool mergeWith(const Command& next) override;
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

    MeshId mesh() const { return mesh_; }
    std::size_t primitive() const { return primitive_; }
    MaterialId material() const { return new_; }

private:
    ChangeSet changes() const;

    MeshId mesh_;
    std::size_t primitive_;
    MaterialId new_;
    MaterialId old_{};
};

} // namespace glint
