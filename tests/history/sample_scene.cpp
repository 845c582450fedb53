#include "sample_scene.h"

#include <glm/gtc/quaternion.hpp>

namespace glint::test {
namespace {

Node node(const std::string& name, Component component = {}, glm::vec3 translation = {}) {
    Node n;
    n.name = name;
    n.component = std::move(component);
    n.local.translation = translation;
    return n;
}

Mesh triangleMesh(MaterialId material) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals.assign(3, {0, 0, 1});
    p.uv0 = {{0, 0}, {1, 0}, {0, 1}};
    p.indices = {0, 1, 2};
    p.material = material;
    Mesh mesh;
    mesh.name = "triangle";
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

Camera cameraWithPath() {
    Camera camera;
    for (int i = 0; i < 3; ++i) {
        CameraKey key;
        key.time = i;
        key.position = {i * 2.0, 1.0, 5.0};
        key.orientation = glm::angleAxis(0.2 * i, glm::dvec3(0, 1, 0));
        camera.path.keys.push_back(key);
    }
    return camera;
}

} // namespace

std::vector<std::uint8_t> tinyPng() {
    return {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
            0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00,
            0x0d, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x68, 0xf8, 0xff, 0x1f, 0x00, 0x04, 0x82, 0x02, 0x7f,
            0x38, 0x86, 0x48, 0x7c, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
}

Scene sampleScene(SampleIds* out) {
    Scene scene;
    SampleIds ids;
    scene.name = "sample";

    Image image;
    image.name = "checker";
    image.mimeType = "image/png";
    image.encoded = tinyPng();
    image.width = image.height = 1;
    ids.checkerImage = scene.images.add(image);
    Sampler sampler;
    sampler.name = "clamped";
    sampler.wrapS = sampler.wrapT = Wrap::ClampToEdge;
    ids.clamped = scene.samplers.add(sampler);
    Texture texture;
    texture.name = "checker";
    texture.image = ids.checkerImage;
    texture.sampler = ids.clamped;
    ids.checker = scene.textures.add(texture);

    Material red;
    red.name = "red";
    red.baseColorFactor = {0.8f, 0.1f, 0.1f, 1.0f};
    red.metallicFactor = 0.0f;
    ids.red = scene.materials.add(red);
    Material glass;
    glass.name = "glass";
    glass.transmissionFactor = 1.0f;
    glass.roughnessFactor = 0.0f;
    ids.glass = scene.materials.add(glass);
    Material textured;
    textured.name = "textured";
    textured.baseColorTexture.texture = ids.checker;
    ids.textured = scene.materials.add(textured);
    ids.triangleMesh = scene.meshes.add(triangleMesh(ids.textured));

    ids.world = scene.addNode(node("world"));
    ids.floor = scene.addNode(node("floor", Shape{.kind = ShapeKind::GroundPlane, .material = ids.red}), ids.world);
    ids.ball = scene.addNode(node("ball", Shape{.kind = ShapeKind::Sphere, .material = ids.glass}, {0, 1, 0}), ids.world);
    ids.triangle = scene.addNode(node("triangle", MeshInstance{ids.triangleMesh}, {2, 0, 0}), ids.world);
    ids.lamp = scene.addNode(node("lamp", Light{.type = LightType::Point, .intensity = 50.0f}, {0, 2, 0}), ids.ball);
    ids.sun = scene.addNode(node("sun", Light{.type = LightType::Sun, .intensity = 3.0f}));
    ids.camera = scene.addNode(node("camera", cameraWithPath(), {0, 1, 5}));
    ids.topCamera = scene.addNode(node("top", Camera{.projection = Projection::Orthographic}, {0, 10, 0}));
    scene.settings.activeCamera = ids.camera;
    if (out) *out = ids;
    return scene;
}

} // namespace glint::test
