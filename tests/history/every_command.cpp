#include "every_command.h"

#include "scene/history/asset_commands.h"
#include "scene/history/camera_path_commands.h"
#include "scene/history/macro_command.h"
#include "scene/history/material_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"
#include "scene/anim/node_keys.h"

namespace glint::test {
namespace {

// Ids for assets the sequence adds and later removes; far above the sample's own ids.
constexpr MeshId kNewMesh{100};
constexpr MaterialId kNewMaterial{100};
constexpr TextureId kNewTexture{100};
constexpr ImageId kNewImage{100};
constexpr SamplerId kNewSampler{100};
constexpr AnimationId kNewAnimation{100};

void addNodeCommands(std::vector<CommandPtr>& out, const SampleIds& ids) {
    Node lamp;
    lamp.name = "new lamp";
    lamp.component = Light{.type = LightType::Spot, .intensity = 20.0f};
    out.push_back(std::make_unique<AddNode>(lamp, ids.world, 1));
    out.push_back(std::make_unique<RenameNode>(ids.sun, "key light"));
    Transform moved;
    moved.translation = {0.5f, 1.5f, -1.0f};
    moved.rotation = glm::angleAxis(0.3f, glm::vec3(0, 1, 0));
    moved.scale = {2.0f, 2.0f, 2.0f};
    out.push_back(std::make_unique<SetTransform>(ids.ball, moved));
    out.push_back(std::make_unique<SetVisibility>(ids.floor, false));
    out.push_back(std::make_unique<SetComponent>(ids.lamp, Light{.type = LightType::Point, .intensity = 80.0f}));
    out.push_back(std::make_unique<DuplicateNode>(ids.ball));
    out.push_back(std::make_unique<ReparentNode>(ids.lamp, NodeId{}, 0, true));
}

Mesh editedMesh(Mesh mesh) {
    mesh.name = "edited";
    mesh.primitives.front().positions[2] = {0.0f, 2.0f, 0.0f};
    return mesh;
}

void addAssetCommands(std::vector<CommandPtr>& out, const Scene& start, const SampleIds& ids) {
    Material blue;
    blue.name = "blue";
    blue.baseColorFactor = {0.1f, 0.1f, 0.9f, 1.0f};
    out.push_back(std::make_unique<AddAsset<Material>>(blue, kNewMaterial));
    Material red = start.materials.at(ids.red);
    red.roughnessFactor = 0.25f;
    red.attenuationDistance = 3.0f;
    red.scatterColor = {0.9f, 0.5f, 0.25f};
    red.scatterAnisotropy = -0.4f;
    out.push_back(std::make_unique<SetAsset<Material>>(ids.red, red));
    out.push_back(std::make_unique<AddAsset<Mesh>>(start.meshes.at(ids.triangleMesh), kNewMesh));
    out.push_back(std::make_unique<SetAsset<Mesh>>(ids.triangleMesh, editedMesh(start.meshes.at(ids.triangleMesh))));
    out.push_back(std::make_unique<SetPrimitiveMaterial>(ids.triangleMesh, 0, ids.red));
    Image image = start.images.at(ids.checkerImage);
    image.name = "copy";
    out.push_back(std::make_unique<AddAsset<Image>>(image, kNewImage));
    image.uri = "textures/renamed.png";
    out.push_back(std::make_unique<SetAsset<Image>>(ids.checkerImage, image));
    Sampler sampler;
    sampler.name = "nearest";
    sampler.magFilter = Filter::Nearest;
    out.push_back(std::make_unique<AddAsset<Sampler>>(sampler, kNewSampler));
    sampler.wrapS = Wrap::MirroredRepeat;
    out.push_back(std::make_unique<SetAsset<Sampler>>(ids.clamped, sampler));
    Texture texture{.name = "copy", .image = kNewImage, .sampler = kNewSampler};
    out.push_back(std::make_unique<AddAsset<Texture>>(texture, kNewTexture));
    out.push_back(std::make_unique<SetAsset<Texture>>(ids.checker, Texture{.name = "c", .image = ids.checkerImage}));
    out.push_back(std::make_unique<RemoveAsset<Texture>>(kNewTexture));
    out.push_back(std::make_unique<RemoveAsset<Image>>(kNewImage));
    out.push_back(std::make_unique<RemoveAsset<Sampler>>(kNewSampler));
    out.push_back(std::make_unique<RemoveAsset<Mesh>>(kNewMesh));
    out.push_back(std::make_unique<RemoveAsset<Material>>(kNewMaterial));
}

void addCameraCommands(std::vector<CommandPtr>& out, const SampleIds& ids) {
    CameraKey key;
    key.time = 1.5;
    key.position = {1.0, 2.0, 3.0};
    out.push_back(std::make_unique<AddCameraKey>(ids.camera, key)); // keys at 0, 1, 1.5, 2
    out.push_back(std::make_unique<MoveCameraKey>(ids.camera, 0, 2.5)); // 1, 1.5, 2, 2.5
    key.yfov = 0.5f;
    key.focusDistance = 4.0f;
    out.push_back(std::make_unique<EditCameraKey>(ids.camera, 1, key));
    out.push_back(std::make_unique<RemoveCameraKey>(ids.camera, 2));
    out.push_back(std::make_unique<SetCameraPathMode>(ids.camera, RotationInterpolation::Slerp, true));
}

// A node's transform keys: a new animation, a second key, then the animation removed.
void addAnimationCommands(std::vector<CommandPtr>& out, const Scene& start, const SampleIds& ids) {
    Transform local = start.at(ids.ball).local;
    Animation animation = withNodeKey({}, ids.ball, 0.0, local, Interpolation::Linear);
    out.push_back(std::make_unique<AddAsset<Animation>>(animation, kNewAnimation));
    local.translation.y += 1.0f;
    out.push_back(std::make_unique<SetAsset<Animation>>(kNewAnimation, withNodeKey(animation, ids.ball, 1.0, local, Interpolation::Linear)));
    out.push_back(std::make_unique<RemoveAsset<Animation>>(kNewAnimation));
}

void addDocumentCommands(std::vector<CommandPtr>& out, const Scene& start, const SampleIds& ids) {
    ProjectSettings settings = start.settings;
    settings.render.spp = 128;
    settings.render.exposure = 1.0f;
    settings.activeCamera = ids.topCamera;
    settings.fog = {.density = 0.05f, .color = {0.8f, 0.9f, 1.0f}, .anisotropy = 0.6f, .heightFalloff = 0.5f, .baseHeight = -2.0f};
    out.push_back(std::make_unique<SetProjectSettings>(settings));
    out.push_back(std::make_unique<RemoveNode>(ids.world));
    std::vector<CommandPtr> grouped;
    grouped.push_back(std::make_unique<RenameNode>(ids.camera, "shot camera"));
    grouped.push_back(std::make_unique<SetVisibility>(ids.topCamera, false));
    out.push_back(std::make_unique<MacroCommand>("Group edit", std::move(grouped)));
}

} // namespace

std::vector<CommandPtr> oneOfEachCommand(const SampleIds& ids) {
    const Scene start = sampleScene();
    std::vector<CommandPtr> out;
    addNodeCommands(out, ids);
    addAssetCommands(out, start, ids);
    addCameraCommands(out, ids);
    addAnimationCommands(out, start, ids);
    addDocumentCommands(out, start, ids);
    return out;
}

} // namespace glint::test
