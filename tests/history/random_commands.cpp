#include "random_commands.h"

#include "sample_scene.h"
#include "scene/anim/node_keys.h"
#include "scene/history/asset_commands.h"
#include "scene/history/asset_usage.h"
#include "scene/history/camera_path_commands.h"
#include "scene/history/material_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace glint::test {
namespace {

constexpr std::size_t kMaxNodes = 30;
constexpr std::size_t kMaxAssetsPerTable = 8;

template <class IdT, class T>
std::vector<IdT> idsOf(const AssetTable<IdT, T>& table) {
    std::vector<IdT> ids;
    for (const auto& entry : table) ids.push_back(entry.first);
    return ids;
}

// An existing id, or none (with the given chance, or when the table is empty).
template <class IdT, class T>
IdT maybeOneOf(RandomSource& random, const AssetTable<IdT, T>& table, std::uint32_t nonePercent) {
    const std::vector<IdT> ids = idsOf(table);
    if (ids.empty() || random.chance(nonePercent)) return IdT{};
    return random.pick(ids);
}

glm::vec3 randomVec(RandomSource& random, float lo, float hi) {
    return {random.between(lo, hi), random.between(lo, hi), random.between(lo, hi)};
}

std::vector<NodeId> camerasOf(const Scene& scene) {
    std::vector<NodeId> cameras;
    for (NodeId id : scene.depthFirst())
        if (scene.at(id).get<Camera>()) cameras.push_back(id);
    return cameras;
}

Component randomComponent(RandomSource& random, const Scene& scene) {
    switch (random.below(6)) {
    case 0: return std::monostate{};
    case 1: {
        const MeshId mesh = maybeOneOf(random, scene.meshes, 0);
        if (mesh) return MeshInstance{mesh};
        return std::monostate{};
    }
    case 2: {
        Shape shape;
        shape.kind = static_cast<ShapeKind>(random.below(6));
        shape.radius = random.between(0.1f, 2.0f);
        shape.size = randomVec(random, 0.1f, 3.0f);
        shape.material = maybeOneOf(random, scene.materials, 20);
        return shape;
    }
    case 3: {
        Light light;
        light.type = static_cast<LightType>(random.below(3));
        light.color = randomVec(random, 0.0f, 1.0f);
        light.intensity = random.between(0.0f, 100.0f);
        return light;
    }
    default: {
        Camera camera;
        camera.projection = static_cast<Projection>(random.below(2));
        camera.yfov = random.between(0.2f, 1.5f);
        camera.exposure = random.between(-2.0f, 2.0f);
        return camera;
    }
    }
}

// An edit of the node's component that keeps its kind most of the time.
Component editedComponent(RandomSource& random, const Scene& scene, const Component& current) {
    if (random.chance(15)) return randomComponent(random, scene);
    Component edited = current;
    if (auto* light = std::get_if<Light>(&edited)) light->intensity = random.between(0.0f, 100.0f);
    else if (auto* shape = std::get_if<Shape>(&edited)) shape->radius = random.between(0.1f, 2.0f);
    else if (auto* camera = std::get_if<Camera>(&edited)) camera->yfov = random.between(0.2f, 1.5f);
    else return randomComponent(random, scene);
    return edited;
}

CommandPtr addNode(RandomSource& random, const Scene& scene) {
    Node node;
    node.name = "node " + std::to_string(random.below(1000));
    node.local = randomTransform(random);
    node.visible = random.chance(90);
    node.component = randomComponent(random, scene);
    const std::vector<NodeId> nodes = scene.depthFirst();
    const NodeId parent = nodes.empty() || random.chance(30) ? NodeId{} : random.pick(nodes);
    return std::make_unique<AddNode>(node, parent, random.below(4));
}

CommandPtr reparent(RandomSource& random, const Scene& scene, NodeId node) {
    std::vector<NodeId> parents{NodeId{}};
    for (NodeId candidate : scene.depthFirst())
        if (candidate != node && !scene.isAncestor(node, candidate)) parents.push_back(candidate);
    return std::make_unique<ReparentNode>(node, random.pick(parents), random.below(4), random.chance(50));
}

CommandPtr nodeCommand(RandomSource& random, const Scene& scene) {
    const std::vector<NodeId> nodes = scene.depthFirst();
    if (nodes.size() < 4 || (nodes.size() < kMaxNodes && random.chance(25))) return addNode(random, scene);
    const NodeId node = random.pick(nodes);
    switch (random.below(7)) {
    case 0: return randomTransformEdit(random, scene, node);
    case 1: return std::make_unique<RenameNode>(node, "renamed " + std::to_string(random.below(1000)));
    case 2: return std::make_unique<SetVisibility>(node, !scene.at(node).visible);
    case 3: return std::make_unique<SetComponent>(node, editedComponent(random, scene, scene.at(node).component));
    case 4: return std::make_unique<RemoveNode>(node);
    case 5:
        if (nodes.size() + scene.subtree(node).size() <= kMaxNodes) return std::make_unique<DuplicateNode>(node);
        return std::make_unique<RemoveNode>(node);
    default: return reparent(random, scene, node);
    }
}

Mesh randomMesh(RandomSource& random, const Scene& scene) {
    Primitive p;
    p.positions = {randomVec(random, -1, 1), randomVec(random, -1, 1), randomVec(random, -1, 1)};
    p.indices = {0, 1, 2};
    p.material = maybeOneOf(random, scene.materials, 30);
    Mesh mesh;
    mesh.name = "mesh " + std::to_string(random.below(1000));
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

Material randomMaterial(RandomSource& random, const Scene& scene, Material material) {
    material.baseColorFactor = glm::vec4(randomVec(random, 0, 1), 1.0f);
    material.roughnessFactor = random.between(0, 1);
    material.metallicFactor = random.chance(50) ? 0.0f : 1.0f;
    material.transmissionFactor = random.chance(20) ? 1.0f : 0.0f;
    if (random.chance(20)) material.baseColorTexture.texture = maybeOneOf(random, scene.textures, 40);
    if (random.chance(20)) {
        material.scatterColor = randomVec(random, 0, 1);
        material.scatterAnisotropy = random.between(-0.9f, 0.9f);
    }
    return material;
}

Image randomImage(RandomSource& random) {
    Image image;
    image.name = "image " + std::to_string(random.below(1000));
    image.mimeType = "image/png";
    image.encoded = tinyPng();
    image.width = image.height = 1;
    return image;
}

Sampler randomSampler(RandomSource& random) {
    Sampler sampler;
    sampler.name = "sampler " + std::to_string(random.below(1000));
    const Wrap wraps[] = {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat};
    sampler.wrapS = wraps[random.below(3)];
    sampler.wrapT = wraps[random.below(3)];
    return sampler;
}

Texture randomTexture(RandomSource& random, const Scene& scene) {
    Texture texture;
    texture.name = "texture " + std::to_string(random.below(1000));
    texture.image = maybeOneOf(random, scene.images, 10);
    texture.sampler = maybeOneOf(random, scene.samplers, 30);
    return texture;
}

template <class T, class IdT>
CommandPtr removeUnused(RandomSource& random, const Scene& scene, const AssetTable<IdT, T>& table) {
    std::vector<IdT> unused;
    for (IdT id : idsOf(table))
        if (!isInUse(scene, id)) unused.push_back(id);
    if (unused.empty()) return nullptr;
    return std::make_unique<RemoveAsset<T>>(random.pick(unused));
}

// Adds while a table is small, removes unused assets while it is large, else edits.
template <class T, class IdT, class Make>
CommandPtr assetCommand(RandomSource& random, const Scene& scene, const AssetTable<IdT, T>& table, Make make) {
    if (table.empty() || (table.size() < kMaxAssetsPerTable && random.chance(30)))
        return std::make_unique<AddAsset<T>>(make());
    if (random.chance(30))
        if (CommandPtr remove = removeUnused(random, scene, table)) return remove;
    return std::make_unique<SetAsset<T>>(random.pick(idsOf(table)), make());
}

// Points a random primitive at a random material (or none), as the materials panel assigns.
CommandPtr primitiveMaterialCommand(RandomSource& random, const Scene& scene) {
    const MeshId mesh = maybeOneOf(random, scene.meshes, 0);
    if (!mesh || scene.meshes.at(mesh).primitives.empty()) return std::make_unique<AddAsset<Mesh>>(randomMesh(random, scene));
    const auto primitives = static_cast<std::uint32_t>(scene.meshes.at(mesh).primitives.size());
    return std::make_unique<SetPrimitiveMaterial>(mesh, random.below(primitives), maybeOneOf(random, scene.materials, 20));
}

CommandPtr anyAssetCommand(RandomSource& random, const Scene& scene) {
    if (random.chance(10)) return primitiveMaterialCommand(random, scene);
    switch (random.below(5)) {
    case 0: return assetCommand(random, scene, scene.meshes, [&] { return randomMesh(random, scene); });
    case 1: return assetCommand(random, scene, scene.materials, [&] { return randomMaterial(random, scene, Material{}); });
    case 2: return assetCommand(random, scene, scene.textures, [&] { return randomTexture(random, scene); });
    case 3: return assetCommand(random, scene, scene.images, [&] { return randomImage(random); });
    default: return assetCommand(random, scene, scene.samplers, [&] { return randomSampler(random); });
    }
}

// A time on a 0.25 s grid that no key of the path uses yet; none if all are taken.
std::optional<double> freeKeyTime(RandomSource& random, const CameraPath& path) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        const double time = 0.25 * random.below(40);
        const bool taken = std::any_of(path.keys.begin(), path.keys.end(), [&](const CameraKey& k) { return k.time == time; });
        if (!taken) return time;
    }
    return std::nullopt;
}

CameraKey randomKey(RandomSource& random, double time) {
    CameraKey key;
    key.time = time;
    key.position = glm::dvec3(randomVec(random, -5, 5));
    key.orientation = glm::dquat(glm::angleAxis(random.between(-3, 3), glm::vec3(0, 1, 0)));
    key.yfov = random.between(0.2f, 1.5f);
    return key;
}

CommandPtr cameraPathCommand(RandomSource& random, const Scene& scene) {
    const std::vector<NodeId> cameras = camerasOf(scene);
    if (cameras.empty()) return addNode(random, scene);
    const NodeId camera = random.pick(cameras);
    const CameraPath& path = scene.at(camera).get<Camera>()->path;
    const auto keyCount = static_cast<std::uint32_t>(path.keys.size());
    const std::optional<double> time = freeKeyTime(random, path);
    const std::uint32_t kind = keyCount == 0 ? 0 : random.below(5);
    if (kind == 4) return std::make_unique<SetCameraPathMode>(camera, static_cast<RotationInterpolation>(random.below(2)), random.chance(50));
    if (kind == 1 && keyCount > 0) return std::make_unique<RemoveCameraKey>(camera, random.below(keyCount));
    if (kind == 2 && time) return std::make_unique<MoveCameraKey>(camera, random.below(keyCount), *time);
    if (kind == 3 || !time) {
        if (keyCount == 0) return std::make_unique<SetCameraPathMode>(camera, RotationInterpolation::Slerp, true);
        return std::make_unique<EditCameraKey>(camera, random.below(keyCount), randomKey(random, 0.0));
    }
    return std::make_unique<AddCameraKey>(camera, randomKey(random, *time));
}

// Keys a random node at a free time on a 0.5 s grid, or moves, deletes or re-times its keys, or
// removes its animation: the edits the timeline makes (scene/anim/node_keys.h).
CommandPtr nodeKeyCommand(RandomSource& random, const Scene& scene) {
    const std::vector<NodeId> nodes = scene.depthFirst();
    if (nodes.empty()) return addNode(random, scene);
    const NodeId node = random.pick(nodes);
    const double time = 0.5 * random.below(8);
    const auto interpolation = static_cast<Interpolation>(random.below(3));
    const std::optional<AnimationId> id = nodeKeyAnimation(scene, node);
    if (!id) return std::make_unique<AddAsset<Animation>>(withNodeKey({}, node, time, randomTransform(random), interpolation));
    const Animation& animation = scene.animations.at(*id);
    const std::vector<double> times = nodeKeyTimes(animation, node);
    switch (random.below(5)) {
    case 0: return std::make_unique<RemoveAsset<Animation>>(*id);
    case 1: return std::make_unique<SetAsset<Animation>>(*id, withoutNodeKey(animation, node, random.pick(times)));
    case 2: return std::make_unique<SetAsset<Animation>>(*id, withNodeKeyMoved(animation, node, random.pick(times), time));
    case 3: return std::make_unique<SetAsset<Animation>>(*id, withNodeInterpolation(animation, node, interpolation));
    default: return std::make_unique<SetAsset<Animation>>(*id, withNodeKey(animation, node, time, randomTransform(random), interpolation));
    }
}

CommandPtr settingsCommand(RandomSource& random, const Scene& scene) {
    ProjectSettings settings = scene.settings;
    switch (random.below(5)) {
    case 0: settings.render.exposure = random.between(-3, 3); break;
    case 1: settings.render.tonemapper = static_cast<Tonemapper>(random.below(3)); break;
    case 2: settings.render.spp = 1 + static_cast<int>(random.below(256)); break;
    case 3: settings.environment.intensity = random.between(0, 4); break;
    case 4:
        settings.fog.density = random.chance(25) ? 0.0f : random.between(0.0f, 0.5f);
        settings.fog.anisotropy = random.between(-0.9f, 0.9f);
        break;
    default: {
        std::vector<NodeId> cameras = camerasOf(scene);
        cameras.push_back(NodeId{});
        settings.activeCamera = random.pick(cameras);
    }
    }
    return std::make_unique<SetProjectSettings>(settings);
}

} // namespace

Transform randomTransform(RandomSource& random) {
    Transform t;
    t.translation = randomVec(random, -5, 5);
    t.rotation = glm::angleAxis(random.between(-3, 3), glm::normalize(randomVec(random, 0.1f, 1.0f)));
    t.scale = randomVec(random, 0.5f, 2.0f);
    return t;
}

CommandPtr randomTransformEdit(RandomSource& random, const Scene&, NodeId node) {
    return std::make_unique<SetTransform>(node, randomTransform(random));
}

CommandPtr randomMaterialEdit(RandomSource& random, const Scene& scene, MaterialId material) {
    return std::make_unique<SetAsset<Material>>(material, randomMaterial(random, scene, scene.materials.at(material)));
}

CommandPtr randomCommand(RandomSource& random, const Scene& scene) {
    const std::uint32_t family = random.below(10);
    if (family < 5) return nodeCommand(random, scene);
    if (family < 7) return anyAssetCommand(random, scene);
    if (family < 8) return cameraPathCommand(random, scene);
    if (family < 9) return nodeKeyCommand(random, scene);
    return settingsCommand(random, scene);
}

} // namespace glint::test
