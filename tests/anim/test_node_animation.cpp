// glTF node animations sampled at and between keys, with hand-computed answers for STEP, LINEAR
// (slerp, shortest arc) and CUBICSPLINE (tangents scaled by the key interval).
#include "scene/anim/channel_sampling.h"
#include "scene/anim/node_animation.h"

#include <QtTest>

#include <glm/gtc/constants.hpp>

using namespace glint;

namespace {

AnimationChannel channel(AnimationPath path, Interpolation interpolation, std::vector<float> times,
                         std::vector<float> values, NodeId node = NodeId{1}) {
    return {node, path, interpolation, std::move(times), std::move(values)};
}

glm::quat aboutZ(float radians) { return glm::angleAxis(radians, glm::vec3(0, 0, 1)); }

// The same rotation: q and -q are equal rotations.
bool sameRotation(const glm::quat& a, const glm::quat& b) { return std::abs(glm::dot(a, b)) > 1.0f - 1e-6f; }

bool near(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-6f; }

} // namespace

class TestNodeAnimation : public QObject {
    Q_OBJECT
private slots:
    void linearTranslationBetweenAndOutsideKeys() {
        const auto c = channel(AnimationPath::Translation, Interpolation::Linear, {1, 3}, {0, 0, 0, 2, 4, 6});
        QVERIFY(near(sampleVec3Channel(c, 2.0), {1, 2, 3}));
        QVERIFY(near(sampleVec3Channel(c, 1.5), {0.5f, 1, 1.5f}));
        QVERIFY(near(sampleVec3Channel(c, 3.0), {2, 4, 6}));
        QVERIFY(near(sampleVec3Channel(c, -10.0), {0, 0, 0})); // clamped before the first key
        QVERIFY(near(sampleVec3Channel(c, 10.0), {2, 4, 6}));  // and after the last
    }

    void stepHoldsThePreviousKey() {
        const auto c = channel(AnimationPath::Scale, Interpolation::Step, {0, 1, 2}, {1, 1, 1, 2, 2, 2, 3, 3, 3});
        QVERIFY(near(sampleVec3Channel(c, 0.99), {1, 1, 1}));
        QVERIFY(near(sampleVec3Channel(c, 1.0), {2, 2, 2}));
        QVERIFY(near(sampleVec3Channel(c, 1.5), {2, 2, 2}));
        QVERIFY(near(sampleVec3Channel(c, 7.0), {3, 3, 3}));
    }

    void linearRotationIsSlerp() {
        const glm::quat q1 = aboutZ(glm::half_pi<float>());
        const auto c = channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1}, {0, 0, 0, 1, q1.x, q1.y, q1.z, q1.w});
        QVERIFY(sameRotation(sampleRotationChannel(c, 0.5), aboutZ(glm::quarter_pi<float>())));
        QVERIFY(sameRotation(sampleRotationChannel(c, 0.25), aboutZ(glm::pi<float>() / 8)));
        QVERIFY(sameRotation(sampleRotationChannel(c, 1.0), q1));
    }

    // Keys stored as q and -q, or as a 270-degree turn: slerp takes the short way.
    void linearRotationTakesTheShortestArc() {
        const glm::quat q1 = -aboutZ(glm::half_pi<float>());
        const auto flipped =
            channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1}, {0, 0, 0, 1, q1.x, q1.y, q1.z, q1.w});
        QVERIFY(sameRotation(sampleRotationChannel(flipped, 0.5), aboutZ(glm::quarter_pi<float>())));
        const glm::quat q270 = aboutZ(1.5f * glm::pi<float>());
        const auto longWay =
            channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1}, {0, 0, 0, 1, q270.x, q270.y, q270.z, q270.w});
        QVERIFY(sameRotation(sampleRotationChannel(longWay, 0.5), aboutZ(-glm::quarter_pi<float>())));
    }

    // Keys at t = 1 and 3 (interval 2): v0 = 0, out-tangent b0 = (1, 0, 0); v1 = (1, 2, 0),
    // in-tangent a1 = (0, 4, 0). p(u) = h00 v0 + h10 * 2 * b0 + h01 v1 + h11 * 2 * a1.
    void cubicSplineFollowsTheSpecFormula() {
        const auto c = channel(AnimationPath::Translation, Interpolation::CubicSpline, {1, 3},
                               {9, 9, 9, 0, 0, 0, 1, 0, 0, /* key 1 */ 0, 4, 0, 1, 2, 0, 9, 9, 9});
        QVERIFY(near(sampleVec3Channel(c, 1.0), {0, 0, 0}));
        QVERIFY(near(sampleVec3Channel(c, 3.0), {1, 2, 0}));
        QVERIFY(near(sampleVec3Channel(c, 2.0), {0.75f, 0, 0}));          // u = 1/2
        QVERIFY(near(sampleVec3Channel(c, 1.5), {0.4375f, -0.0625f, 0})); // u = 1/4
        QVERIFY(near(sampleVec3Channel(c, 0.0), {0, 0, 0}));
        QVERIFY(near(sampleVec3Channel(c, 4.0), {1, 2, 0}));
    }

    // With zero tangents the spline at u = 1/2 is the normalised mean of the keys: a half turn.
    void cubicSplineRotationIsNormalised() {
        const glm::quat q1 = aboutZ(glm::half_pi<float>());
        const auto c = channel(AnimationPath::Rotation, Interpolation::CubicSpline, {0, 2},
                               {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, /* key 1 */ 0, 0, 0, 0, q1.x, q1.y, q1.z, q1.w,
                                0, 0, 0, 0});
        const glm::quat mid = sampleRotationChannel(c, 1.0);
        QVERIFY(std::abs(glm::length(mid) - 1.0f) < 1e-6f);
        QVERIFY(sameRotation(mid, aboutZ(glm::quarter_pi<float>())));
    }

    void malformedChannelsAreRecognised() {
        QVERIFY(isWellFormed(channel(AnimationPath::Translation, Interpolation::Linear, {0, 1}, {0, 0, 0, 1, 1, 1})));
        QVERIFY(!isWellFormed(channel(AnimationPath::Translation, Interpolation::Linear, {0, 1}, {0, 0, 0})));
        QVERIFY(!isWellFormed(channel(AnimationPath::Rotation, Interpolation::CubicSpline, {0}, {0, 0, 0, 1})));
        QVERIFY(!isWellFormed(channel(AnimationPath::Translation, Interpolation::Linear, {}, {})));
        QVERIFY(!isWellFormed(channel(AnimationPath::Translation, Interpolation::Linear, {1, 1}, {0, 0, 0, 1, 1, 1})));
        QVERIFY(!isWellFormed(channel(AnimationPath::Translation, Interpolation::Step, {2, 1}, {0, 0, 0, 1, 1, 1})));
    }

    void timeSpansUniteChannelsAndAnimations() {
        Animation a;
        a.channels = {channel(AnimationPath::Translation, Interpolation::Linear, {0.5f, 2}, {0, 0, 0, 1, 1, 1}),
                      channel(AnimationPath::Scale, Interpolation::Step, {1, 3}, {1, 1, 1, 2, 2, 2})};
        QCOMPARE(animationTimeSpan(a), std::make_pair(0.5, 3.0));
        QCOMPARE(animationTimeSpan(Animation{}), std::make_pair(0.0, 0.0));
        Scene scene;
        QCOMPARE(sceneAnimationTimeSpan(scene), std::make_pair(0.0, 0.0));
        scene.animations.add(a);
        Animation later;
        later.bakedCameraPath = true;
        later.channels = {channel(AnimationPath::Translation, Interpolation::Linear, {2, 5}, {0, 0, 0, 1, 1, 1})};
        scene.animations.add(later);
        scene.animations.add(Animation{}); // no keys: does not pull the span to 0
        QCOMPARE(sceneAnimationTimeSpan(scene), std::make_pair(0.5, 5.0));
    }

    void sceneSamplingReplacesOnlyAnimatedPaths() {
        Scene scene;
        Node moving;
        moving.local.scale = glm::vec3(2.0f);
        const NodeId movingId = scene.addNode(moving);
        const NodeId still = scene.addNode(Node{});
        Animation a;
        a.channels = {channel(AnimationPath::Translation, Interpolation::Linear, {0, 1}, {0, 0, 0, 4, 0, 0}, movingId)};
        scene.animations.add(a);
        const Transform atHalf = sampleLocalTransform(scene, movingId, 0.5);
        QVERIFY(near(atHalf.translation, {2, 0, 0}));
        QCOMPARE(atHalf.scale, glm::vec3(2.0f)); // not animated: the stored value stays
        QCOMPARE(sampleLocalTransform(scene, still, 0.5), scene.at(still).local);
        const auto all = sampleAnimatedTransforms(scene, 0.25);
        QCOMPARE(all.size(), std::size_t(1));
        QVERIFY(near(all.at(movingId).translation, {1, 0, 0}));
        QCOMPARE(scene.at(movingId).local.translation, glm::vec3(0.0f)); // the scene is untouched
    }

    // A camera with a path follows the exact path; a baked track of it is ignored, and the path
    // counts towards the scene's time span.
    void cameraPathDrivesItsNode() {
        Scene scene;
        Node cameraNode;
        Camera camera;
        CameraKey first, second;
        first.time = 1.0;
        second.time = 6.0;
        second.position = {10, 0, 0};
        camera.path.keys = {first, second};
        cameraNode.component = camera;
        const NodeId id = scene.addNode(cameraNode);
        Animation staleBake;
        staleBake.bakedCameraPath = true;
        staleBake.channels = {channel(AnimationPath::Translation, Interpolation::Linear, {0, 1}, {5, 5, 5, 5, 5, 5}, id)};
        scene.animations.add(staleBake);
        QVERIFY(near(sampleLocalTransform(scene, id, 3.5).translation, {5, 0, 0}));
        QCOMPARE(sceneAnimationTimeSpan(scene), std::make_pair(0.0, 6.0));
        const auto all = sampleAnimatedTransforms(scene, 6.0);
        QCOMPARE(all.size(), std::size_t(1));
        QVERIFY(near(all.at(id).translation, {10, 0, 0}));

        // Paths are in world space: under a parent moved by (0, 3, 0) the local transform compensates.
        Node parent;
        parent.local.translation = {0, 3, 0};
        scene.setParent(id, scene.addNode(parent));
        QVERIFY(near(sampleLocalTransform(scene, id, 3.5).translation, {5, -3, 0}));
    }
};

QTEST_APPLESS_MAIN(TestNodeAnimation)
#include "test_node_animation.moc"
