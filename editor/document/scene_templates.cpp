#include "scene_templates.h"

#include "scene/io/scene_io.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QStandardPaths>

#include <glm/gtc/quaternion.hpp>

#include <numbers>
#include <stdexcept>

namespace glint::editor {

namespace {

// A file compiled into the editor (":/templates/NAME"), written to the user's data folder once (again
// when it differs, e.g. after an upgrade): scenes name files on disk.
std::filesystem::path shippedFile(const QString& name) {
    QFile source(QStringLiteral(":/templates/") + name);
    if (!source.open(QIODevice::ReadOnly)) throw std::runtime_error("missing template resource " + name.toStdString());
    const QByteArray bytes = source.readAll();
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/templates");
    const QString path = folder + QLatin1Char('/') + name;
    QFile existing(path);
    if (existing.open(QIODevice::ReadOnly) && existing.readAll() == bytes) return path.toStdString();
    existing.close();
    QDir().mkpath(folder);
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(bytes) != bytes.size())
        throw std::runtime_error("cannot write " + path.toStdString() + ": " + out.errorString().toStdString());
    return path.toStdString();
}

glm::quat lookAlong(glm::vec3 direction) {
    const glm::vec3 f = glm::normalize(direction);
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, f);
    return glm::quat_cast(glm::mat3(right, up, -f)); // glTF cameras look along their -Z
}

NodeId addNode(Scene& scene, std::string name, Component component, glm::vec3 at, glm::quat rotation = glm::quat(1, 0, 0, 0)) {
    Node node;
    node.name = std::move(name);
    node.component = std::move(component);
    node.local.translation = at;
    node.local.rotation = rotation;
    return scene.addNode(std::move(node));
}

// A ground plane in a mid-grey dielectric, and a camera 5 m back and 1.6 m up looking at the origin.
void addGroundAndCamera(Scene& scene) {
    Material grey;
    grey.name = "Ground";
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    grey.metallicFactor = 0.0f;
    grey.roughnessFactor = 0.6f;
    Shape ground;
    ground.kind = ShapeKind::GroundPlane;
    ground.material = scene.materials.add(grey);
    addNode(scene, "Ground", ground, glm::vec3(0.0f));
    Camera camera;
    camera.focusDistance = 5.2f;
    const glm::vec3 eye(0.0f, 1.6f, 5.0f);
    scene.settings.activeCamera = addNode(scene, "Camera", camera, eye, lookAlong(glm::vec3(0.0f, 0.3f, 0.0f) - eye));
}

Scene studio() {
    Scene scene;
    addGroundAndCamera(scene);
    scene.settings = withStudioLighting(scene.settings);
    return scene;
}

// A sun of 3 W/m^2 (2049 lux; Blender's new sun is 1 W/m^2, which reads as dusk) 50 degrees up,
// and a sky that adds about a sixth of its light (a clear sky's share).
Scene sunAndSky() {
    Scene scene;
    addGroundAndCamera(scene);
    Light sun;
    sun.type = LightType::Sun;
    sun.intensity = 3.0f * 683.0f;
    sun.angularDiameter = 0.0093f; // the sun's 0.53 degrees: soft shadow edges
    const float elevation = float(50.0 * std::numbers::pi / 180.0), azimuth = float(30.0 * std::numbers::pi / 180.0);
    const glm::vec3 shine(-std::cos(elevation) * std::sin(azimuth), -std::sin(elevation), -std::cos(elevation) * std::cos(azimuth));
    addNode(scene, "Sun", sun, glm::vec3(0.0f, 5.0f, 0.0f), lookAlong(shine));
    scene.settings.environment.color = glm::vec3(0.096f, 0.144f, 0.24f);
    return scene;
}

Scene cornellBox() { return loadScene(shippedFile(QStringLiteral("cornell_box.gltf"))).scene; }

// The box in a light haze (docs/MEDIA.md): 0.6 per metre over the box's 0.55 m dims the far wall by
// about a third and makes a visible glow under the lamp; albedo 0.9 and g 0.6 as in haze.
Scene cornellBoxInFog() {
    Scene scene = cornellBox();
    scene.settings.fog = {.density = 0.6f, .color = glm::vec3(0.9f), .anisotropy = 0.6f};
    return scene;
}

Material plainMaterial(std::string name, glm::vec3 colour, float metallic, float roughness) {
    Material m;
    m.name = std::move(name);
    m.baseColorFactor = glm::vec4(colour, 1.0f);
    m.metallicFactor = metallic;
    m.roughnessFactor = roughness;
    return m;
}

NodeId addShape(Scene& scene, std::string name, Shape shape, MaterialId material, glm::vec3 at,
                glm::quat rotation = glm::quat(1, 0, 0, 0)) {
    shape.material = material;
    return addNode(scene, std::move(name), shape, at, rotation);
}

// Sun and sky with a portal pair (docs/PORTALS.md): A stands left of centre facing the camera; B
// stands 9 m off to the right, out of the view, facing +X towards a red ball and a gold box. Through
// A the camera sees them, as if it stood behind B; a white ball beside A is seen directly.
Scene portals() {
    Scene scene = sunAndSky();
    const float quarterTurn = 0.5f * std::numbers::pi_v<float>;
    const glm::quat facingCamera = glm::angleAxis(quarterTurn, glm::vec3(1, 0, 0)); // normal +Y turned to +Z
    const glm::quat facingX = glm::angleAxis(quarterTurn, glm::vec3(0, 1, 0)) * facingCamera;
    Shape quad;
    quad.kind = ShapeKind::Quad;
    quad.size = {2.0f, 1.0f, 2.0f};
    const MaterialId frame = scene.materials.add(plainMaterial("Portal", glm::vec3(0.2f), 0.0f, 0.5f));
    const NodeId a = addShape(scene, "Portal A", quad, frame, {-1.3f, 1.0f, 0.0f}, facingCamera);
    const NodeId b = addShape(scene, "Portal B", quad, frame, {9.0f, 1.0f, -6.0f}, facingX);
    std::get<Shape>(scene.component(a)).portal = b;
    std::get<Shape>(scene.component(b)).portal = a;
    Shape ball;
    ball.radius = 0.5f;
    addShape(scene, "Red ball", ball, scene.materials.add(plainMaterial("Red", {0.8f, 0.1f, 0.08f}, 0.0f, 0.4f)),
             {11.5f, 0.5f, -6.3f});
    addShape(scene, "White ball", ball, scene.materials.add(plainMaterial("White", glm::vec3(0.8f), 0.0f, 0.3f)),
             {1.3f, 0.5f, 0.0f});
    Shape box;
    box.kind = ShapeKind::Box;
    box.size = glm::vec3(0.7f);
    addShape(scene, "Gold box", box, scene.materials.add(plainMaterial("Gold", {1.0f, 0.77f, 0.34f}, 1.0f, 0.25f)),
             {11.0f, 0.35f, -5.0f}, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)));
    return scene;
}

} // namespace

const char* templateTitle(SceneTemplate kind) {
    switch (kind) {
    case SceneTemplate::Studio: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Studio");
    case SceneTemplate::Empty: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Empty");
    case SceneTemplate::SunAndSky: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Sun and sky");
    case SceneTemplate::CornellBox: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Cornell box");
    case SceneTemplate::CornellBoxInFog: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Cornell box in fog");
    case SceneTemplate::Portals: return QT_TRANSLATE_NOOP("glint::editor::SceneTemplates", "Portals");
    }
    return "";
}

const char* templateActionId(SceneTemplate kind) {
    switch (kind) {
    case SceneTemplate::Studio: return "file.new.studio";
    case SceneTemplate::Empty: return "file.new.empty";
    case SceneTemplate::SunAndSky: return "file.new.sun_and_sky";
    case SceneTemplate::CornellBox: return "file.new.cornell_box";
    case SceneTemplate::CornellBoxInFog: return "file.new.cornell_box_fog";
    case SceneTemplate::Portals: return "file.new.portals";
    }
    return "";
}

ProjectSettings withStudioLighting(ProjectSettings settings) {
    settings.environment.file = shippedFile(QStringLiteral("studio_small_03_1k.hdr")).string();
    // The studio's lamps give the ground about 11 W/m^2: 2.5 stops down keeps the mid-grey ground a
    // light grey instead of white.
    settings.render.exposure = -2.5f;
    return settings;
}

Scene buildTemplate(SceneTemplate kind) {
    switch (kind) {
    case SceneTemplate::Studio: return studio();
    case SceneTemplate::Empty: return Scene{};
    case SceneTemplate::SunAndSky: return sunAndSky();
    case SceneTemplate::CornellBox: return cornellBox();
    case SceneTemplate::CornellBoxInFog: return cornellBoxInFog();
    case SceneTemplate::Portals: return portals();
    }
    return Scene{};
}

} // namespace glint::editor
