// Click picking through the CPU BVH: meshes, analytic shapes, the ground plane, hidden nodes,
// nearest hit wins, and rays through the view camera's pixels.
#include "editor/viewport/scene_picker.h"
#include "editor/viewport/view_camera.h"

#include <QtTest>

using namespace glint;
using namespace glint::editor;

namespace {

NodeId addShape(Scene& scene, const char* name, ShapeKind kind, glm::vec3 at) {
    Node node;
    node.name = name;
    node.local.translation = at;
    Shape shape;
    shape.kind = kind;
    node.component = shape;
    return scene.addNode(std::move(node));
}

// A unit quad mesh (two triangles) in the XY plane, facing +Z.
NodeId addQuadMesh(Scene& scene, glm::vec3 at) {
    Mesh mesh;
    Primitive p;
    p.positions = {{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}};
    p.indices = {0, 1, 2, 0, 2, 3};
    mesh.primitives.push_back(p);
    const MeshId id = scene.meshes.add(std::move(mesh));
    Node node;
    node.name = "quad";
    node.local.translation = at;
    node.component = MeshInstance{id};
    return scene.addNode(std::move(node));
}

bvh::Ray down(float x, float z) { return {{x, 10.0f, z}, {0.0f, -1.0f, 0.0f}}; }

} // namespace

class TestViewportPick : public QObject {
    Q_OBJECT
private slots:
    void picksShapesMeshesAndGround() {
        Scene scene;
        const NodeId sphere = addShape(scene, "sphere", ShapeKind::Sphere, {-2, 0.5f, 0});
        const NodeId box = addShape(scene, "box", ShapeKind::Box, {2, 0.5f, 0});
        const NodeId ground = addShape(scene, "ground", ShapeKind::GroundPlane, {0, 0, 0});
        const NodeId quad = addQuadMesh(scene, {0, 0.5f, -3});
        const ScenePicker picker(scene);
        QCOMPARE(picker.pick(down(-2, 0)).node, sphere);
        QVERIFY(std::abs(picker.pick(down(-2, 0)).t - 9.0f) < 1e-4f);
        QCOMPARE(picker.pick(down(2.4f, 0.4f)).node, box);
        QCOMPARE(picker.pick(down(0, 0)).node, ground);
        QCOMPARE(picker.pick({{0, 0.5f, 5}, {0, 0, -1}}).node, quad);
        QCOMPARE(picker.pick({{0, 0.5f, 5}, {0, 0, 1}}).node, NodeId{});
    }

    void nearestHitWins() {
        Scene scene;
        const NodeId front = addShape(scene, "front", ShapeKind::Sphere, {0, 0, 2});
        addShape(scene, "back", ShapeKind::Sphere, {0, 0, -2});
        const ScenePicker picker(scene);
        QCOMPARE(picker.pick({{0, 0, 10}, {0, 0, -1}}).node, front);
    }

    void hiddenNodesAreNotPicked() {
        Scene scene;
        addShape(scene, "hidden", ShapeKind::Sphere, {0, 0, 0});
        scene.setVisible(scene.roots().front(), false);
        const ScenePicker picker(scene);
        QCOMPARE(picker.pick({{0, 0, 10}, {0, 0, -1}}).node, NodeId{});
    }

    void childOfATransformedParent() {
        Scene scene;
        Node parent;
        parent.name = "parent";
        parent.local.translation = {5, 0, 0};
        parent.local.scale = glm::vec3(2.0f);
        const NodeId p = scene.addNode(parent);
        Node child;
        child.name = "child";
        child.local.translation = {1, 0, 0}; // world x = 7, radius 1 after the parent's scale
        child.component = Shape{};
        const NodeId c = scene.addNode(child, p);
        const ScenePicker picker(scene);
        QCOMPARE(picker.pick(down(7.9f, 0)).node, c);
        QCOMPARE(picker.pick(down(8.1f, 0)).node, NodeId{});
        const bvh::Aabb bounds = picker.worldBounds(c);
        QVERIFY(std::abs(bounds.lo.x - 6.0f) < 1e-5f && std::abs(bounds.hi.x - 8.0f) < 1e-5f);
    }

    void pickThroughTheViewCamera() {
        Scene scene;
        const NodeId left = addShape(scene, "left", ShapeKind::Sphere, {-1.5f, 0, 0});
        const NodeId right = addShape(scene, "right", ShapeKind::Cylinder, {1.5f, 0, 0});
        const ScenePicker picker(scene);
        ViewCamera camera; // on +Z at 5 m, looking at the origin
        const int w = 128, h = 64;
        const glm::dvec3 l = projectToPixels(camera, {-1.5, 0, 0}, w, h);
        const glm::dvec3 r = projectToPixels(camera, {1.5, 0, 0}, w, h);
        QCOMPARE(picker.pick(pixelRay(camera, l.x, l.y, w, h)).node, left);
        QCOMPARE(picker.pick(pixelRay(camera, r.x, r.y, w, h)).node, right);
        QCOMPARE(picker.pick(pixelRay(camera, w / 2.0, 2.0, w, h)).node, NodeId{});
    }
};

QTEST_APPLESS_MAIN(TestViewportPick)
#include "test_viewport_pick.moc"
