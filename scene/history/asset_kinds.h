#pragma once
// The asset tables commands can edit, each described once for asset_commands.h: its table, its
// name in logs, and what a change of its content touches.
#include "change_set.h"
#include "scene/core/scene.h"

namespace glint {

template <class T>
struct AssetKind;

template <>
struct AssetKind<Mesh> {
    using IdT = MeshId;
    static constexpr const char* name = "mesh";
    static constexpr Change contentChange = Change::Geometry;
    static AssetTable<IdT, Mesh>& table(Scene& scene) { return scene.meshes; }
    static void touch(ChangeSet& changes, IdT id) { changes.meshes.insert(id); }
};

template <>
struct AssetKind<Material> {
    using IdT = MaterialId;
    static constexpr const char* name = "material";
    static constexpr Change contentChange = Change::Material;
    static AssetTable<IdT, Material>& table(Scene& scene) { return scene.materials; }
    static void touch(ChangeSet& changes, IdT id) { changes.materials.insert(id); }
};

// Textures, images and samplers only reach the picture through materials.
template <>
struct AssetKind<Texture> {
    using IdT = TextureId;
    static constexpr const char* name = "texture";
    static constexpr Change contentChange = Change::Material;
    static AssetTable<IdT, Texture>& table(Scene& scene) { return scene.textures; }
    static void touch(ChangeSet& changes, IdT id) { changes.textures.insert(id); }
};

template <>
struct AssetKind<Image> {
    using IdT = ImageId;
    static constexpr const char* name = "image";
    static constexpr Change contentChange = Change::Material;
    static AssetTable<IdT, Image>& table(Scene& scene) { return scene.images; }
    static void touch(ChangeSet& changes, IdT id) { changes.images.insert(id); }
};

template <>
struct AssetKind<Sampler> {
    using IdT = SamplerId;
    static constexpr const char* name = "sampler";
    static constexpr Change contentChange = Change::Material;
    static AssetTable<IdT, Sampler>& table(Scene& scene) { return scene.samplers; }
    static void touch(ChangeSet& changes, IdT id) { changes.samplers.insert(id); }
};

// Node animations: keyframes the timeline edits (scene/anim/node_keys.h).
template <>
struct AssetKind<Animation> {
    using IdT = AnimationId;
    static constexpr const char* name = "animation";
    static constexpr Change contentChange = Change::Animation;
    static AssetTable<IdT, Animation>& table(Scene& scene) { return scene.animations; }
    static void touch(ChangeSet&, IdT) {}
};

} // namespace glint
