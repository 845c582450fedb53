// Failure modes of reconstruction with history, measured against per-frame converged references
// (48 spp, another seed): disocclusion under a moving camera, a light switched off (lag), a moving
// object (trail), and the mirror under camera motion (smear). Figures go to docs/DENOISING.md.
#include "reconstruction_fixture.h"

#include "scene/anim/scene_at_time.h"

#include <QtTest>

using namespace glint;
using namespace glint::test;

namespace {

std::vector<float> ids(renderer::FrameRenderer& frames) { return frames.readImages().objectId; }

double meanLuminance(const std::vector<float>& rgba) {
    double sum = 0.0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) sum += 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    return sum / static_cast<double>(rgba.size() / 4);
}

// Mean frame-to-frame change of tonemapped luminance Y/(1+Y) after motion compensation: frame b
// against frame a fetched at b's motion vectors (nearest pixel; pixels reprojected outside skipped).
double flicker(const std::vector<float>& a, const std::vector<float>& b, const std::vector<float>& motion) {
    const auto tone = [](const std::vector<float>& v, std::size_t p) {
        const double y = 0.2126 * v[p * 4] + 0.7152 * v[p * 4 + 1] + 0.0722 * v[p * 4 + 2];
        return y / (1.0 + y);
    };
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < imageSize; ++y)
        for (int x = 0; x < imageSize; ++x) {
            const std::size_t p = static_cast<std::size_t>(y * imageSize + x);
            // Images are top-down, motion is in GL pixels (y up).
            const int px = static_cast<int>(std::lround(x + motion[p * 2]));
            const int py = static_cast<int>(std::lround(y - motion[p * 2 + 1]));
            if (px < 0 || py < 0 || px >= imageSize || py >= imageSize) continue;
            sum += std::abs(tone(b, p) - tone(a, static_cast<std::size_t>(py * imageSize + px)));
            ++count;
        }
    return count ? sum / count : 0.0;
}

// A rotation channel that lowers the sun (about world X) by `angle` radians over `seconds`: its
// shadows move and the ground dims, by animation alone (no edit, no history drop).
void addSunset(RoomScene& room, float angle, float seconds) {
    const glm::quat start = room.scene.at(room.sun).local.rotation;
    const glm::quat end = glm::angleAxis(angle, glm::vec3(1.0f, 0.0f, 0.0f)) * start;
    AnimationChannel channel;
    channel.node = room.sun;
    channel.path = AnimationPath::Rotation;
    channel.times = {0.0f, seconds};
    channel.values = {start.x, start.y, start.z, start.w, end.x, end.y, end.z, end.w};
    Animation animation;
    animation.name = "sunset";
    animation.channels.push_back(channel);
    room.scene.animations.add(std::move(animation));
}

} // namespace

class TestTemporalStability : public QObject {
    Q_OBJECT
    std::unique_ptr<Harness> h_;

    // Raw 1-spp error of one frame at `camera` (a fresh accumulation, no history).
    double rawError(const Scene& scene, const renderer::CameraSetup& camera, const std::vector<float>& reference,
                    const std::vector<bool>& mask = {}) {
        renderer::FrameRenderer raw;
        raw.setSettings(settingsFor(renderer::Configuration::Accumulate));
        raw.setScene(scene);
        raw.setCamera(camera);
        raw.renderFrame();
        return relMse(raw.readImages().radiance, reference, mask);
    }

    // Relative errors over a metal surface under the camera pan (5 cm a frame), frames 4-12: Full,
    // Realistic and raw 1 spp (references shared by all three).
    struct MetalErrors {
        double full = 0.0, realistic = 0.0, raw = 0.0;
    };
    MetalErrors metalUnderCameraMotion(const Scene& scene, NodeId metal, const std::string& name) {
        renderer::FrameRenderer realistic;
        realistic.setSettings(settingsFor(renderer::Configuration::Realistic));
        realistic.setScene(scene);
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(scene);
        MetalErrors e;
        for (int f = 0; f <= 12; ++f) {
            const auto camera = cameraAt(scene, 0.05f * static_cast<float>(f));
            const auto image = h_->frame(camera);
            realistic.setCamera(camera);
            realistic.renderFrame();
            if (f < 4) continue;
            const auto current = ids(h_->frames);
            std::vector<bool> mask(current.size());
            for (std::size_t i = 0; i < current.size(); ++i) mask[i] = current[i] == static_cast<float>(metal.value);
            const auto reference = h_->converged(scene, camera);
            e.full += relMse(image, reference, mask) / 9;
            e.realistic += relMse(realistic.readImages().radiance, reference, mask) / 9;
            e.raw += rawError(scene, camera, reference, mask) / 9;
            if (f == 12) dump(image, name + "_full_12"), dump(reference, name + "_reference_12");
        }
        return e;
    }

private slots:
    void initTestCase() { h_ = std::make_unique<Harness>(); }

    // Slow pan (2 cm, about a quarter pixel, a frame) over static geometry. Tolerance: Realistic's
    // motion-compensated frame-to-frame change is below half of raw 1-spp frames'.
    void flickerUnderSlowPan() {
        const RoomScene room = makeRoom();
        std::vector<std::vector<float>> taa, raw, motion;
        h_->frames.setSettings(settingsFor(renderer::Configuration::Realistic));
        h_->frames.setScene(room.scene);
        renderer::FrameRenderer noFilter;
        noFilter.setScene(room.scene);
        for (int f = 0; f < 16; ++f) {
            const auto camera = cameraAt(room.scene, 0.02f * static_cast<float>(f));
            taa.push_back(h_->frame(camera));
            motion.push_back(h_->frames.readImages().motion);
            renderer::FrameSettings rawSettings = settingsFor(renderer::Configuration::Accumulate);
            rawSettings.seed = static_cast<std::uint32_t>(f); // fresh noise each frame, as a real-time frame has
            noFilter.setSettings(rawSettings);
            noFilter.setCamera(camera);
            noFilter.renderFrame();
            raw.push_back(noFilter.readImages().radiance);
        }
        double withTaa = 0.0, without = 0.0;
        for (std::size_t f = 8; f < 16; ++f) {
            withTaa += flicker(taa[f - 1], taa[f], motion[f]) / 8;
            without += flicker(raw[f - 1], raw[f], motion[f]) / 8;
        }
        qInfo("slow pan, frames 8-15: mean |change| of tonemapped luminance, TAA %.4f, raw 1 spp %.4f", withTaa, without);
        QVERIFY(withTaa < 0.5 * without);
    }

    // Camera pans 5 cm a frame past the red box. Tolerance: over frames 4-12 Full's mean relMSE is
    // below 0.6x the raw 1-spp error, and in the pixels disoccluded since frame 0 (id changed) it is
    // no worse than raw samples there (ghosting would make it worse).
    void disocclusionUnderCameraMotion() {
        const RoomScene room = makeRoom();
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        h_->frame(cameraAt(room.scene, 0.0f));
        const std::vector<float> firstIds = ids(h_->frames);
        double full = 0.0, raw = 0.0, fullNew = 0.0, rawNew = 0.0;
        for (int f = 1; f <= 12; ++f) {
            const auto camera = cameraAt(room.scene, 0.05f * static_cast<float>(f));
            const auto image = h_->frame(camera);
            if (f < 4) continue;
            const auto current = ids(h_->frames);
            std::vector<bool> uncovered(current.size());
            for (std::size_t i = 0; i < current.size(); ++i) uncovered[i] = current[i] != firstIds[i];
            const auto reference = h_->converged(room.scene, camera);
            full += relMse(image, reference);
            raw += rawError(room.scene, camera, reference);
            fullNew += relMse(image, reference, uncovered);
            rawNew += rawError(room.scene, camera, reference, uncovered);
            if (f == 12) dump(image, "pan_full_12"), dump(reference, "pan_reference_12");
        }
        qInfo("camera pan, frames 4-12: Full relMSE %.4f, raw 1 spp %.4f; disoccluded pixels: Full %.4f, raw %.4f",
              full / 9, raw / 9, fullNew / 9, rawNew / 9);
        QVERIFY(full < 0.6 * raw);
        QVERIFY(fullNew <= rawNew);
    }

    // The sun goes off after 16 still frames (switched through the API, as A-SVGF's protocol does).
    // Lag = frames until the mean luminance is within 10% of the sun-less reference's. The edit keeps
    // the history (it took 17 frames so); anti-lag finds the stale pixels and shortens their history.
    // relMSE on frames 1 and 4 after the switch is printed. Tolerance: lag <= 2 frames, and frame 4
    // already below the raw 1-spp error.
    void lightSwitchedOff() {
        RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        for (int f = 0; f < 16; ++f) h_->frame(camera);
        Light off = *room.scene.at(room.sun).get<Light>();
        off.intensity = 0.0f;
        room.scene.setComponent(room.sun, off);
        h_->frames.applyChanges(room.scene, nodeChange(Change::Light, room.sun));
        const auto reference = h_->converged(room.scene, camera);
        const double target = meanLuminance(reference);
        int lag = -1;
        double errors[5] = {};
        for (int f = 1; f <= 4; ++f) {
            const auto image = h_->frame(camera);
            errors[f] = relMse(image, reference);
            if (lag < 0 && std::abs(meanLuminance(image) - target) <= 0.1 * target) lag = f;
        }
        const double raw = rawError(room.scene, camera, reference);
        qInfo("light switched off: lag %d frames (Full); relMSE after the switch: frame 1 %.4f, frame 4 %.4f, raw %.4f",
              lag, errors[1], errors[4], raw);
        QVERIFY(lag > 0);
        QVERIFY(lag <= 2);
        QVERIFY(errors[4] < raw);
    }

    // The sun sinks 2 degrees a frame by animation for 16 frames after 16 still ones (setTime only:
    // history is kept). Without anti-lag the filters lag behind the moving shadows and the dimming
    // ground (measured: 0.65x raw without anti-lag, 0.59x with it). Tolerance: over frames 8, 12 and
    // 16 of the sunset Full's relMSE is below 0.6x the raw 1-spp error, and its mean luminance is
    // within 3 % of the reference's at every one of them.
    void animatedLightDoesNotLag() {
        RoomScene room = makeRoom();
        const float fps = 24.0f;
        addSunset(room, 0.56f, 16.0f / fps);
        const auto camera = cameraAt(room.scene, 0.0f);
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        h_->frames.setTime(0.0);
        for (int f = 0; f < 16; ++f) h_->frame(camera);
        double full = 0.0, raw = 0.0, worstMean = 0.0;
        for (int f = 1; f <= 16; ++f) {
            h_->frames.setTime(f / fps);
            const auto image = h_->frame(camera);
            if (f % 4 != 0 || f < 8) continue;
            Scene posed = sceneAt(room.scene, f / fps);
            posed.animations = {}; // a still copy: the reference renderers stay at time 0
            const auto reference = h_->converged(posed, camera);
            full += relMse(image, reference) / 3;
            raw += rawError(posed, camera, reference) / 3;
            const double target = meanLuminance(reference);
            worstMean = std::max(worstMean, std::abs(meanLuminance(image) - target) / target);
            if (f == 16) dump(image, "sunset_full_16"), dump(reference, "sunset_reference_16");
        }
        qInfo("sunset by animation, frames 8/12/16: Full relMSE %.4f, raw 1 spp %.4f; worst mean-luminance error %.1f %%",
              full, raw, 100.0 * worstMean);
        QVERIFY(full < 0.6 * raw);
        QVERIFY(worstMean < 0.03);
    }

    // Mirrors under the camera pan: a reflection moves with the reflected point's virtual image, by
    // which SVGF reprojects the specular lobe (virtual motion vectors, docs/DENOISING.md failure
    // mode 4). The mirror ball (its image is near the surface's: the thin-mirror correction) and a
    // mirror floor quad (metal, roughness 0; it reflects the wall, box and balls, whose images move
    // unlike the floor). Tolerances, as measured with a margin: Full below 0.72x the raw error on the
    // ball (0.68x; 0.71x before virtual motion) and below 0.25x on the floor (0.22x; 0.28x before).
    void mirrorUnderCameraMotion() {
        const RoomScene room = makeRoom();
        const MetalErrors ball = metalUnderCameraMotion(room.scene, room.mirrorBall, "mirror_ball");
        qInfo("mirror ball under camera pan, frames 4-12: Full relMSE %.4f, Realistic %.4f, raw 1 spp %.4f", ball.full,
              ball.realistic, ball.raw);
        RoomScene floorRoom = makeRoom();
        Material chrome = mirror();
        chrome.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        const NodeId floor = addShape(floorRoom.scene, ShapeKind::Quad, floorRoom.scene.materials.add(chrome), {0.0f, 0.01f, 0.5f},
                                      0.5f, {6.0f, 1.0f, 3.0f});
        const MetalErrors floorErrors = metalUnderCameraMotion(floorRoom.scene, floor, "mirror_floor");
        qInfo("mirror floor under camera pan, frames 4-12: Full relMSE %.4f, Realistic %.4f, raw 1 spp %.4f", floorErrors.full,
              floorErrors.realistic, floorErrors.raw);
        QVERIFY(ball.full < 0.72 * ball.raw);
        QVERIFY(floorErrors.full < 0.25 * floorErrors.raw);
    }

    // The box slides 4 cm a frame (transform changes through the API). Trail: pixels the box
    // covered `age` frames ago and no longer covers. This is a known failure (a trail: the box's
    // moving shadow and the uncovered wall keep stale history, docs/DENOISING.md). Tolerance, as
    // measured (0.27 vs 0.16): 4 frames after the box left, Full's error there stays below twice
    // the raw 1-spp error; a regression that makes the trail longer or brighter fails.
    void movingObjectLeavesNoTrail() {
        RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        std::vector<std::vector<float>> history;
        double full[2] = {0, 0}, raw[2] = {0, 0};
        const int ages[2] = {2, 4};
        const float box = static_cast<float>(room.occluder.value);
        for (int f = 0; f <= 12; ++f) {
            Transform t = room.scene.at(room.occluder).local;
            t.translation.x = -0.6f + 0.04f * static_cast<float>(f);
            room.scene.setLocal(room.occluder, t);
            h_->frames.applyChanges(room.scene, nodeChange(Change::Transform, room.occluder));
            const auto image = h_->frame(camera);
            history.push_back(ids(h_->frames));
            if (f < 6) continue;
            const auto reference = h_->converged(room.scene, camera);
            for (int k = 0; k < 2; ++k) {
                const auto& then = history[static_cast<std::size_t>(f - ages[k])];
                std::vector<bool> trail(then.size());
                for (std::size_t i = 0; i < trail.size(); ++i) trail[i] = then[i] == box && history.back()[i] != box;
                full[k] += relMse(image, reference, trail) / 7;
                raw[k] += rawError(room.scene, camera, reference, trail) / 7;
            }
            if (f == 12) dump(image, "moving_full_12"), dump(reference, "moving_reference_12"), dump(errorImage(image, reference), "moving_error_12");
        }
        qInfo("moving box, frames 6-12, pixels it left 2 frames ago: Full relMSE %.4f, raw 1 spp %.4f", full[0], raw[0]);
        qInfo("moving box, frames 6-12, pixels it left 4 frames ago: Full relMSE %.4f, raw 1 spp %.4f", full[1], raw[1]);
        // No trail beyond 4 frames: there the error is below one raw sample's (0.89x measured; 1.64x
        // before restarted histories got the stricter SVGF filter, docs/DENOISING.md mode 3).
        QVERIFY(full[1] < 1.0 * raw[1]);
    }
};

QTEST_APPLESS_MAIN(TestTemporalStability)
#include "test_temporal_stability.moc"
