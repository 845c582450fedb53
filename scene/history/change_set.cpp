#include "change_set.h"

namespace glint {

bool ChangeSet::empty() const {
    return flags == 0 && nodes.empty() && meshes.empty() && materials.empty() && textures.empty() &&
           images.empty() && samplers.empty();
}

void ChangeSet::merge(const ChangeSet& other) {
    flags |= other.flags;
    nodes.insert(other.nodes.begin(), other.nodes.end());
    meshes.insert(other.meshes.begin(), other.meshes.end());
    materials.insert(other.materials.begin(), other.materials.end());
    textures.insert(other.textures.begin(), other.textures.end());
    images.insert(other.images.begin(), other.images.end());
    samplers.insert(other.samplers.begin(), other.samplers.end());
}

ChangeSet nodeChange(Change change, NodeId node) {
    ChangeSet changes;
    changes.add(change);
    changes.nodes.insert(node);
    return changes;
}

bool affectsImage(const ChangeSet& changes) {
    constexpr std::uint32_t imageNeutral = static_cast<std::uint32_t>(Change::Name) |
                                           static_cast<std::uint32_t>(Change::Display) |
                                           static_cast<std::uint32_t>(Change::Project) |
                                           static_cast<std::uint32_t>(Change::Assets);
    return (changes.flags & ~imageNeutral) != 0;
}

} // namespace glint
