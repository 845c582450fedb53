#include "value_json.h"

#include <cmath>
#include <limits>
#include <string>
#include <variant>

namespace glint {
namespace {

nlohmann::json distanceJson(float distance) {
    if (std::isinf(distance) && distance > 0) return "infinity";
    return distance;
}

float distanceFromJson(const nlohmann::json& j) {
    if (j.is_string() && j.get<std::string>() == "infinity") return std::numeric_limits<float>::infinity();
    return j.get<float>();
}

} // namespace

void to_json(nlohmann::json& j, const Material& m) {
    j = {{"name", m.name},
         {"baseColorFactor", m.baseColorFactor},
         {"baseColorTexture", m.baseColorTexture},
         {"metallicFactor", m.metallicFactor},
         {"roughnessFactor", m.roughnessFactor},
         {"metallicRoughnessTexture", m.metallicRoughnessTexture},
         {"normalTexture", m.normalTexture},
         {"occlusionTexture", m.occlusionTexture},
         {"emissiveFactor", m.emissiveFactor},
         {"emissiveTexture", m.emissiveTexture},
         {"emissiveStrength", m.emissiveStrength},
         {"specularFactor", m.specularFactor},
         {"specularTexture", m.specularTexture},
         {"specularColorFactor", m.specularColorFactor},
         {"specularColorTexture", m.specularColorTexture},
         {"transmissionFactor", m.transmissionFactor},
         {"transmissionTexture", m.transmissionTexture},
         {"ior", m.ior},
         {"thicknessFactor", m.thicknessFactor},
         {"thicknessTexture", m.thicknessTexture},
         {"attenuationDistance", distanceJson(m.attenuationDistance)},
         {"attenuationColor", m.attenuationColor},
         {"scatterColor", m.scatterColor},
         {"scatterAnisotropy", m.scatterAnisotropy},
         {"alphaMode", m.alphaMode},
         {"alphaCutoff", m.alphaCutoff},
         {"doubleSided", m.doubleSided},
         {"unknown", m.unknown}};
}

void from_json(const nlohmann::json& j, Material& m) {
    j.at("name").get_to(m.name);
    j.at("baseColorFactor").get_to(m.baseColorFactor);
    j.at("baseColorTexture").get_to(m.baseColorTexture);
    j.at("metallicFactor").get_to(m.metallicFactor);
    j.at("roughnessFactor").get_to(m.roughnessFactor);
    j.at("metallicRoughnessTexture").get_to(m.metallicRoughnessTexture);
    j.at("normalTexture").get_to(m.normalTexture);
    j.at("occlusionTexture").get_to(m.occlusionTexture);
    j.at("emissiveFactor").get_to(m.emissiveFactor);
    j.at("emissiveTexture").get_to(m.emissiveTexture);
    j.at("emissiveStrength").get_to(m.emissiveStrength);
    j.at("specularFactor").get_to(m.specularFactor);
    j.at("specularTexture").get_to(m.specularTexture);
    j.at("specularColorFactor").get_to(m.specularColorFactor);
    j.at("specularColorTexture").get_to(m.specularColorTexture);
    j.at("transmissionFactor").get_to(m.transmissionFactor);
    j.at("transmissionTexture").get_to(m.transmissionTexture);
    j.at("ior").get_to(m.ior);
    j.at("thicknessFactor").get_to(m.thicknessFactor);
    j.at("thicknessTexture").get_to(m.thicknessTexture);
    m.attenuationDistance = distanceFromJson(j.at("attenuationDistance"));
    j.at("attenuationColor").get_to(m.attenuationColor);
    // Optional: command logs written before GLINT_materials_volume_scatter still replay.
    const Material defaults;
    readJsonFieldOr(j, "scatterColor", m.scatterColor, defaults.scatterColor);
    readJsonFieldOr(j, "scatterAnisotropy", m.scatterAnisotropy, defaults.scatterAnisotropy);
    j.at("alphaMode").get_to(m.alphaMode);
    j.at("alphaCutoff").get_to(m.alphaCutoff);
    j.at("doubleSided").get_to(m.doubleSided);
    m.unknown = j.at("unknown");
}

void to_json(nlohmann::json& j, const Component& component) {
    struct Writer {
        nlohmann::json operator()(std::monostate) const { return {{"kind", "none"}}; }
        nlohmann::json operator()(const MeshInstance& v) const { return {{"kind", "mesh"}, {"value", v}}; }
        nlohmann::json operator()(const Shape& v) const { return {{"kind", "shape"}, {"value", v}}; }
        nlohmann::json operator()(const Light& v) const { return {{"kind", "light"}, {"value", v}}; }
        nlohmann::json operator()(const Camera& v) const { return {{"kind", "camera"}, {"value", v}}; }
    };
    j = std::visit(Writer{}, component);
}

void from_json(const nlohmann::json& j, Component& component) {
    const std::string kind = j.at("kind").get<std::string>();
    if (kind == "none") component = std::monostate{};
    else if (kind == "mesh") component = j.at("value").get<MeshInstance>();
    else if (kind == "shape") component = j.at("value").get<Shape>();
    else if (kind == "light") component = j.at("value").get<Light>();
    else if (kind == "camera") component = j.at("value").get<Camera>();
    else throw std::invalid_argument("unknown component kind \"" + kind + "\"");
}

void to_json(nlohmann::json& j, const Node& node) {
    j = {{"id", node.id},         {"name", node.name},           {"local", node.local},
         {"visible", node.visible}, {"component", node.component}, {"unknown", node.unknown}};
}

void from_json(const nlohmann::json& j, Node& node) {
    j.at("id").get_to(node.id);
    j.at("name").get_to(node.name);
    j.at("local").get_to(node.local);
    j.at("visible").get_to(node.visible);
    j.at("component").get_to(node.component);
    node.unknown = j.at("unknown");
}

} // namespace glint
