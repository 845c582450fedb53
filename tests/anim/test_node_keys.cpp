// Keyframing a node's transform (scene/anim/node_keys.h): keys at two times interpolate between
// them when the scene is posed (exact for linear: the midpoint at half time); a key at the same
// time replaces; keys move and go away on all paths together; a cubic track passes through its keys
// with Catmull-Rom tangents; rotations take the short way even when a key's quaternion is negated.
#include "scene/anim/node_keys.h"
#include "scene/anim/node_animation.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

using namespace glint;

namespace {

Transform at(glm::vec3 t, float degreesY = 0.0f) {
    Transform x;
    x.translation = t;
    x.rotation = glm::angleAxis(glm::radians(degreesY), glm::vec3(0.0f, 1.0f, 0.0f));
    return x;
}

Scene withAnimation(Animation animation, NodeId& node) {
    Scene scene;
    Node n;
    n.name = "box";
    node = scene.addNode(n);
    scene.animations.add(std::move(animation));
    return scene;
}

} // namespace

class TestNodeKeys : public QObject {
    Q_OBJECT
private slots:
    void twoKeysInterpolate() {
        const NodeId node{1};
        Animation a = withNodeKey({}, node, 0.0, at({0, 0, 0}), Interpolation::Linear);
        a = withNodeKey(a, node, 2.0, at({4, 2, 0}, 90.0f), Interpolation::Linear);
        QCOMPARE(a.channels.size(), std::size_t(3)); // translation, rotation, scale
        QCOMPARE(nodeKeyTimes(a, node), (std::vector<double>{0.0, 2.0}));
        NodeId id;
        const Scene scene = withAnimation(a, id);
        QCOMPARE(id, node);
        const Transform mid = sampleLocalTransform(scene, node, 1.0);
        QCOMPARE(mid.translation, glm::vec3(2, 1, 0));
        const float angle = glm::degrees(glm::angle(mid.rotation));
        QVERIFY2(std::abs(angle - 45.0f) < 1e-3f, qPrintable(QString::number(angle)));
        QCOMPARE(sampleLocalTransform(scene, node, 5.0).translation, glm::vec3(4, 2, 0)); // held after the last key
    }

    void sameTimeReplacesAndKeysMoveTogether() {
        const NodeId node{1};
        Animation a = withNodeKey({}, node, 1.0, at({1, 0, 0}), Interpolation::Linear);
        a = withNodeKey(a, node, 1.0, at({3, 0, 0}), Interpolation::Linear);
        QCOMPARE(nodeKeyTimes(a, node), std::vector<double>{1.0});
        QCOMPARE(a.channels[0].values, (std::vector<float>{3, 0, 0}));
        a = withNodeKey(a, node, 2.0, at({5, 0, 0}), Interpolation::Linear);
        a = withNodeKeyMoved(a, node, 1.0, 3.0);
        QCOMPARE(nodeKeyTimes(a, node), (std::vector<double>{2.0, 3.0}));
        QCOMPARE(a.channels[0].values, (std::vector<float>{5, 0, 0, 3, 0, 0})); // sorted by time
        a = withoutNodeKey(a, node, 2.0);
        QCOMPARE(nodeKeyTimes(a, node), std::vector<double>{3.0});
        a = withoutNodeKey(a, node, 3.0);
        QVERIFY(a.channels.empty()); // channels without keys go
    }

    void otherNodesAreLeftAlone() {
        Animation a = withNodeKey({}, NodeId{1}, 0.0, at({1, 0, 0}), Interpolation::Linear);
        a = withNodeKey(a, NodeId{2}, 0.5, at({2, 0, 0}), Interpolation::Step);
        a = withoutNodeKey(a, NodeId{1}, 0.0);
        QCOMPARE(nodeKeyTimes(a, NodeId{2}), std::vector<double>{0.5});
        QCOMPARE(nodeKeyInterpolation(a, NodeId{2}), Interpolation::Step);
    }

    // Cubic: (in-tangent, value, out-tangent) per key, Catmull-Rom inside, zero at the ends; the
    // curve passes through every key.
    void cubicTrackPassesThroughItsKeys() {
        const NodeId node{1};
        Animation a;
        for (int i = 0; i < 4; ++i) a = withNodeKey(a, node, double(i), at({float(i * i), 0, 0}), Interpolation::Linear);
        a = withNodeInterpolation(a, node, Interpolation::CubicSpline);
        const AnimationChannel& t = a.channels[0];
        QCOMPARE(t.interpolation, Interpolation::CubicSpline);
        QCOMPARE(t.values.size(), std::size_t(4 * 9));
        QCOMPARE(t.values[9 + 0], 2.0f); // key 1's in-tangent: (4 - 0) / 2 s
        NodeId id;
        const Scene scene = withAnimation(a, id);
        for (int i = 0; i < 4; ++i) QCOMPARE(sampleLocalTransform(scene, node, double(i)).translation.x, float(i * i));
        a = withNodeInterpolation(a, node, Interpolation::Linear); // and back, values intact
        QCOMPARE(a.channels[0].values, (std::vector<float>{0, 0, 0, 1, 0, 0, 4, 0, 0, 9, 0, 0}));
    }

    void rotationsTakeTheShortWay() {
        const NodeId node{1};
        Transform first = at({0, 0, 0}, 10.0f), second = at({0, 0, 0}, 20.0f);
        second.rotation = -second.rotation; // the same orientation, the other hemisphere
        Animation a = withNodeKey({}, node, 0.0, first, Interpolation::Linear);
        a = withNodeKey(a, node, 1.0, second, Interpolation::Linear);
        NodeId id;
        const Scene scene = withAnimation(a, id);
        const float angle = glm::degrees(glm::angle(sampleLocalTransform(scene, node, 0.5).rotation));
        QVERIFY2(std::abs(angle - 15.0f) < 1e-3f, qPrintable(QString::number(angle)));
    }
};

QTEST_APPLESS_MAIN(TestNodeKeys)
#include "test_node_keys.moc"
