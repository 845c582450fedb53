// The BVH heat map (DebugView::BvhCost, the `bvh_cost` AOV): on a scene with a known layout the
// camera rays' BVH work is higher through a cluster of 64 box instances than on a lone quad, and
// exactly 0 where the rays miss the scene's bounds or the scene has no meshes; the counts are
// deterministic; the beauty render is bit-identical before and after the variant was compiled and
// ran (the counters exist only in the variant); the EXR gets a `bvh_cost` channel only when it is asked
// for. Orthographic camera, 32x16 px, 2 spp, seed 3, llvmpipe.
#include "mesh_builder.h"
#include "scene_builder.h"

#include "renderer/bvh_cost_render.h"
#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstring>
#include <memory>
#include <set>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kWidth = 32, kHeight = 16;

struct Layout {
    Scene scene;
    std::set<float> cluster; // object ids of the cluster's boxes
    float quad = 0.0f;       // object id of the lone quad
};

// Left: a 4 x 4 x 4 grid of 0.2 m boxes, 0.5 m apart (rays between the front boxes pass many
// top-level boxes); right: one quad facing the camera; all within |y| < 0.9 m. The orthographic
// camera sees |y| < 2 m, so its top row misses the scene's bounds.
Layout knownLayout() {
    Layout l;
    Scene& s = l.scene;
    s.settings.environment.color = glm::vec3(0.5f);
    const MaterialId grey = s.materials.add(lambert(glm::vec3(0.6f)));
    const MeshId box = s.meshes.add(boxMesh(glm::vec3(0.2f), grey));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                const glm::vec3 at(-2.5f + 0.5f * (float(i) - 1.5f), 0.5f * (float(j) - 1.5f), -0.5f * float(k));
                l.cluster.insert(float(addNode(s, "box", MeshInstance{box}, at).value));
            }
    const MeshId quad = s.meshes.add(quadMesh(1.0f, grey));
    l.quad = float(addNode(s, "quad", MeshInstance{quad}, {2.5f, 0.0f, 0.0f},
                           glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f))).value);
    addSun(s, {0.3f, -1.0f, -0.5f}, 683.0f);
    addOrthographicCamera(s, {0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, 2.0f);
    return l;
}

renderer::RenderRequest request() {
    renderer::RenderRequest r;
    r.width = kWidth;
    r.height = kHeight;
    r.spp = 2;
    r.seed = 3;
    r.bounces = 2;
    return r;
}

double meanOf(const std::vector<float>& cost, const std::vector<float>& ids, auto&& keep) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < cost.size(); ++i)
        if (keep(ids[i])) sum += cost[i], ++n;
    return n > 0 ? sum / n : -1.0;
}

} // namespace

class TestBvhCost : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    void costFollowsTheLayout() {
        const Layout l = knownLayout();
        renderer::RenderRequest r = request();
        r.view = renderer::DebugView::BvhCost;
        r.configuration = renderer::Configuration::Accumulate;
        const renderer::RenderOutput out = renderer_->render(l.scene, r);
        std::vector<float> cost;
        for (std::size_t i = 0; i < out.radiance.size(); i += 4) cost.push_back(out.radiance[i]);
        // The top row misses the scene's bounds: no node is visited at all.
        for (int x = 0; x < kWidth; ++x) QCOMPARE(cost[std::size_t(x)], 0.0f);
        const double cluster = meanOf(cost, out.objectId, [&](float id) { return l.cluster.count(id) > 0; });
        const double quad = meanOf(cost, out.objectId, [&](float id) { return id == l.quad; });
        qInfo("mean cost per camera ray: cluster %.2f, lone quad %.2f, largest %.1f", cluster, quad,
              double(*std::max_element(cost.begin(), cost.end())));
        QVERIFY(quad > 0.0);             // something was hit, so something was walked
        QVERIFY(cluster > quad + 1.0);   // the cluster's overlapping boxes cost more (measured 8.5 vs 6)
        // nodes + primitives = total: green and blue hold the two parts.
        for (std::size_t i = 0; i < out.radiance.size(); i += 4)
            QCOMPARE(out.radiance[i], out.radiance[i + 1] + out.radiance[i + 2]);
    }

    void noMeshesCostNothing() {
        Scene s;
        s.settings.environment.color = glm::vec3(0.5f);
        addShape(s, ShapeKind::Sphere, s.materials.add(lambert(glm::vec3(0.6f))), glm::vec3(0.0f));
        addOrthographicCamera(s, {0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, 1.0f);
        const std::vector<float> cost = renderer::renderBvhCost(*renderer_, s, request());
        QCOMPARE(cost.size(), std::size_t(kWidth * kHeight));
        QVERIFY(std::all_of(cost.begin(), cost.end(), [](float c) { return c == 0.0f; }));
    }

    void deterministicAndTheBeautyIsUntouched() {
        const Layout l = knownLayout();
        const renderer::RenderOutput before = renderer_->render(l.scene, request());
        const std::vector<float> first = renderer::renderBvhCost(*renderer_, l.scene, request());
        const std::vector<float> second = renderer::renderBvhCost(*renderer_, l.scene, request());
        const renderer::RenderOutput after = renderer_->render(l.scene, request());
        QVERIFY(first == second);
        QCOMPARE(before.radiance.size(), after.radiance.size());
        QVERIFY(std::memcmp(before.radiance.data(), after.radiance.data(), before.radiance.size() * sizeof(float)) == 0);
    }

    void exrChannelOnlyWhenListed() {
        const Layout l = knownLayout();
        renderer::RenderOutput image = renderer_->render(l.scene, request());
        image.bvhCost = renderer::renderBvhCost(*renderer_, l.scene, request());
        QTemporaryDir dir;
        const std::string with = dir.filePath("with.exr").toStdString(), without = dir.filePath("all.exr").toStdString();
        renderer::writeRenderImage(with, image, renderer::parseAovList("albedo,normal,depth,id,bvh_cost"), {});
        renderer::writeRenderImage(without, image, renderer::parseAovList("all"), {});
        auto in = OIIO::ImageInput::open(with);
        QVERIFY(in);
        const OIIO::ImageSpec spec = in->spec();
        const auto channel = std::find(spec.channelnames.begin(), spec.channelnames.end(), "bvh_cost");
        QVERIFY(channel != spec.channelnames.end());
        std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
        QVERIFY(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
        const auto c = std::size_t(channel - spec.channelnames.begin());
        for (std::size_t i = 0; i < image.bvhCost.size(); ++i) QCOMPARE(pixels[i * std::size_t(spec.nchannels) + c], image.bvhCost[i]);
        auto plain = OIIO::ImageInput::open(without);
        QVERIFY(plain);
        const auto& names = plain->spec().channelnames;
        QVERIFY(std::find(names.begin(), names.end(), "bvh_cost") == names.end());
        QCOMPARE(int(names.size()), 12); // R G B A, albedo x3, N x3, Z, id: unchanged
    }
};

QTEST_APPLESS_MAIN(TestBvhCost)
#include "test_bvh_cost.moc"
