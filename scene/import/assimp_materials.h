#pragma once
// Assimp materials -> glTF metallic-roughness (scene/import/README.md explains the choices).
// Phong/Blinn/Lambert (OBJ, FBX, DAE, 3DS, PLY, STL):
//   baseColor = diffuse colour (x diffuse texture), metallic = 0,
//   roughness = sqrt(2 / (shininess + 2)) (the Blinn-Phong exponent <-> Beckmann/GGX width relation;
//   no shininess: 1), specularFactor = max(specular colour) x shininess strength (clamped to 1, so a
//   material without specular is pure Lambert), specularColor = specular colour / its maximum,
//   transmission = 1 - opacity (thin-walled: a "dissolved" Phong surface is a see-through sheet, not
//   an alpha cut-out), emissive colour (above 1 moved into emissiveStrength).
// PBR materials (AI_MATKEY_METALLIC_FACTOR or AI_MATKEY_ROUGHNESS_FACTOR present) are taken as they are.
#include "assimp_textures.h"

#include "scene/core/material.h"

struct aiMaterial;

namespace glint {

Material convertMaterial(const aiMaterial& material, TextureImporter& textures, Warnings& warnings, const std::string& file);

// The Phong exponent -> roughness relation above, in [0, 1].
float roughnessFromShininess(float shininess);

} // namespace glint
