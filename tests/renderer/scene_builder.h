#pragma once
// Small scenes built in code for the renderer's tests: materials, shapes, lights and cameras in a
// line each.
#include "scene/core/scene.h"

#include <glm/gtc/quaternion.hpp>

namespace glint::test {

inline Material lambert(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.baseColorFactor = glm::vec4(albedo, 1.0f);
    m.metallicFactor = 0.0f;
    m.specularFactor = 0.0f; // KHR_materials_specular 0: pure Lambert
    m.emissiveFactor = emission;
    return m;
}

inline Material mirror() {
    Material m;
    m.metallicFactor = 1.0f;
    m.roughnessFactor = 0.0f;
    return m;
}

inline Material glass(float ior, float thickness) {
    Material m;
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.0f;
    m.transmissionFactor = 1.0f;
    m.ior = ior;
    m.thicknessFactor = thickness;
    return m;
}

// Rotation that turns the camera's -Z towards `direction`.
inline glm::quat lookRotation(glm::vec3 direction, glm::vec3 up = {0.0f, 1.0f, 0.0f}) {
    return glm::quatLookAt(glm::normalize(direction), up);
}

inline NodeId addNode(Scene& scene, const std::string& name, Component component, glm::vec3 position,
                      glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f), glm::vec3 scale = glm::vec3(1.0f)) {
    Node node;
    node.name = name;
    node.local.translation = position;
    node.local.rotation = rotation;
    node.local.scale = scale;
    node.component = std::move(component);
    return scene.addNode(std::move(node));
}

inline NodeId addShape(Scene& scene, ShapeKind kind, MaterialId material, glm::vec3 position, float radius = 0.5f,
                       glm::vec3 size = glm::vec3(1.0f), glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
    Shape shape;
    shape.kind = kind;
    shape.material = material;
    shape.radius = radius;
    shape.size = size;
    return addNode(scene, "shape", shape, position, rotation);
}

inline NodeId addPerspectiveCamera(Scene& scene, glm::vec3 position, glm::vec3 target, float yfov) {
    Camera camera;
    camera.yfov = yfov;
    const glm::vec3 forward = target - position;
    const glm::vec3 up = std::abs(glm::normalize(forward).y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return addNode(scene, "camera", camera, position, lookRotation(forward, up));
}

inline NodeId addOrthographicCamera(Scene& scene, glm::vec3 position, glm::vec3 direction, float halfHeight) {
    Camera camera;
    camera.projection = Projection::Orthographic;
    camera.xmag = halfHeight;
    camera.ymag = halfHeight;
    const glm::vec3 up = std::abs(glm::normalize(direction).y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return addNode(scene, "camera", camera, position, lookRotation(direction, up));
}

inline NodeId addSun(Scene& scene, glm::vec3 shineDirection, float lux, float angularDiameter = 0.0f) {
    Light light;
    light.type = LightType::Sun;
    light.intensity = lux;
    light.angularDiameter = angularDiameter;
    return addNode(scene, "sun", light, glm::vec3(0.0f), lookRotation(shineDirection,
                   std::abs(glm::normalize(shineDirection).y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f)));
}

} // namespace glint::test
