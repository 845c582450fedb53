#include "renderer/gpu_scene/packed_scene.h"

#include "renderer/gpu_scene/emissive_triangles.h"
#include "renderer/gpu_scene/light_units.h"
#include "renderer/gpu_scene/texture_refs.h"
#include "renderer/gpu_scene/visibility.h"
#include "scene/core/area_light.h"
#include "scene/core/portal.h"

#include <cmath>

namespace glint::renderer {
namespace {

// `emission`: the radiance light sampling assumes (none for an emissive texture, which BSDF
// sampling alone finds on a shape: its light samples would need the shape's texture coordinates). An emissive shape is light-sampled with the power luminance x world area (one side of a quad or disk,
// the outside of a closed shape); the infinite ground plane never is.
void packShape(PackedScene& out, const Shape& shape, const glm::mat4& worldFromLocal, float objectId, int material,
               glm::vec3 emission) {
    const glm::mat4 localFromWorld = glm::inverse(worldFromLocal);
    const glm::mat4 rows = glm::transpose(localFromWorld);
    const glm::mat4 worldRows = glm::transpose(worldFromLocal);
    float power = 0.0f;
    if (shape.kind != ShapeKind::GroundPlane && emission != glm::vec3(0.0f))
        power = emissionLuminance(emission) * shapeArea(shape, worldFromLocal);
    if (!(power > 0.0f) || !std::isfinite(power)) power = 0.0f;
    out.shapeEmitterPower += power;
    out.emissiveShapes = out.emissiveShapes || power > 0.0f;
    out.shapes.push_back({static_cast<float>(shape.kind), static_cast<float>(material), objectId, shape.height});
    out.shapes.push_back(rows[0]);
    out.shapes.push_back(rows[1]);
    out.shapes.push_back(rows[2]);
    out.shapes.push_back({shape.radius, shape.size.x, shape.size.y, shape.size.z});
    out.shapes.push_back({power, out.shapeEmitterPower, 0.0f, std::abs(glm::determinant(glm::mat3(worldFromLocal)))});
    out.shapes.push_back(worldRows[0]);
    out.shapes.push_back(worldRows[1]);
    out.shapes.push_back(worldRows[2]);
    ++out.shapeCount;
}

// An area light is traced as its shape (area_light.h) with a material of its own: black (it reflects
// nothing), emitting P / (pi A) x colour from its front face only (texel 5 w = 1, which shapes.glsl
// and the shape sampling honour), A its world area.
void packAreaLight(PackedScene& out, const Light& light, const glm::mat4& worldFromLight, float objectId) {
    const Shape shape = areaLightShape(light);
    const glm::mat4 worldFromShape = worldFromLight * lightFromAreaShape(light);
    const glm::vec3 radiance = areaLightRadiance(light, shapeArea(shape, worldFromShape));
    Material emitter;
    emitter.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    emitter.metallicFactor = 0.0f;
    emitter.specularFactor = 0.0f;
    emitter.emissiveFactor = radiance;
    std::vector<glm::vec4> texels = packMaterial(emitter);
    texels[5].w = 1.0f;
    const int material = static_cast<int>(out.materials.size() / materialTexels);
    out.materials.insert(out.materials.end(), texels.begin(), texels.end());
    packShape(out, shape, worldFromShape, objectId, material, radiance);
    out.emissiveShapes = true;
}

// Texels: type, radius, node id (the id AOV of a visible lamp), 0; radiometric intensity, cos of the
// sun's angular radius; position, cos outer cone; shine direction, cos inner cone.
void packLight(PackedScene& out, const Light& light, const glm::mat4& worldFromLight, float objectId, LightUnits units) {
    const glm::vec3 position(worldFromLight[3]);
    const glm::vec3 shine = glm::normalize(glm::vec3(worldFromLight * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)));
    const float cosSunRadius = light.angularDiameter > 0.0f ? std::cos(0.5f * light.angularDiameter) : 1.0f;
    const float radius = light.type == LightType::Sun ? 0.0f : std::max(light.radius, 0.0f);
    out.lights.push_back({static_cast<float>(light.type), radius, objectId, 0.0f});
    out.lights.push_back(glm::vec4(radiometricIntensity(light, units), cosSunRadius));
    out.lights.push_back(glm::vec4(position, std::cos(light.outerConeAngle)));
    out.lights.push_back(glm::vec4(shine, std::cos(light.innerConeAngle)));
    ++out.lightCount;
    out.sphereLamps = out.sphereLamps || radius > 0.0f;
}

// Texel 5's z of each portal quad: its partner's shape index + 1 (0 on every other shape).
void linkPortals(PackedScene& out, const Scene& scene, const std::map<NodeId, int>& portalShapes) {
    for (const auto& [id, shape] : portalShapes) {
        const int partner = portalShapes.at(*portalPartner(scene, id));
        out.shapes[std::size_t(shape) * shapeTexels + 5].z = static_cast<float>(partner + 1);
    }
    out.portals = !portalShapes.empty();
}

glm::vec4 scatteringTexel(const Material& m) {
    if (!scatters(m)) return glm::vec4(0.0f);
    return glm::vec4(glm::clamp(m.scatterColor, 0.0f, 1.0f), glm::clamp(m.scatterAnisotropy, -0.99f, 0.99f));
}

} // namespace

bool indexMatched(const Material& m) {
    return m.transmissionFactor >= 1.0f && m.ior <= 1.0f && m.metallicFactor <= 0.0f &&
           m.emissiveFactor * m.emissiveStrength == glm::vec3(0.0f) && m.alphaMode == AlphaMode::Opaque &&
           !m.baseColorTexture.valid() && !m.metallicRoughnessTexture.valid() && !m.transmissionTexture.valid() &&
           !m.thicknessTexture.valid();
}

bool scatters(const Material& m) {
    return std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f && m.attenuationColor != glm::vec3(1.0f) &&
           glm::any(glm::greaterThan(m.scatterColor, glm::vec3(0.0f)));
}

// Texels: base colour; emission, roughness; metallic, specular, transmission, IOR; specular colour,
// thickness (0: thin-walled); attenuation colour, attenuation distance (0: no absorption); alpha mode
// (0 opaque, 1 mask, 2 blend), alpha cutoff, double-sided, 0 (an area light's material: 1, front
// face only; an index-matched boundary: 2); the volume's scattering albedo and Henyey-Greenstein g
// (all 0 where the volume only absorbs: media.glsl); then the texture references (texture_refs.h),
// the emissive one's last w holding the luminance light sampling assumes for an emissive-textured
// mesh triangle (sampledEmission).
std::vector<glm::vec4> packMaterial(const Material& m, const Scene* scene, const TextureSet* textures) {
    const bool absorbs = std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f;
    std::vector<glm::vec4> texels{m.baseColorFactor,
            glm::vec4(m.emissiveFactor * m.emissiveStrength, glm::clamp(m.roughnessFactor, 0.0f, 1.0f)),
            {glm::clamp(m.metallicFactor, 0.0f, 1.0f), std::max(m.specularFactor, 0.0f),
             glm::clamp(m.transmissionFactor, 0.0f, 1.0f), std::max(m.ior, 1.0f)},
            glm::vec4(m.specularColorFactor, std::max(m.thicknessFactor, 0.0f)),
            glm::vec4(m.attenuationColor, absorbs ? m.attenuationDistance : 0.0f),
            {static_cast<float>(m.alphaMode), m.alphaCutoff, m.doubleSided ? 1.0f : 0.0f, indexMatched(m) ? 2.0f : 0.0f},
            scatteringTexel(m)};
    appendMaterialTextureRefs(texels, scene, m, textures);
    if (scene && hasEmissiveTexture(*scene, m))
        texels[materialBaseTexels + textureRefTexels * emissiveRef + 2].w = emissionLuminance(sampledEmission(*scene, m, textures));
    return texels;
}

PackedScene packScene(const Scene& scene, const TextureSet* textures) {
    PackedScene out;
    out.materials = packMaterial(Material{});
    for (const auto& [id, material] : scene.materials) {
        out.materialIndex[id] = static_cast<int>(out.materials.size() / materialTexels);
        const auto texels = packMaterial(material, &scene, textures);
        out.materials.insert(out.materials.end(), texels.begin(), texels.end());
    }
    out.sceneMaterialCount = static_cast<int>(out.materials.size() / materialTexels);
    std::map<NodeId, int> portalShapes;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (!visibleInWorld(scene, node)) continue;
        if (const auto* shape = node.get<Shape>()) {
            const auto it = out.materialIndex.find(shape->material);
            const Material* material = scene.materials.find(shape->material);
            // A portal is no light source: what it shows comes from behind its partner.
            const bool portal = portalPartner(scene, id).has_value();
            if (portal) portalShapes[id] = out.shapeCount;
            packShape(out, *shape, scene.worldFromNode(id), static_cast<float>(id.value),
                      it == out.materialIndex.end() ? 0 : it->second,
                      material && !portal && !hasEmissiveTexture(scene, *material) ? sampledEmission(scene, *material, textures)
                                                                                   : glm::vec3(0.0f));
        } else if (const auto* light = node.get<Light>()) {
            if (light->type == LightType::Area)
                packAreaLight(out, *light, scene.worldFromNode(id), static_cast<float>(id.value));
            else
                packLight(out, *light, scene.worldFromNode(id), static_cast<float>(id.value), scene.settings.lightUnits);
        }
    }
    linkPortals(out, scene, portalShapes);
    return out;
}

} // namespace glint::renderer
