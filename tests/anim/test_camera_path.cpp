// Camera paths: exact at keys, C1 in time (position and, with squad, rotation), non-uniform
// Catmull-Rom tangents, constant speed within 1 %, and a baked LINEAR track equal to the curve.
#include "scene/anim/camera_path_sampling.h"

#include <QtTest>

#include <glm/gtc/constants.hpp>

using namespace glint;

namespace {

CameraKey key(double time, glm::dvec3 position, double angle, glm::dvec3 axis, float yfov = 0.7f,
              float lensRadius = 0.0f) {
    CameraKey k;
    k.time = time;
    k.position = position;
    k.orientation = glm::angleAxis(angle, glm::normalize(axis));
    k.yfov = yfov;
    k.focusDistance = float(2.0 + time);
    k.lensRadius = lensRadius;
    return k;
}

// Five keys, unevenly spaced in time, turning about changing axes.
CameraPath winding(RotationInterpolation rotation = RotationInterpolation::Squad, bool constantSpeed = false) {
    CameraPath path;
    path.keys = {key(0.0, {0, 0, 0}, 0.0, {0, 1, 0}, 0.7f),        key(0.7, {1, 2, 0}, 0.6, {0, 1, 0}, 0.9f),
                 key(2.0, {3, 2, 1}, 1.2, {1, 1, 0}, 0.5f, 0.02f), key(2.5, {4, 0, 2}, -0.4, {0, 0, 1}, 0.6f),
                 key(4.0, {6, 1, 0}, 2.0, {1, 0, 1}, 0.8f)};
    path.rotation = rotation;
    path.constantSpeed = constantSpeed;
    return path;
}

glm::dvec3 positionAt(const CameraPath& path, double t) { return sampleCameraPath(path, t).position; }

bool sameRotation(const glm::dquat& a, const glm::dquat& b, double tolerance) {
    return std::abs(glm::dot(a, b)) > 1.0 - tolerance;
}

// Angular velocity (rad/s, in the frame of `from`) of the rotation from `from` to `to` over dt.
glm::dvec3 angularVelocity(const glm::dquat& from, const glm::dquat& to, double dt) {
    glm::dquat delta = glm::inverse(from) * to;
    if (delta.w < 0.0) delta = -delta;
    const glm::dvec3 v(delta.x, delta.y, delta.z);
    const double sinHalf = glm::length(v); // not glm::axis: 1 - w^2 cancels badly for tiny turns
    return sinHalf > 0.0 ? v * (2.0 * std::atan2(sinHalf, delta.w) / sinHalf / dt) : glm::dvec3(0.0);
}

// |right - left| one-sided difference quotients of position at time t.
double positionKink(const CameraPath& path, double t, double h) {
    const glm::dvec3 here = positionAt(path, t);
    return glm::length((positionAt(path, t + h) - here) / h - (here - positionAt(path, t - h)) / h);
}

double rotationKink(const CameraPath& path, double t, double h) {
    const glm::dquat before = sampleCameraPath(path, t - h).orientation, here = sampleCameraPath(path, t).orientation,
                     after = sampleCameraPath(path, t + h).orientation;
    return glm::length(angularVelocity(here, after, h) - angularVelocity(before, here, h));
}

} // namespace

class TestCameraPath : public QObject {
    Q_OBJECT
private slots:
    void exactAtKeys() {
        for (RotationInterpolation mode : {RotationInterpolation::Squad, RotationInterpolation::Slerp}) {
            const CameraPath path = winding(mode);
            for (const CameraKey& k : path.keys) {
                const CameraKey s = sampleCameraPath(path, k.time);
                QVERIFY(glm::length(s.position - k.position) < 1e-12);
                QVERIFY(sameRotation(s.orientation, k.orientation, 1e-12));
                QCOMPARE(s.yfov, k.yfov);
                QCOMPARE(s.focusDistance, k.focusDistance);
                QCOMPARE(s.lensRadius, k.lensRadius);
                QCOMPARE(s.time, k.time);
            }
        }
    }

    void clampsOutsideTheKeys() {
        const CameraPath path = winding();
        QCOMPARE(sampleCameraPath(path, -5.0).position, path.keys.front().position);
        QCOMPARE(sampleCameraPath(path, -5.0).time, 0.0);
        QCOMPARE(sampleCameraPath(path, 99.0).position, path.keys.back().position);
    }

    // Keys at t = 0, 1, 3 with x = 0, 1, 5: secant slopes 1 and 2, so the middle tangent is
    // (1 * 2 + 2 * 1) / 3 = 4/3 and the one-sided end tangents are 1 and 2.
    void tangentsAreNonUniformCatmullRom() {
        CameraPath path;
        path.keys = {key(0, {0, 0, 0}, 0, {0, 1, 0}), key(1, {1, 0, 0}, 0, {0, 1, 0}), key(3, {5, 0, 0}, 0, {0, 1, 0})};
        const double h = 1e-6;
        auto slopeAt = [&](double t) { return (positionAt(path, t + h) - positionAt(path, t - h)).x / (2 * h); };
        QVERIFY(std::abs(slopeAt(1.0) - 4.0 / 3.0) < 1e-6);
        QVERIFY(std::abs((positionAt(path, h) - positionAt(path, 0)).x / h - 1.0) < 1e-5);
        QVERIFY(std::abs((positionAt(path, 3) - positionAt(path, 3 - h)).x / h - 2.0) < 1e-5);
    }

    // One-sided difference quotients at each interior key differ by O(h): the kink shrinks ten-fold
    // with h. (A C0 curve would keep a fixed kink.)
    void positionIsC1InTime() {
        const CameraPath path = winding();
        for (std::size_t k = 1; k + 1 < path.keys.size(); ++k) {
            const double t = path.keys[k].time;
            const double coarse = positionKink(path, t, 1e-3), fine = positionKink(path, t, 1e-4);
            QVERIFY2(fine < 0.15 * coarse + 1e-9, qPrintable(QString("key %1: %2 vs %3").arg(k).arg(fine).arg(coarse)));
            QVERIFY(fine < 1e-2);
        }
    }

    // Squad's angular velocity is continuous at keys and equals the central difference
    // 2 (log(q_k^-1 q_k+1) - log(q_k^-1 q_k-1)) / (t_k+1 - t_k-1); slerp's jumps.
    void squadIsC1AndSlerpIsNot() {
        const CameraPath squad = winding(RotationInterpolation::Squad);
        const CameraPath slerp = winding(RotationInterpolation::Slerp);
        for (std::size_t k = 1; k + 1 < squad.keys.size(); ++k) {
            const double t = squad.keys[k].time;
            const double coarse = rotationKink(squad, t, 1e-3), fine = rotationKink(squad, t, 1e-4);
            QVERIFY(fine < 0.15 * coarse + 1e-9);
            QVERIFY(rotationKink(slerp, t, 1e-4) > 0.05);
            const glm::dquat q = squad.keys[k].orientation;
            const double span = squad.keys[k + 1].time - squad.keys[k - 1].time;
            const glm::dvec3 central = (angularVelocity(q, squad.keys[k + 1].orientation, 1.0)
                                        - angularVelocity(q, squad.keys[k - 1].orientation, 1.0)) / span;
            const glm::dvec3 measured = angularVelocity(sampleCameraPath(squad, t - 1e-6).orientation,
                                                        sampleCameraPath(squad, t + 1e-6).orientation, 2e-6);
            QVERIFY2(glm::length(measured - central) < 1e-4 * glm::length(central),
                     qPrintable(QString("key %1").arg(k)));
        }
    }

    void constantSpeedIsWithinOnePercent() {
        const CameraPath path = winding(RotationInterpolation::Squad, true);
        const double length = cameraPathLength(path);
        const double duration = path.keys.back().time - path.keys.front().time;
        const double expected = length / duration;
        const int samples = 2000;
        const double h = 1e-5;
        std::vector<double> times; // pairs t - h, t + h
        for (int i = 0; i < samples; ++i) {
            const double t = h + (duration - 2 * h) * i / (samples - 1);
            times.insert(times.end(), {t - h, t + h});
        }
        const std::vector<CameraKey> keys = sampleCameraPath(path, times);
        QCOMPARE(keys[777], sampleCameraPath(path, times[777])); // batch and single sampling agree exactly
        double worst = 0.0;
        for (std::size_t i = 0; i < keys.size(); i += 2) {
            const double speed = glm::length(keys[i + 1].position - keys[i].position) / (2 * h);
            worst = std::max(worst, std::abs(speed / expected - 1.0));
        }
        qInfo("constant speed: path length %.6f m, worst relative speed error %.2e over %d samples", length, worst,
              samples);
        QVERIFY(worst < 0.01);
        QCOMPARE(positionAt(path, 0.0), path.keys.front().position);
        QVERIFY(glm::length(positionAt(path, duration) - path.keys.back().position) < 1e-9);
    }

    // The test above is meaningful: the plain curve's speed varies a lot.
    void plainTimingIsNotConstantSpeed() {
        const CameraPath path = winding();
        double slowest = 1e30, fastest = 0.0;
        for (int i = 1; i < 400; ++i) {
            const double t = 4.0 * i / 400, h = 1e-5;
            const double speed = glm::length(positionAt(path, t + h) - positionAt(path, t - h)) / (2 * h);
            slowest = std::min(slowest, speed);
            fastest = std::max(fastest, speed);
        }
        QVERIFY(fastest > 1.5 * slowest);
    }

    void lensValuesStayValid() {
        CameraPath path;
        path.keys = {key(0, {0, 0, 0}, 0, {0, 1, 0}, 0.7f, 0.0f), key(0.1, {1, 0, 0}, 0, {0, 1, 0}, 0.7f, 0.5f),
                     key(3, {2, 0, 0}, 0, {0, 1, 0}, 0.7f, 0.0f), key(3.1, {3, 0, 0}, 0, {0, 1, 0}, 0.7f, 0.0f)};
        for (int i = 0; i <= 310; ++i) QVERIFY(sampleCameraPath(path, i * 0.01).lensRadius >= 0.0f);
    }

    void bakedTrackMatchesTheCurveAtItsSamples() {
        const CameraPath path = winding();
        const NodeId camera{42};
        const Animation baked = bakeCameraPath(path, camera, 10.0);
        QVERIFY(baked.bakedCameraPath);
        QCOMPARE(baked.channels.size(), std::size_t(2));
        const AnimationChannel& translation = baked.channels[0];
        const AnimationChannel& rotation = baked.channels[1];
        QCOMPARE(translation.path, AnimationPath::Translation);
        QCOMPARE(rotation.path, AnimationPath::Rotation);
        QCOMPARE(translation.node, camera);
        QCOMPARE(rotation.interpolation, Interpolation::Linear);
        QCOMPARE(translation.times.size(), std::size_t(41)); // 0, 0.1, ..., 4.0
        QCOMPARE(translation.times, rotation.times);
        for (std::size_t i = 0; i < translation.times.size(); ++i) {
            QCOMPARE(translation.times[i], float(0.1 * double(i)));
            const CameraKey exact = sampleCameraPath(path, 0.1 * double(i));
            const float* p = &translation.values[3 * i];
            const float* q = &rotation.values[4 * i];
            QVERIFY(glm::length(glm::dvec3(p[0], p[1], p[2]) - exact.position) < 1e-6);
            QVERIFY(sameRotation(glm::dquat(q[3], q[0], q[1], q[2]), exact.orientation, 1e-6));
            if (i > 0) QVERIFY(glm::dot(glm::vec4(q[0], q[1], q[2], q[3]), glm::vec4(q[-4], q[-3], q[-2], q[-1])) >= 0);
        }
    }

    void bakeIncludesTheLastKeyOffTheFrameGrid() {
        CameraPath path = winding();
        path.keys.back().time = 4.05;
        const Animation baked = bakeCameraPath(path, NodeId{1}, 10.0);
        const std::vector<float>& times = baked.channels[0].times;
        QCOMPARE(times.size(), std::size_t(42));
        QCOMPARE(times[40], 4.0f);
        QCOMPARE(times.back(), 4.05f);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bakeCameraPath(path, NodeId{1}, 0.0));
    }

    void validationRejectsWhatSamplingCannotUse() {
        QVERIFY(isValidCameraPath(winding()));
        QVERIFY(!isValidCameraPath(CameraPath{}));
        CameraPath repeated = winding();
        repeated.keys[2].time = repeated.keys[1].time;
        QVERIFY(!isValidCameraPath(repeated));
        CameraPath notANumber = winding();
        notANumber.keys[3].position.y = std::nan("");
        QVERIFY(!isValidCameraPath(notANumber));
        CameraPath zeroRotation = winding();
        zeroRotation.keys[0].orientation = glm::dquat(0, 0, 0, 0);
        QVERIFY(!isValidCameraPath(zeroRotation));
    }

    void oneKeyPathHoldsStill() {
        CameraPath path;
        path.keys = {key(2.0, {1, 2, 3}, 0.5, {0, 1, 0})};
        const CameraKey s = sampleCameraPath(path, 7.0);
        QCOMPARE(s.position, path.keys[0].position);
        QCOMPARE(s.orientation, path.keys[0].orientation);
        QCOMPARE(cameraPathLength(path), 0.0);
        const Animation baked = bakeCameraPath(path, NodeId{3}, 24.0);
        QCOMPARE(baked.channels[0].times, std::vector<float>{2.0f});
        QCOMPARE(baked.channels[0].values, (std::vector<float>{1, 2, 3}));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, sampleCameraPath(CameraPath{}, 0.0));
    }

    // Two keys: straight motion at uniform speed and a plain slerp (squad has no inner controls).
    void twoKeyPathIsLinearWithSlerp() {
        CameraPath path;
        path.keys = {key(1, {0, 0, 0}, 0, {0, 1, 0}), key(3, {4, 0, 3}, 1.0, {0, 1, 0})};
        QVERIFY(std::abs(cameraPathLength(path) - 5.0) < 1e-12);
        for (double u : {0.1, 0.25, 0.5, 0.9}) {
            const CameraKey s = sampleCameraPath(path, 1 + 2 * u);
            QVERIFY(glm::length(s.position - u * glm::dvec3(4, 0, 3)) < 1e-12);
            QVERIFY(sameRotation(s.orientation, glm::angleAxis(u, glm::dvec3(0, 1, 0)), 1e-12));
        }
        path.constantSpeed = true;
        QVERIFY(glm::length(sampleCameraPath(path, 1.5).position - glm::dvec3(1, 0, 0.75)) < 1e-9);
    }
};

QTEST_APPLESS_MAIN(TestCameraPath)
#include "test_camera_path.moc"
