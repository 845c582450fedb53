// Nodes in id order with their one component: a mesh, an analytic shape (GLINT_shape plus a
// tessellated fallback mesh), a KHR_lights_punctual light (plus GLINT_light), an area light
// (GLINT_area_light plus an emissive fallback mesh) or a camera (plus GLINT_camera and, with a
// path, GLINT_camera_path). Then the default scene.
#include "gltf_writer_context.h"
#include "scene/io/json/json_numbers.h"

#include "scene/core/area_light.h"
#include "scene/geometry/geometry.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <optional>

namespace glint {

namespace {

nlohmann::json vec3Json(const glm::vec3& v) { return jsonFloats({glm::value_ptr(v), 3}); }

void writeTransform(nlohmann::json& node, const Transform& t)
{
    if (t.translation != glm::vec3(0.0f)) node["translation"] = vec3Json(t.translation);
    if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
        node["rotation"] = {jsonFloat(t.rotation.x), jsonFloat(t.rotation.y), jsonFloat(t.rotation.z), jsonFloat(t.rotation.w)};
    if (t.scale != glm::vec3(1.0f)) node["scale"] = vec3Json(t.scale);
}

const char* shapeKindName(ShapeKind kind)
{
    switch (kind) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Quad: return "quad";
    case ShapeKind::Disk: return "disk";
    case ShapeKind::Box: return "box";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::GroundPlane: return "groundPlane";
    }
    return "sphere";
}

const char* lightTypeName(LightType type)
{
    switch (type) {
    case LightType::Sun: return "directional";
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
    case LightType::Area: break; // GLINT_area_light, not KHR_lights_punctual
    }
    return "point";
}

// A file carries portal pairs only: two quads naming each other (hidden or not). A one-sided link
// (its partner deleted, or no longer a quad) renders as an ordinary quad and is not saved.
std::optional<int> portalPartnerIndex(const GltfWriteContext& ctx, const Node& source, const Shape& shape)
{
    if (shape.kind != ShapeKind::Quad || !shape.portal.valid() || shape.portal == source.id) return std::nullopt;
    const Node* partner = ctx.scene.node(shape.portal);
    const Shape* other = partner ? partner->get<Shape>() : nullptr;
    if (!other || other->kind != ShapeKind::Quad || other->portal != source.id) return std::nullopt;
    return ctx.nodes.at(shape.portal);
}

// The fallback mesh other tools show; Glint drops it on load and regenerates it here.
void writeShape(GltfWriteContext& ctx, nlohmann::json& node, const Node& source, const Shape& shape)
{
    nlohmann::json ext{{"kind", shapeKindName(shape.kind)},
                       {"radius", jsonFloat(shape.radius)},
                       {"size", vec3Json(shape.size)},
                       {"height", jsonFloat(shape.height)}};
    if (shape.material.valid()) {
        if (auto it = ctx.materials.find(shape.material); it != ctx.materials.end())
            ext["material"] = it->second;
        else
            ctx.drop("dangling-material", "shape node " + std::to_string(source.id.value) + " refers to a missing material");
    }
    if (const auto partner = portalPartnerIndex(ctx, source, shape)) ext["portal"] = *partner;
    node["extensions"]["GLINT_shape"] = std::move(ext);

    Mesh fallback;
    fallback.name = source.name.empty() ? "shape" : source.name + ".shape";
    fallback.primitives.push_back(tessellateShape(shape));
    // No tangents: tools that need them generate MikkTSpace ones, and a sphere's poles have none.
    fallback.primitives.back().tangents.clear();
    fallback.primitives.back().material = shape.material;
    fallback.unknown = {{"extensions", {{"GLINT_shape_fallback", nlohmann::json::object()}}}};
    node["mesh"] = ctx.root["meshes"].size();
    ctx.root["meshes"].push_back(meshJson(ctx, fallback, "the fallback mesh of node " + std::to_string(source.id.value)));
}

const char* areaShapeName(AreaShape shape)
{
    switch (shape) {
    case AreaShape::Rectangle: return "rectangle";
    case AreaShape::Disk: return "disk";
    case AreaShape::Sphere: return "sphere";
    }
    return "rectangle";
}

// The material other tools show on an area light's fallback mesh: black, emitting the light's
// radiance P / (pi A) x colour (A its world area) through emissiveFactor (the colour, scaled to a
// largest component of 1, as glTF bounds it) x KHR_materials_emissive_strength. Single-sided: the
// rectangle and disk emit from their front face only, the sphere from its outside.
nlohmann::json areaLightMaterialJson(const Node& source, const Light& light, float area)
{
    const glm::vec3 radiance = areaLightRadiance(light, area);
    const float largest = std::max({radiance.x, radiance.y, radiance.z});
    nlohmann::json out{{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}}}};
    out["name"] = (source.name.empty() ? std::string("area light") : source.name) + ".emission";
    if (largest > 0.0f) {
        out["emissiveFactor"] = vec3Json(radiance / largest);
        if (largest != 1.0f) out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", jsonFloat(largest)}};
    }
    out["extensions"]["GLINT_area_light_material"] = nlohmann::json::object();
    return out;
}

// GLINT_area_light carries the light (Glint reads it back exactly: size and radius are both written
// whatever the shape, so switching shapes keeps them); the node's mesh is its emitting surface for
// other tools, in the light's space, marked as a fallback, with a material of its own.
void writeAreaLight(GltfWriteContext& ctx, nlohmann::json& node, const Node& source, const Light& light)
{
    nlohmann::json ext{{"shape", areaShapeName(light.areaShape)},
                       {"power", jsonFloat(light.intensity)},
                       {"color", vec3Json(light.color)},
                       {"size", {jsonFloat(light.size.x), jsonFloat(light.size.y)}},
                       {"radius", jsonFloat(light.radius)}};
    node["extensions"]["GLINT_area_light"] = std::move(ext);

    const glm::mat4 lightFromShape = lightFromAreaShape(light);
    Primitive surface = tessellateShape(areaLightShape(light));
    std::vector<glm::vec3> positions(surface.positions.begin(), surface.positions.end());
    std::vector<glm::vec3> normals(surface.normals.begin(), surface.normals.end());
    for (glm::vec3& p : positions) p = glm::vec3(lightFromShape * glm::vec4(p, 1.0f));
    for (glm::vec3& n : normals) n = glm::vec3(lightFromShape * glm::vec4(n, 0.0f));
    surface.positions = std::move(positions);
    surface.normals = std::move(normals);
    surface.tangents.clear();
    surface.material = MaterialId{};
    const int material = static_cast<int>(ctx.scene.materials.size() + ctx.generatedMaterials.size());
    ctx.generatedMaterials.push_back(areaLightMaterialJson(source, light, areaLightArea(light, ctx.scene.worldFromNode(source.id))));
    Mesh fallback;
    fallback.name = (source.name.empty() ? std::string("area light") : source.name) + ".emitter";
    fallback.primitives.push_back(std::move(surface));
    fallback.unknown = {{"extensions", {{"GLINT_shape_fallback", nlohmann::json::object()}}}};
    nlohmann::json mesh = meshJson(ctx, fallback, "the emitting surface of area light node " + std::to_string(source.id.value));
    mesh["primitives"][0]["material"] = material;
    node["mesh"] = ctx.root["meshes"].size();
    ctx.root["meshes"].push_back(std::move(mesh));
}

void writeLight(GltfWriteContext& ctx, nlohmann::json& node, const Light& light)
{
    nlohmann::json out{{"type", lightTypeName(light.type)},
                       {"color", vec3Json(light.color)},
                       {"intensity", jsonFloat(light.intensity)}};
    if (light.range > 0.0f) out["range"] = jsonFloat(light.range);
    if (light.type == LightType::Spot)
        out["spot"] = {{"innerConeAngle", jsonFloat(light.innerConeAngle)}, {"outerConeAngle", jsonFloat(light.outerConeAngle)}};
    if (light.type == LightType::Sun && light.angularDiameter > 0.0f)
        out["extensions"]["GLINT_light"] = {{"angularDiameter", jsonFloat(light.angularDiameter)}};
    if (light.type != LightType::Sun && light.radius > 0.0f)
        out["extensions"]["GLINT_light"] = {{"radius", jsonFloat(light.radius)}};
    nlohmann::json& lights = ctx.root["extensions"]["KHR_lights_punctual"]["lights"];
    node["extensions"]["KHR_lights_punctual"] = {{"light", lights.size()}};
    lights.push_back(std::move(out));
}

nlohmann::json cameraPathJson(const CameraPath& path)
{
    nlohmann::json keys = nlohmann::json::array();
    for (const CameraKey& k : path.keys) {
        keys.push_back({{"t", k.time},
                        {"p", {k.position.x, k.position.y, k.position.z}},
                        {"q", {k.orientation.x, k.orientation.y, k.orientation.z, k.orientation.w}},
                        {"yfov", jsonFloat(k.yfov)},
                        {"focus", jsonFloat(k.focusDistance)},
                        {"lens", jsonFloat(k.lensRadius)}});
    }
    return {{"rotation", path.rotation == RotationInterpolation::Squad ? "squad" : "slerp"},
            {"constantSpeed", path.constantSpeed},
            {"keys", std::move(keys)}};
}

// glTF requires an orthographic zfar greater than znear, but Glint's orthographic cameras may
// see without limit (zfar 0). Such a camera writes a far plane well past the near one for other
// tools, and GLINT_camera.infiniteFar so that Glint reads the unbounded camera back.
float orthographicFarForGltf(const Camera& camera)
{
    if (camera.zfar > camera.znear) return camera.zfar;
    return std::max(1.0e4f, camera.znear * 2.0f + 1.0f);
}

void writeCamera(GltfWriteContext& ctx, nlohmann::json& node, const Camera& camera)
{
    nlohmann::json out;
    if (camera.projection == Projection::Perspective) {
        out["type"] = "perspective";
        nlohmann::json& p = out["perspective"];
        p["yfov"] = jsonFloat(camera.yfov);
        p["znear"] = jsonFloat(camera.znear);
        if (camera.aspectRatio > 0.0f) p["aspectRatio"] = jsonFloat(camera.aspectRatio);
        if (camera.zfar > 0.0f) p["zfar"] = jsonFloat(camera.zfar);
    } else {
        out["type"] = "orthographic";
        out["orthographic"] = {{"xmag", jsonFloat(camera.xmag)},
                               {"ymag", jsonFloat(camera.ymag)},
                               {"znear", jsonFloat(camera.znear)},
                               {"zfar", jsonFloat(orthographicFarForGltf(camera))}};
    }
    out["extensions"]["GLINT_camera"] = {{"lensRadius", jsonFloat(camera.lensRadius)},
                                         {"focusDistance", jsonFloat(camera.focusDistance)},
                                         {"exposure", jsonFloat(camera.exposure)}};
    if (camera.projection == Projection::Orthographic && camera.zfar <= camera.znear)
        out["extensions"]["GLINT_camera"]["infiniteFar"] = true;
    nlohmann::json& cameras = ctx.root["cameras"];
    node["camera"] = cameras.size();
    cameras.push_back(std::move(out));
    if (!camera.path.empty()) node["extensions"]["GLINT_camera_path"] = cameraPathJson(camera.path);
}

void writeComponent(GltfWriteContext& ctx, nlohmann::json& node, const Node& source)
{
    if (const auto* instance = source.get<MeshInstance>()) {
        if (auto it = ctx.meshes.find(instance->mesh); it != ctx.meshes.end())
            node["mesh"] = it->second;
        else
            ctx.drop("dangling-mesh", "node " + std::to_string(source.id.value) + " refers to a missing mesh");
    } else if (const auto* shape = source.get<Shape>()) {
        writeShape(ctx, node, source, *shape);
    } else if (const auto* light = source.get<Light>()) {
        if (light->type == LightType::Area) writeAreaLight(ctx, node, source, *light);
        else writeLight(ctx, node, *light);
    } else if (const auto* camera = source.get<Camera>()) {
        writeCamera(ctx, node, *camera);
    }
}

nlohmann::json nodeJson(GltfWriteContext& ctx, const Node& source)
{
    nlohmann::json node = nlohmann::json::object();
    if (!source.name.empty()) node["name"] = source.name;
    writeTransform(node, source.local);
    for (NodeId child : source.children) node["children"].push_back(ctx.nodes.at(child));
    node["extensions"]["GLINT_node"] = {{"id", source.id.value}};
    if (!source.visible) node["extensions"]["GLINT_node"]["visible"] = false;
    writeComponent(ctx, node, source);
    mergeUnknown(node, source.unknown);
    return node;
}

} // namespace

void writeNodes(GltfWriteContext& ctx)
{
    for (const auto& [id, node] : ctx.scene.nodes()) ctx.root["nodes"].push_back(nodeJson(ctx, node));

    nlohmann::json scene = nlohmann::json::object();
    if (!ctx.scene.name.empty()) scene["name"] = ctx.scene.name;
    for (NodeId root : ctx.scene.roots()) scene["nodes"].push_back(ctx.nodes.at(root));
    ctx.root["scenes"] = nlohmann::json::array({std::move(scene)});
    ctx.root["scene"] = 0;
}

} // namespace glint
