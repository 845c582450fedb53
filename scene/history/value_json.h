#pragma once
// JSON forms of the scene's value types, for command logs. Not a file format: glTF and the
// project file are. Numbers keep every bit (nlohmann writes doubles as shortest round-trip
// decimals); the one infinite default (Material::attenuationDistance) is written as a string.
#include "scene/core/scene.h"
#include "scene/history/checked_numbers.h"

#include <nlohmann/json.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace nlohmann {

template <glm::length_t L, class T, glm::qualifier Q>
struct adl_serializer<glm::vec<L, T, Q>> {
    static void to_json(json& j, const glm::vec<L, T, Q>& v) {
        j = json::array();
        for (glm::length_t i = 0; i < L; ++i) j.push_back(v[i]);
    }
    static void from_json(const json& j, glm::vec<L, T, Q>& v) {
        if (!j.is_array() || j.size() != static_cast<std::size_t>(L)) throw std::invalid_argument("vector of wrong size");
        for (glm::length_t i = 0; i < L; ++i) v[i] = glint::checkedNumber<T>(j.at(static_cast<std::size_t>(i)));
    }
};

// Quaternions as glTF writes them: [x, y, z, w].
template <class T, glm::qualifier Q>
struct adl_serializer<glm::qua<T, Q>> {
    static void to_json(json& j, const glm::qua<T, Q>& q) { j = json::array({q.x, q.y, q.z, q.w}); }
    static void from_json(const json& j, glm::qua<T, Q>& q) {
        if (!j.is_array() || j.size() != 4) throw std::invalid_argument("quaternion needs 4 numbers");
        q = glm::qua<T, Q>(glint::checkedNumber<T>(j[3]), glint::checkedNumber<T>(j[0]), glint::checkedNumber<T>(j[1]),
                           glint::checkedNumber<T>(j[2]));
    }
};

template <class T>
struct adl_serializer<glint::SharedArray<T>> {
    static void to_json(json& j, const glint::SharedArray<T>& a) { j = a.vector(); }
    static void from_json(const json& j, glint::SharedArray<T>& a) {
        if (!j.is_array()) throw std::invalid_argument("array expected");
        std::vector<T> values;
        values.reserve(j.size());
        for (const json& element : j) {
            if constexpr (std::is_arithmetic_v<T>) values.push_back(glint::checkedNumber<T>(element));
            else values.push_back(element.get<T>());
        }
        a = std::move(values);
    }
};

template <class Tag>
struct adl_serializer<glint::Id<Tag>> {
    static void to_json(json& j, glint::Id<Tag> id) { j = id.value; }
    static void from_json(const json& j, glint::Id<Tag>& id) { id = glint::Id<Tag>{glint::checkedNumber<std::uint32_t>(j)}; }
};

} // namespace nlohmann

namespace glint {

// One field of a generated reader (GLINT_JSON_TYPE below). Numbers go through checkedNumber, so an
// integer field refuses a non-integral number, a negative one for an unsigned field and one out of
// its range, naming the key (nlohmann's own readers cast: -1.5 to an unsigned is undefined, -1
// becomes 4294967295, 2.5 becomes 2); everything else reads as nlohmann reads it.
template <class T>
void readJsonField(const nlohmann::json& value, const char* key, T& field) {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        try {
            field = checkedNumber<T>(value);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("key '") + key + "': " + e.what());
        }
    } else {
        value.get_to(field);
    }
}

// The same where a missing key keeps `fallback` (readers of types that gained fields later).
template <class T>
void readJsonFieldOr(const nlohmann::json& object, const char* key, T& field, const T& fallback) {
    if (!object.is_object()) throw std::invalid_argument(std::string("an object with key '") + key + "' expected");
    const auto found = object.find(key);
    if (found == object.end()) field = fallback;
    else readJsonField(*found, key, field);
}

} // namespace glint

// GLINT_JSON_TYPE(_WITH_DEFAULT) with readJsonField(Or) for each field.
#define GLINT_JSON_FROM(v1) ::glint::readJsonField(nlohmann_json_j.at(#v1), #v1, nlohmann_json_t.v1);
#define GLINT_JSON_FROM_WITH_DEFAULT(v1) ::glint::readJsonFieldOr(nlohmann_json_j, #v1, nlohmann_json_t.v1, nlohmann_json_default_obj.v1);
#define GLINT_JSON_TYPE(Type, ...)                                                                                        \
    inline void to_json(nlohmann::json& nlohmann_json_j, const Type& nlohmann_json_t) {                                   \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))                                          \
    }                                                                                                                     \
    inline void from_json(const nlohmann::json& nlohmann_json_j, Type& nlohmann_json_t) {                                 \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(GLINT_JSON_FROM, __VA_ARGS__))                                           \
    }
#define GLINT_JSON_TYPE_WITH_DEFAULT(Type, ...)                                                                           \
    inline void to_json(nlohmann::json& nlohmann_json_j, const Type& nlohmann_json_t) {                                   \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))                                          \
    }                                                                                                                     \
    inline void from_json(const nlohmann::json& nlohmann_json_j, Type& nlohmann_json_t) {                                 \
        const Type nlohmann_json_default_obj{};                                                                           \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(GLINT_JSON_FROM_WITH_DEFAULT, __VA_ARGS__))                              \
    }

namespace glint {

NLOHMANN_JSON_SERIALIZE_ENUM(ShapeKind, {{ShapeKind::Sphere, "sphere"}, {ShapeKind::Quad, "quad"},
                                         {ShapeKind::Disk, "disk"}, {ShapeKind::Box, "box"},
                                         {ShapeKind::Cylinder, "cylinder"}, {ShapeKind::GroundPlane, "groundPlane"}})
NLOHMANN_JSON_SERIALIZE_ENUM(LightType, {{LightType::Sun, "sun"}, {LightType::Point, "point"}, {LightType::Spot, "spot"},
                                         {LightType::Area, "area"}})
NLOHMANN_JSON_SERIALIZE_ENUM(AreaShape, {{AreaShape::Rectangle, "rectangle"}, {AreaShape::Disk, "disk"}, {AreaShape::Sphere, "sphere"}})
NLOHMANN_JSON_SERIALIZE_ENUM(Projection, {{Projection::Perspective, "perspective"}, {Projection::Orthographic, "orthographic"}})
NLOHMANN_JSON_SERIALIZE_ENUM(RotationInterpolation, {{RotationInterpolation::Slerp, "slerp"}, {RotationInterpolation::Squad, "squad"}})
NLOHMANN_JSON_SERIALIZE_ENUM(Interpolation, {{Interpolation::Step, "step"}, {Interpolation::Linear, "linear"},
                                             {Interpolation::CubicSpline, "cubicSpline"}})
NLOHMANN_JSON_SERIALIZE_ENUM(AnimationPath, {{AnimationPath::Translation, "translation"}, {AnimationPath::Rotation, "rotation"},
                                             {AnimationPath::Scale, "scale"}, {AnimationPath::Weights, "weights"}})
NLOHMANN_JSON_SERIALIZE_ENUM(AlphaMode, {{AlphaMode::Opaque, "opaque"}, {AlphaMode::Mask, "mask"}, {AlphaMode::Blend, "blend"}})
NLOHMANN_JSON_SERIALIZE_ENUM(LightUnits, {{LightUnits::Blender, "blender"}, {LightUnits::Raw, "raw"}})
NLOHMANN_JSON_SERIALIZE_ENUM(Tonemapper, {{Tonemapper::None, "none"}, {Tonemapper::AcesFitted, "acesFitted"},
                                          {Tonemapper::PbrNeutral, "pbrNeutral"}, {Tonemapper::AgX, "agx"},
                                          {Tonemapper::Reinhard, "reinhard"}, {Tonemapper::Hable, "hable"}})

GLINT_JSON_TYPE(Transform, translation, rotation, scale)
GLINT_JSON_TYPE(MeshInstance, mesh)
// With defaults: command logs written before portals existed still replay.
GLINT_JSON_TYPE_WITH_DEFAULT(Shape, kind, radius, size, height, material, portal)
// With defaults: command logs written before area lights existed still replay.
GLINT_JSON_TYPE_WITH_DEFAULT(Light, type, color, intensity, range, innerConeAngle, outerConeAngle,
                                                angularDiameter, radius, areaShape, size)
GLINT_JSON_TYPE(CameraKey, time, position, orientation, yfov, focusDistance, lensRadius)
GLINT_JSON_TYPE(CameraPath, keys, rotation, constantSpeed)
GLINT_JSON_TYPE(Camera, projection, yfov, aspectRatio, znear, zfar, xmag, ymag, lensRadius,
                                   focusDistance, exposure, path)
GLINT_JSON_TYPE(TextureTransform, offset, rotation, scale, texCoord)
GLINT_JSON_TYPE(TextureRef, texture, texCoord, scale, transform, unknown)
GLINT_JSON_TYPE(Primitive, positions, normals, tangents, uv0, uv1, colors, indices, material,
                                   unknown)
GLINT_JSON_TYPE(Mesh, name, primitives, unknown)
GLINT_JSON_TYPE(AnimationChannel, node, path, interpolation, times, values)
GLINT_JSON_TYPE(Animation, name, channels, bakedCameraPath, unknown)
GLINT_JSON_TYPE(Image, name, uri, mimeType, encoded, width, height, missing, unknown)
GLINT_JSON_TYPE(Sampler, name, magFilter, minFilter, wrapS, wrapT, unknown)
GLINT_JSON_TYPE(Texture, name, image, sampler, unknown)
GLINT_JSON_TYPE(Environment, file, color, intensity, rotationDegrees)
NLOHMANN_JSON_SERIALIZE_ENUM(TaaClip, {{TaaClip::Variance, "variance"}, {TaaClip::MinMax, "minmax"}, {TaaClip::None, "none"}})
GLINT_JSON_TYPE_WITH_DEFAULT(TaaParameters, blend, clip, clipGamma, perceptualBlend)
GLINT_JSON_TYPE_WITH_DEFAULT(SvgfParameters, iterations, alpha, momentsAlpha, sigmaLuminance,
                                                sigmaNormal, sigmaDepth, fireflyRatio)
GLINT_JSON_TYPE_WITH_DEFAULT(BloomParameters, strength, radius)
NLOHMANN_JSON_SERIALIZE_ENUM(AdaptiveGoal, {{AdaptiveGoal::Even, adaptiveGoalName(AdaptiveGoal::Even)},
                                            {AdaptiveGoal::Mean, adaptiveGoalName(AdaptiveGoal::Mean)}})
// With defaults: command logs written before the adaptive goal existed still replay.
GLINT_JSON_TYPE_WITH_DEFAULT(AdaptiveSampling, threshold, minSamples, goal)
// With defaults: command logs written before the reconstruction parameters, motion blur and
// adaptive sampling existed still replay.
GLINT_JSON_TYPE_WITH_DEFAULT(RenderSettings, configuration, width, height, spp, bounces, seed,
                                                exposure, tonemapper, clamp, shutter, taa, svgf, bloom, adaptive)
GLINT_JSON_TYPE(Timeline, start, end, fpsNumerator, fpsDenominator)
GLINT_JSON_TYPE_WITH_DEFAULT(OutputSettings, path, aovs, passes, codec)
GLINT_JSON_TYPE(Fog, density, color, anisotropy, heightFalloff, baseHeight)
// With defaults: command logs written before fog existed still replay.
GLINT_JSON_TYPE_WITH_DEFAULT(ProjectSettings, render, environment, fog, activeCamera, timeline, output,
                                                lightUnits, unknown)

// Hand-written: attenuationDistance defaults to infinity, which JSON numbers cannot hold.
void to_json(nlohmann::json& j, const Material& material);
void from_json(const nlohmann::json& j, Material& material);

// {"kind": "none" | "mesh" | "shape" | "light" | "camera", "value": ...}
void to_json(nlohmann::json& j, const Component& component);
void from_json(const nlohmann::json& j, Component& component);

// A node's own content (id, name, transform, visibility, component, unknown); the hierarchy
// (parent, children) belongs to the command that places the node.
void to_json(nlohmann::json& j, const Node& node);
void from_json(const nlohmann::json& j, Node& node);

} // namespace glint
