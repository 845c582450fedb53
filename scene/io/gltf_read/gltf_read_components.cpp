// The components a glTF node can carry: cameras (plus GLINT_camera and GLINT_camera_path),
// KHR_lights_punctual lights (plus GLINT_light), GLINT_area_light area lights and GLINT_shape
// analytic shapes.
#include "gltf_read_json.h"
#include "gltf_read_nodes.h"

#include <glm/gtc/constants.hpp>

namespace glint {

namespace {

CameraPath readCameraPath(const GltfReadContext& ctx, const Json& ext, const std::string& where)
{
    const JsonReader json{ctx.file};
    CameraPath path;
    const std::string rotation = json.string(ext, "rotation", where);
    path.rotation = rotation == "slerp" ? RotationInterpolation::Slerp : RotationInterpolation::Squad;
    path.constantSpeed = json.boolean(ext, "constantSpeed", false, where);
    const Json* keys = json.member(ext, "keys");
    if (!keys) return path;
    if (!keys->is_array()) json.wrongType(where, "keys", "an array");
    for (std::size_t i = 0; i < keys->size(); ++i) {
        const Json& k = (*keys)[i];
        const std::string at = where + ".keys[" + std::to_string(i) + "]";
        if (!k.is_object()) ctx.fail("wrong-type", at + " must be an object");
        CameraKey key;
        key.time = json.number64(k, "t", 0.0, at);
        // Checked as floats (type, count, range), then kept as the doubles they were saved as.
        json.vec3(k, "p", glm::vec3(0.0f), at);
        json.vec4(k, "q", glm::vec4(0.0f), at);
        if (k.contains("p")) key.position = {k["p"][0].get<double>(), k["p"][1].get<double>(), k["p"][2].get<double>()};
        if (k.contains("q")) key.orientation = glm::dquat(k["q"][3].get<double>(), k["q"][0].get<double>(), k["q"][1].get<double>(), k["q"][2].get<double>());
        key.yfov = json.number(k, "yfov", key.yfov, at);
        key.focusDistance = json.number(k, "focus", key.focusDistance, at);
        key.lensRadius = json.number(k, "lens", key.lensRadius, at);
        if (!path.keys.empty() && key.time <= path.keys.back().time)
            ctx.fail("invalid-camera-path", at + ".t must be greater than the time of the key before it");
        path.keys.push_back(key);
    }
    return path;
}

void readProjection(const JsonReader& json, const Json& source, const std::string& where, Camera& c)
{
    if (json.string(source, "type", where) == "orthographic") {
        c.projection = Projection::Orthographic;
        const Json* o = json.member(source, "orthographic");
        if (!o || !o->is_object()) json.wrongType(where, "orthographic", "an object");
        c.xmag = json.number(*o, "xmag", c.xmag, where + ".orthographic");
        c.ymag = json.number(*o, "ymag", c.ymag, where + ".orthographic");
        c.znear = json.number(*o, "znear", c.znear, where + ".orthographic");
        c.zfar = json.number(*o, "zfar", c.zfar, where + ".orthographic");
        return;
    }
    const Json* p = json.member(source, "perspective");
    if (!p || !p->is_object()) json.wrongType(where, "perspective", "an object");
    c.yfov = json.number(*p, "yfov", c.yfov, where + ".perspective");
    c.aspectRatio = json.number(*p, "aspectRatio", c.aspectRatio, where + ".perspective");
    c.znear = json.number(*p, "znear", c.znear, where + ".perspective");
    c.zfar = json.number(*p, "zfar", c.zfar, where + ".perspective");
}

// glTF requires yfov in (0, pi), znear > 0 (orthographic: >= 0), zfar > znear, aspectRatio > 0 and
// xmag, ymag != 0; a degenerate camera casts every ray alike. Lenient but loud: each bad value is
// replaced by a usable one and named.
void fixCamera(GltfReadContext& ctx, const Json& source, const std::string& where, Camera& c)
{
    const Camera defaults;
    const auto fix = [&](float& value, float replacement, const std::string& key, const char* rule) {
        ctx.warn("invalid-value", where + "." + key + " is " + floatText(value) + " (" + rule + "): " +
                                      (replacement == 0.0f && key.ends_with("zfar") ? "the far plane is dropped" : "replaced by " + floatText(replacement)));
        value = replacement;
    };
    const bool ortho = c.projection == Projection::Orthographic;
    const std::string kind = ortho ? "orthographic." : "perspective.";
    const Json* projection = JsonReader{ctx.file}.member(source, ortho ? "orthographic" : "perspective");
    if (ortho) {
        if (c.xmag == 0.0f) fix(c.xmag, defaults.xmag, kind + "xmag", "must not be 0");
        if (c.ymag == 0.0f) fix(c.ymag, defaults.ymag, kind + "ymag", "must not be 0");
        if (c.znear < 0.0f) fix(c.znear, 0.0f, kind + "znear", "must be 0 or more");
    } else {
        if (!(c.yfov > 0.0f && c.yfov < glm::pi<float>())) fix(c.yfov, defaults.yfov, kind + "yfov", "must be between 0 and pi radians");
        if (c.znear <= 0.0f) fix(c.znear, defaults.znear, kind + "znear", "must be greater than 0");
        if (projection && projection->contains("aspectRatio") && c.aspectRatio <= 0.0f)
            fix(c.aspectRatio, 0.0f, kind + "aspectRatio", "must be greater than 0; the output's is used");
    }
    // Absent zfar (perspective) is an infinite far plane, which is what a bad one becomes.
    if (projection && projection->contains("zfar") && c.zfar <= c.znear) fix(c.zfar, 0.0f, kind + "zfar", "must be greater than znear");
}

LightType lightTypeFrom(const GltfReadContext& ctx, const std::string& type, const std::string& where)
{
    if (type == "directional") return LightType::Sun;
    if (type == "point") return LightType::Point;
    if (type == "spot") return LightType::Spot;
    ctx.fail("wrong-type", where + ".type is \"" + type + "\" (directional, point or spot)");
}

ShapeKind shapeKindFrom(const GltfReadContext& ctx, const std::string& kind, const std::string& where)
{
    static constexpr std::pair<const char*, ShapeKind> kKinds[] = {{"sphere", ShapeKind::Sphere}, {"quad", ShapeKind::Quad}, {"disk", ShapeKind::Disk},
                                                                   {"box", ShapeKind::Box}, {"cylinder", ShapeKind::Cylinder}, {"groundPlane", ShapeKind::GroundPlane}};
    for (const auto& [name, value] : kKinds)
        if (kind == name) return value;
    ctx.fail("wrong-type", where + ".kind is \"" + kind + "\", not a shape Glint knows");
}

} // namespace

Camera readCamera(GltfReadContext& ctx, int camera, const Json& node, const std::string& nodeWhere)
{
    const JsonReader json{ctx.file};
    const std::string where = "cameras[" + std::to_string(camera) + "]";
    const Json& source = ctx.doc["cameras"][static_cast<std::size_t>(camera)];
    Camera c;
    readProjection(json, source, where, c);
    fixCamera(ctx, source, where, c);
    if (const Json* e = json.extension(source, "GLINT_camera", where)) {
        c.lensRadius = json.number(*e, "lensRadius", c.lensRadius, where + ".extensions.GLINT_camera");
        c.focusDistance = json.number(*e, "focusDistance", c.focusDistance, where + ".extensions.GLINT_camera");
        c.exposure = json.number(*e, "exposure", c.exposure, where + ".extensions.GLINT_camera");
        if (c.projection == Projection::Orthographic && json.boolean(*e, "infiniteFar", false, where + ".extensions.GLINT_camera"))
            c.zfar = 0.0f;
    }
    if (const Json* e = json.extension(node, "GLINT_camera_path", nodeWhere)) c.path = readCameraPath(ctx, *e, nodeWhere + ".extensions.GLINT_camera_path");
    return c;
}

Light readLight(const GltfReadContext& ctx, int light)
{
    const JsonReader json{ctx.file};
    const std::string where = "extensions.KHR_lights_punctual.lights[" + std::to_string(light) + "]";
    const Json& source = ctx.doc["extensions"]["KHR_lights_punctual"]["lights"][static_cast<std::size_t>(light)];
    Light l;
    l.type = lightTypeFrom(ctx, json.string(source, "type", where), where);
    l.color = json.vec3(source, "color", l.color, where);
    l.intensity = json.number(source, "intensity", l.intensity, where);
    l.range = json.number(source, "range", l.range, where);
    if (const Json* spot = json.member(source, "spot"); spot && l.type == LightType::Spot) {
        l.innerConeAngle = json.number(*spot, "innerConeAngle", l.innerConeAngle, where + ".spot");
        l.outerConeAngle = json.number(*spot, "outerConeAngle", l.outerConeAngle, where + ".spot");
    }
    if (const Json* e = json.extension(source, "GLINT_light", where)) {
        l.angularDiameter = json.number(*e, "angularDiameter", l.angularDiameter, where + ".extensions.GLINT_light");
        l.radius = json.number(*e, "radius", l.radius, where + ".extensions.GLINT_light");
    }
    return l;
}

// Power, sizes and radius must be 0 or more and finite (a non-finite number is refused by the JSON
// checks): a negative one is clamped to 0 and named, as for materials (FILE_FORMAT.md).
Light readAreaLight(GltfReadContext& ctx, const Json& ext, const std::string& where)
{
    const JsonReader json{ctx.file};
    Light l;
    l.type = LightType::Area;
    const std::string shape = json.string(ext, "shape", where);
    if (shape == "rectangle") l.areaShape = AreaShape::Rectangle;
    else if (shape == "disk") l.areaShape = AreaShape::Disk;
    else if (shape == "sphere") l.areaShape = AreaShape::Sphere;
    else ctx.fail("wrong-type", where + ".shape is \"" + shape + "\" (rectangle, disk or sphere)");
    l.color = json.vec3(ext, "color", l.color, where);
    l.intensity = json.number(ext, "power", 0.0f, where);
    l.size = json.vec2(ext, "size", l.size, where); // a disk's diameter is size[0]
    l.radius = json.number(ext, "radius", l.radius, where);
    const auto atLeastZero = [&](float& value, const std::string& key) {
        if (value >= 0.0f) return;
        ctx.warn("invalid-value", where + "." + key + " is " + floatText(value) + " (must be 0 or more): clamped to 0");
        value = 0.0f;
    };
    atLeastZero(l.intensity, "power");
    atLeastZero(l.size.x, "size[0]");
    atLeastZero(l.size.y, "size[1]");
    atLeastZero(l.radius, "radius");
    atLeastZero(l.color.x, "color[0]");
    atLeastZero(l.color.y, "color[1]");
    atLeastZero(l.color.z, "color[2]");
    return l;
}

Shape readShape(GltfReadContext& ctx, const Json& ext, const std::string& where)
{
    const JsonReader json{ctx.file};
    Shape s;
    s.kind = shapeKindFrom(ctx, json.string(ext, "kind", where), where);
    s.radius = json.number(ext, "radius", s.radius, where);
    s.size = json.vec3(ext, "size", s.size, where);
    s.height = json.number(ext, "height", s.height, where);
    const int material = json.index(ext, "material", where);
    if (material >= 0) s.material = ctx.materialIds.at(static_cast<std::size_t>(material));
    s.portal = readPortalLink(ctx, ext, where); // checked as a pair once every node is read
    return s;
}

} // namespace glint
