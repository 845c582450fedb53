#include "feature_scene.h"

#include <glm/gtc/quaternion.hpp>

namespace glint::test {

std::vector<std::uint8_t> checkerPng()
{
    return {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
            0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d, 0x24, 0x00, 0x00, 0x00, 0x12, 0x49,
            0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x04, 0xa0, 0x24, 0xc3, 0x7f, 0x00, 0x6b, 0xa6,
            0x0b, 0xf5, 0x3e, 0xc5, 0xe9, 0x54, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
}

std::vector<std::uint8_t> bluePng()
{
    return {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
            0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00,
            0x0d, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x68, 0xf8, 0xff, 0x1f, 0x00, 0x04, 0x82, 0x02, 0x7f,
            0x38, 0x86, 0x48, 0x7c, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
}

namespace {

struct TextureIds {
    TextureId checker;
    TextureId blue;
};

TextureIds addTextures(Scene& scene)
{
    Image external{.name = "checker", .uri = "textures/checker.png", .mimeType = "image/png", .encoded = checkerPng(), .width = 2, .height = 2};
    Image embedded{.name = "blue", .uri = "", .mimeType = "image/png", .encoded = bluePng(), .width = 1, .height = 1};
    const ImageId checkerImage = scene.images.add(external);
    const ImageId blueImage = scene.images.add(embedded);
    Sampler sampler{.name = "clamped", .magFilter = Filter::Linear, .minFilter = Filter::LinearMipmapLinear,
                    .wrapS = Wrap::ClampToEdge, .wrapT = Wrap::MirroredRepeat};
    const SamplerId samplerId = scene.samplers.add(sampler);
    return {scene.textures.add({.name = "checker", .image = checkerImage, .sampler = samplerId}),
            scene.textures.add({.name = "blue", .image = blueImage})};
}

Material everyExtension(const TextureIds& t)
{
    Material m;
    m.name = "everything";
    m.baseColorFactor = {0.8f, 0.1f, 0.1f, 0.9f};
    m.baseColorTexture = {.texture = t.checker, .texCoord = 0};
    m.baseColorTexture.transform = {.offset = {0.5f, 0.25f}, .rotation = 0.1f, .scale = {2.0f, 3.0f}, .texCoord = 1};
    m.metallicFactor = 0.25f;
    m.roughnessFactor = 0.6f;
    m.metallicRoughnessTexture = {.texture = t.blue};
    m.normalTexture = {.texture = t.checker, .scale = 0.5f};
    m.occlusionTexture = {.texture = t.blue, .texCoord = 1, .scale = 0.8f};
    m.emissiveFactor = {1.0f, 0.5f, 0.25f};
    m.emissiveTexture = {.texture = t.blue};
    m.emissiveStrength = 4.0f;
    m.specularFactor = 0.5f;
    m.specularTexture = {.texture = t.checker};
    m.specularColorFactor = {0.9f, 0.8f, 0.7f};
    m.specularColorTexture = {.texture = t.blue};
    m.transmissionFactor = 0.9f;
    m.transmissionTexture = {.texture = t.checker};
    m.ior = 1.33f;
    m.thicknessFactor = 0.1f;
    m.thicknessTexture = {.texture = t.blue};
    m.attenuationDistance = 2.0f;
    m.attenuationColor = {0.9f, 0.95f, 1.0f};
    m.scatterColor = {0.8f, 0.7f, 0.6f};
    m.scatterAnisotropy = 0.4f;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.3f;
    m.unknown = {{"extensions", {{"EXT_glint_test_unknown", {{"kept", true}, {"value", 1.5}}}}}, {"extras", {{"note", "verbatim"}}}};
    return m;
}

// A unit quad in XY facing +Z with every attribute.
Mesh quadMesh(MaterialId material)
{
    Primitive p;
    p.positions = {{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}};
    p.normals.assign(4, {0.0f, 0.0f, 1.0f});
    p.tangents.assign(4, {1.0f, 0.0f, 0.0f, 1.0f});
    p.uv0 = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    p.uv1 = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.5f, 0.5f}, {0.0f, 0.5f}};
    p.colors = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f, 1.0f}, {1.0f, 1.0f, 1.0f, 0.5f}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    p.unknown = {{"extras", {{"primitiveNote", 7}}}};
    return {.name = "quad", .primitives = {p}, .unknown = {{"extras", {{"meshNote", "m"}}}}};
}

Node node(std::string name, Component component, Transform local = {})
{
    Node n;
    n.name = std::move(name);
    n.component = std::move(component);
    n.local = local;
    return n;
}

Camera pathCamera()
{
    Camera camera;
    camera.yfov = 0.8f;
    camera.aspectRatio = 16.0f / 9.0f;
    camera.znear = 0.05f;
    camera.zfar = 100.0f;
    camera.lensRadius = 0.01f;
    camera.focusDistance = 3.5f;
    camera.exposure = -0.5f;
    camera.path.rotation = RotationInterpolation::Squad;
    const glm::dquat turned = glm::angleAxis(0.5, glm::dvec3(0.0, 1.0, 0.0));
    camera.path.keys = {
        {.time = 0.0, .position = {0.0, 1.0, 5.0}, .orientation = {1.0, 0.0, 0.0, 0.0}, .yfov = 0.8f, .focusDistance = 3.5f, .lensRadius = 0.01f},
        {.time = 0.5, .position = {1.0, 1.2, 4.0}, .orientation = turned, .yfov = 0.7f, .focusDistance = 3.0f, .lensRadius = 0.02f},
        {.time = 1.0, .position = {2.0, 1.0, 3.0}, .orientation = turned * turned, .yfov = 0.6f, .focusDistance = 2.5f, .lensRadius = 0.0f},
    };
    return camera;
}

void addLights(Scene& scene, NodeId parent)
{
    Light sun{.type = LightType::Sun, .color = {1.0f, 0.95f, 0.9f}, .intensity = 3.0f, .angularDiameter = 0.00935f};
    Light point{.type = LightType::Point, .color = {1.0f, 0.5f, 0.2f}, .intensity = 100.0f, .range = 20.0f, .radius = 0.1f};
    Light spot{.type = LightType::Spot, .intensity = 50.0f, .innerConeAngle = 0.2f, .outerConeAngle = 0.5f};
    scene.addNode(node("sun", sun, {.rotation = glm::angleAxis(-1.0f, glm::vec3(1.0f, 0.0f, 0.0f))}), parent);
    scene.addNode(node("point", point, {.translation = {1.0f, 3.0f, 0.0f}}), parent);
    scene.addNode(node("spot", spot, {.translation = {-1.0f, 3.0f, 0.0f}}), parent);
}

NodeId addShapes(Scene& scene, NodeId parent, MaterialId material)
{
    const NodeId sphere = scene.addNode(node("ball", Shape{.kind = ShapeKind::Sphere, .radius = 0.25f, .material = material},
                                            {.translation = {0.0f, 0.25f, 0.0f}}), parent);
    scene.addNode(node("crate", Shape{.kind = ShapeKind::Box, .size = {1.0f, 0.5f, 2.0f}}, {.translation = {2.0f, 0.25f, 0.0f}}), parent);
    scene.addNode(node("floor", Shape{.kind = ShapeKind::GroundPlane, .material = material}), parent);
    return sphere;
}

void addAnimations(Scene& scene, NodeId target)
{
    Animation a;
    a.name = "move";
    a.channels.push_back({.node = target, .path = AnimationPath::Translation, .interpolation = Interpolation::Linear,
                          .times = {0.0f, 1.0f, 2.0f}, .values = {0, 0, 0, 1, 0, 0, 1, 1, 0}});
    const glm::quat r = glm::angleAxis(0.3f, glm::vec3(0.0f, 0.0f, 1.0f));
    a.channels.push_back({.node = target, .path = AnimationPath::Rotation, .interpolation = Interpolation::Step,
                          .times = {0.0f, 1.5f}, .values = {0, 0, 0, 1, r.x, r.y, r.z, r.w}});
    a.channels.push_back({.node = target, .path = AnimationPath::Scale, .interpolation = Interpolation::CubicSpline,
                          .times = {0.0f, 2.0f}, .values = {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0}});
    a.unknown = {{"extras", {{"take", 3}}}};
    scene.animations.add(a);
}

void addSettings(Scene& scene, NodeId camera)
{
    ProjectSettings& s = scene.settings;
    s.activeCamera = camera;
    s.timeline.fpsNumerator = 30;
    s.render.spp = 16;
    s.render.exposure = 0.1f;
    s.environment.file = "studio.hdr";
    s.environment.intensity = 0.7f;
    s.environment.rotationDegrees = 90.0f;
    s.fog = {.density = 0.02f, .color = {0.9f, 0.9f, 1.0f}, .anisotropy = 0.5f, .heightFalloff = 0.1f, .baseHeight = -1.0f};
    s.output.path = "frames/shot_####.exr";
    s.lightUnits = LightUnits::Raw;
}

} // namespace

Scene featureScene()
{
    Scene scene;
    scene.name = "features";
    const TextureIds textures = addTextures(scene);
    const MaterialId rich = scene.materials.add(everyExtension(textures));
    const MaterialId plain = scene.materials.add({.name = "glass", .baseColorFactor = {1, 1, 1, 0.4f}, .alphaMode = AlphaMode::Blend, .doubleSided = true});
    const MeshId quad = scene.meshes.add(quadMesh(rich));

    const NodeId root = scene.addNode(node("root", std::monostate{}, {.scale = {2.0f, 2.0f, 2.0f}}));
    const NodeId quadNode = scene.addNode(node("quad", MeshInstance{quad}, {.translation = {0.0f, 1.0f, -2.0f}}), root);
    addShapes(scene, root, plain);
    addLights(scene, root);
    const NodeId camera = scene.addNode(node("shot", pathCamera()));
    Camera ortho{.projection = Projection::Orthographic, .znear = 0.1f, .zfar = 50.0f, .xmag = 2.0f, .ymag = 1.5f};
    scene.addNode(node("top", ortho, {.translation = {0.0f, 10.0f, 0.0f}}));
    Camera unbounded = ortho;
    unbounded.zfar = 0.0f; // sees without limit: glTF still needs zfar > znear
    scene.addNode(node("plan", unbounded, {.translation = {0.0f, 20.0f, 0.0f}}));
    Node hidden = node("hidden", MeshInstance{quad});
    hidden.visible = false;
    hidden.unknown = {{"extensions", {{"EXT_glint_test_node", {{"payload", {1, 2, 3}}}}}}, {"extras", {{"tag", "keep me"}}}};
    scene.addNode(hidden, root);
    addAnimations(scene, quadNode);
    addSettings(scene, camera);

    scene.unknown = {{"asset", {{"copyright", "generated for Glint's tests"}}}, {"extras", {{"sceneNote", 0.1}}}};
    scene.unsupported.push_back({"source.gltf", "skin-dropped", "skin 0 (armature) loaded as static geometry"});
    return scene;
}

Scene largeScene(int gridSize, int variant)
{
    Scene scene = featureScene();
    Primitive p;
    const int side = gridSize + 1;
    for (int z = 0; z < side; ++z)
        for (int x = 0; x < side; ++x) {
            const float height = 0.01f * static_cast<float>((x * 7 + z * 13 + variant * 5) % 17);
            p.positions.push_back({static_cast<float>(x), height, static_cast<float>(z)});
            p.normals.push_back({0.0f, 1.0f, 0.0f});
            p.uv0.push_back({static_cast<float>(x) / static_cast<float>(gridSize), static_cast<float>(z) / static_cast<float>(gridSize)});
        }
    for (int z = 0; z < gridSize; ++z)
        for (int x = 0; x < gridSize; ++x) {
            const auto i = static_cast<std::uint32_t>(z * side + x);
            const auto s = static_cast<std::uint32_t>(side);
            p.indices.insert(p.indices.end(), {i, i + s, i + 1, i + 1, i + s, i + s + 1});
        }
    const MeshId grid = scene.meshes.add({.name = "grid", .primitives = {p}});
    scene.addNode(node("terrain", MeshInstance{grid}));
    scene.settings.render.seed = static_cast<std::uint32_t>(variant);
    scene.name = "variant " + std::to_string(variant);
    return scene;
}

} // namespace glint::test
