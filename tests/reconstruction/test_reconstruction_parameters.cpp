// The project's TAA parameters reach the renderer (FrameRenderer through OfflineRenderer, as
// `glint render` and the editor's export use it): 3 frames of Realistic (TAA only) at 24x24, 1 spp,
// seed 0, still camera. Each history clip mode gives other pixels than the default variance clip,
// and the same settings give bit-identical pixels (tolerance 0).
#include "reconstruction_fixture.h"

#include "renderer/offline_render.h"

#include <QtTest>

using namespace glint;

namespace {

std::vector<float> renderTaa(renderer::OfflineRenderer& offline, Scene scene, TaaClip clip) {
    scene.settings.render.taa.clip = clip;
    renderer::RenderRequest request;
    request.configuration = renderer::Configuration::Realistic;
    request.frames = 3;
    request.width = request.height = 24;
    request.spp = 1;
    request.bounces = 2;
    return offline.render(scene, request).radiance;
}

} // namespace

class TestReconstructionParameters : public QObject {
    Q_OBJECT
private slots:
    void clipModesChangeTheFrame() {
        const test::RoomScene room = test::makeRoom();
        renderer::OfflineRenderer offline;
        const std::vector<float> variance = renderTaa(offline, room.scene, TaaClip::Variance);
        const std::vector<float> again = renderTaa(offline, room.scene, TaaClip::Variance);
        const std::vector<float> minmax = renderTaa(offline, room.scene, TaaClip::MinMax);
        const std::vector<float> none = renderTaa(offline, room.scene, TaaClip::None);
        QCOMPARE(variance.size(), std::size_t(24 * 24 * 4));
        QVERIFY(again == variance);
        QVERIFY2(minmax != variance, "min/max clamping rendered the variance clip's pixels");
        QVERIFY2(none != variance, "no clipping rendered the variance clip's pixels");
    }
};

QTEST_GUILESS_MAIN(TestReconstructionParameters)
#include "test_reconstruction_parameters.moc"
