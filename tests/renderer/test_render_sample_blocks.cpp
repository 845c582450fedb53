// Sample blocks (RenderSettings::sampleBlock, docs/PERFORMANCE.md "Sample blocks"): the pixels of an
// aligned N x N block share one sample sequence, so their paths take the same directions.
//
// The scene makes a pixel's value a function of its random numbers alone: a grey quad facing up
// under the studio HDR, seen straight down through an orthographic window inside it, at 0 bounces
// and 1 spp. Every hit has the same normal and an open sky, so the light and BSDF samples alone
// decide what a pixel shows: pixels that share a sequence are equal to the bit, and pixels that do
// not almost never are.
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <filesystem>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 16;
const std::filesystem::path kStudio = std::filesystem::path(GLINT_TEST_DATA_DIR) / "env" / "studio_small_03_1k.hdr";

Scene quadUnderStudio() {
    Scene scene;
    addShape(scene, ShapeKind::Quad, scene.materials.add(lambert(glm::vec3(0.5f))), glm::vec3(0.0f), 0.5f, glm::vec3(4.0f));
    addOrthographicCamera(scene, {0.0f, 0.5f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.01f);
    return scene;
}

struct BlockCounts {
    int pairsInBlocks = 0;      // pixel pairs inside one block, compared
    int equalInBlocks = 0;      // of them, equal in every channel
    int pairsAcrossBlocks = 0;  // a block's first pixel against the next block's
    int equalAcrossBlocks = 0;
};

// Compares each pixel with its block's first pixel (block = `block` pixels per side).
BlockCounts compareBlocks(const renderer::RenderOutput& out, int block) {
    const auto pixel = [&](int x, int y) { return &out.radiance[(static_cast<std::size_t>(y) * kSize + x) * 4]; };
    const auto equal = [](const float* a, const float* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
    BlockCounts counts;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float* first = pixel(x - x % block, y - y % block);
            if (first == pixel(x, y)) continue;
            ++counts.pairsInBlocks;
            counts.equalInBlocks += equal(first, pixel(x, y));
        }
    }
    for (int y = 0; y < kSize; y += block) {
        for (int x = 0; x + block < kSize; x += block) {
            ++counts.pairsAcrossBlocks;
            counts.equalAcrossBlocks += equal(pixel(x, y), pixel(x + block, y));
        }
    }
    return counts;
}

} // namespace

class TestRenderSampleBlocks : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(int sampleBlock, int spp) {
        renderer::RenderRequest request = stillRequest(kSize, spp, 7, 0);
        request.envFile = kStudio;
        request.tonemapper = Tonemapper::None;
        request.sampleBlock = sampleBlock;
        return renderer_->render(quadUnderStudio(), request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 1 spp: with blocks of 2, 4 or 8, every pixel equals its block's first one and neighbouring
    // blocks differ (at least 3 in 4 pairs); without blocks, fewer than 1 in 10 pixel pairs are equal.
    void pixelsOfABlockShareTheirSamples_data() {
        QTest::addColumn<int>("block");
        QTest::newRow("2 x 2") << 2;
        QTest::newRow("4 x 4") << 4;
        QTest::newRow("8 x 8") << 8;
    }
    void pixelsOfABlockShareTheirSamples() {
        QFETCH(int, block);
        const BlockCounts shared = compareBlocks(render(block, 1), block);
        QCOMPARE(shared.equalInBlocks, shared.pairsInBlocks);
        QVERIFY2(4 * shared.equalAcrossBlocks <= shared.pairsAcrossBlocks,
                 qPrintable(QString("%1 of %2 neighbouring blocks equal").arg(shared.equalAcrossBlocks).arg(shared.pairsAcrossBlocks)));
        const BlockCounts own = compareBlocks(render(1, 1), block);
        QVERIFY2(10 * own.equalInBlocks < own.pairsInBlocks,
                 qPrintable(QString("%1 of %2 pixel pairs equal without blocks").arg(own.equalInBlocks).arg(own.pairsInBlocks)));
    }

    // 64 spp: a block's pixels still share every sample, and the image mean stays within 2 % of the
    // mean without blocks (each pixel's estimate is as unbiased as before; the two differ by noise).
    void blocksKeepTheMean() {
        const renderer::RenderOutput blocks = render(4, 64);
        const renderer::RenderOutput own = render(1, 64);
        QCOMPARE(compareBlocks(blocks, 4).equalInBlocks, compareBlocks(blocks, 4).pairsInBlocks);
        double sumBlocks = 0.0, sumOwn = 0.0;
        for (std::size_t i = 1; i < own.radiance.size(); i += 4) sumBlocks += blocks.radiance[i], sumOwn += own.radiance[i];
        qInfo("mean green: blocks %.5f, own %.5f", sumBlocks / (kSize * kSize), sumOwn / (kSize * kSize));
        QVERIFY(sumOwn > 0.0);
        QVERIFY2(std::abs(sumBlocks / sumOwn - 1.0) < 0.02, qPrintable(QString("ratio %1").arg(sumBlocks / sumOwn)));
    }
};

QTEST_GUILESS_MAIN(TestRenderSampleBlocks)
#include "test_render_sample_blocks.moc"
