#pragma once
// The material edits the Materials panel, the outliner and the property panel share: each one
// undo step, failures as a message for people (empty on success), as edit_operations.h does for nodes.
#include "editor/document/document.h"

#include "scene/core/material.h"

#include <QString>

class QMimeData;

#include <cstddef>
#include <vector>

namespace glint::editor {

// The nodes that show a material: shapes that use it and mesh instances whose mesh has a primitive
// with it (the "users" the panel counts).
std::vector<NodeId> materialUsers(const Scene& scene, MaterialId material);
// A name no material of the scene has: `base`, else `base.001`, `base.002`, ... as Blender names copies.
std::string uniqueMaterialName(const Scene& scene, const std::string& base);

// Adds `value` under a unique name; returns its id through `added` (none on failure).
QString newMaterial(Document& document, Material value, MaterialId* added = nullptr);
QString duplicateMaterial(Document& document, MaterialId material, MaterialId* added = nullptr);
QString renameMaterial(Document& document, MaterialId material, const QString& name);
// Removes every material nothing uses (one step); `removed` says how many.
QString deleteUnusedMaterials(Document& document, int* removed = nullptr);
// Points every node of `nodes` at `material`: a shape's material, every primitive of a mesh instance's
// mesh (shared meshes change for all their instances, as in glTF). Nodes without either are
// skipped; none left is an error. One undo step.
QString assignMaterial(Document& document, MaterialId material, const std::vector<NodeId>& nodes);
// One primitive of a multi-material mesh.
QString assignPrimitiveMaterial(Document& document, MeshId mesh, std::size_t primitive, MaterialId material);

// Materials dragged from the Materials panel: their ids under this MIME type. A drop on a node in the
// outliner or the viewport assigns the first one to it.
inline constexpr const char* kMaterialMimeType = "application/x-glint-material-ids";
QMimeData* encodeMaterials(const std::vector<MaterialId>& materials);
std::vector<MaterialId> decodeMaterials(const QMimeData* data);
// Whether a material dropped on `node` can be assigned to it (a shape or a mesh instance).
bool takesMaterial(const Scene& scene, NodeId node);

// The texture slots of a material, each with its name in the UI and whether it holds colour (sRGB
// in glTF) or data (linear).
struct TextureSlot {
    const char* id;    // stable ("baseColor")
    const char* title; // English, translated by the caller's context
    TextureRef Material::*member;
    bool color;
};
std::span<const TextureSlot> textureSlots();
const TextureSlot* findTextureSlot(const QString& id);

// Loads an image file (PNG, JPEG, OpenEXR, Radiance HDR, TIFF; through OpenImageIO) into a slot of
// `material`: a new image, sampler and texture and the material edit, one undo step. PNG and JPEG keep
// their bytes; the others become PNG (glTF's images are PNG or JPEG), colour slots converted from
// linear to sRGB. The image is named after the file, its URI a file name no other image of the
// scene uses, so a save writes it beside the scene. A missing or unreadable file is an error that
// names it, and nothing changes.
QString loadTextureFile(Document& document, MaterialId material, const TextureSlot& slot, const QString& path);

} // namespace glint::editor
