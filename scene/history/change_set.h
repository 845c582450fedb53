#pragma once
// What a command changed, so that listeners do only the work that change needs: the renderer
// re-uploads the named parts and resets accumulation only when affectsImage() says the picture
// is different (Mitsuba's parameters_changed(keys), in plain data).
#include "scene/core/ids.h"

#include <cstdint>
#include <set>

namespace glint {

enum class Change : std::uint32_t {
    Transform = 1u << 0,   // a node's local transform (its subtree moves with it)
    Geometry = 1u << 1,    // mesh content, a mesh instance or an analytic shape
    Material = 1u << 2,    // material content, or a texture/image/sampler a material reads
    Light = 1u << 3,
    Camera = 1u << 4,      // camera component, its path, or which camera is active
    Structure = 1u << 5,   // nodes added, removed or moved in the hierarchy
    Settings = 1u << 6,    // render settings that change the image (spp, bounces, seed, units, ...)
    Display = 1u << 7,     // exposure and tonemapper: applied after accumulation, so no reset
    Environment = 1u << 8, // the environment or the fog: the renderer uploads both with the scene
    Animation = 1u << 9,   // camera-path keys and modes
    Name = 1u << 10,
    Visibility = 1u << 11,
    Assets = 1u << 12,     // assets added to or removed from a table (removal only when unused)
    Project = 1u << 13,    // timeline, output and other project data the image does not depend on
};

struct ChangeSet {
    std::uint32_t flags = 0;
    std::set<NodeId> nodes;
    std::set<MeshId> meshes;
    std::set<MaterialId> materials;
    std::set<TextureId> textures;
    std::set<ImageId> images;
    std::set<SamplerId> samplers;

    bool has(Change change) const { return (flags & static_cast<std::uint32_t>(change)) != 0; }
    ChangeSet& add(Change change) {
        flags |= static_cast<std::uint32_t>(change);
        return *this;
    }
    bool empty() const;
    void merge(const ChangeSet& other);
    friend bool operator==(const ChangeSet&, const ChangeSet&) = default;
};

// A change set with one flag and one node, the most common shape.
ChangeSet nodeChange(Change change, NodeId node);

// Whether the rendered picture can differ: false for renames, display settings (exposure,
// tonemapper), project data (timeline, output) and adding or removing unused assets.
bool affectsImage(const ChangeSet& changes);

} // namespace glint
