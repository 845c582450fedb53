// FrameRenderer as a host sees it: it draws into the framebuffer it is given (not 0), puts the
// caller's framebuffer, viewport, vertex array and enables back, keeps accumulating through exposure,
// tonemapper and sample-cap changes, says at once when the picture changed (a host that stops at a
// sample cap must render again), and refines progressively: bands of rows give the pixels of whole
// frames, a preview stands in until the first full-resolution sample is whole, and the mean's filter
// run in steps gives the pixels of the filter run whole.
#include "reconstruction_fixture.h"

#include <epoxy/gl.h>

#include <QtTest>

using namespace glint;
using namespace glint::test;

namespace {

// A host's RGBA8 framebuffer of size x size, deleted with it.
struct HostFramebuffer {
    explicit HostFramebuffer(int side) : size(side) {
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    }
    ~HostFramebuffer() {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &texture);
    }
    HostFramebuffer(const HostFramebuffer&) = delete;
    HostFramebuffer& operator=(const HostFramebuffer&) = delete;
    std::vector<unsigned char> read() const { // rows bottom-up
        std::vector<unsigned char> pixels(std::size_t(size) * std::size_t(size) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        return pixels;
    }
    int size;
    GLuint texture = 0;
    GLuint framebuffer = 0;
};

} // namespace

class TestFrameRendererHost : public QObject {
    Q_OBJECT
    std::unique_ptr<Harness> h_;

private slots:
    void initTestCase() { h_ = std::make_unique<Harness>(); }

    // Tolerance: exact. The host's framebuffer gets the same bytes readImages() reports, scaled 1:1.
    void drawsIntoTheGivenFramebufferAndRestoresState() {
        const RoomScene room = makeRoom();
        h_->frames.setSettings(settingsFor(renderer::Configuration::Accumulate));
        h_->frames.setScene(room.scene);
        h_->frame(cameraAt(room.scene, 0.0f));

        const HostFramebuffer host(imageSize);
        const GLuint target = host.framebuffer;
        QCOMPARE(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        GLuint other = 0;
        glGenFramebuffers(1, &other);
        glBindFramebuffer(GL_FRAMEBUFFER, other); // the host's current binding, not the target
        glViewport(3, 4, 5, 6);
        glEnable(GL_DEPTH_TEST);
        GLuint vertexArray = 0;
        glGenVertexArrays(1, &vertexArray);
        glBindVertexArray(vertexArray);

        h_->frames.drawTo(target, imageSize, imageSize);

        GLint drawFbo = 0, viewport[4] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
        glGetIntegerv(GL_VIEWPORT, viewport);
        QCOMPARE(GLuint(drawFbo), other);
        QCOMPARE(viewport[0], 3);
        QCOMPARE(viewport[3], 6);
        QVERIFY(glIsEnabled(GL_DEPTH_TEST));
        GLint boundVertexArray = 0;
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &boundVertexArray);
        QCOMPARE(GLuint(boundVertexArray), vertexArray);
        glBindVertexArray(0);
        glDeleteVertexArrays(1, &vertexArray);

        const std::vector<unsigned char> pixels = host.read();
        const auto expected = h_->frames.readImages().tonemapped; // top-down
        for (int y = 0; y < imageSize; ++y)
            for (int x = 0; x < imageSize * 4; ++x)
                QCOMPARE(pixels[static_cast<std::size_t>((imageSize - 1 - y) * imageSize * 4 + x)],
                         expected[static_cast<std::size_t>(y * imageSize * 4 + x)]);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &other);
    }

    // Tolerance: exact sample counts; radiance unchanged by exposure (applied only when drawn).
    void exposureAndTonemapperKeepAccumulation() {
        const RoomScene room = makeRoom();
        renderer::FrameSettings s = settingsFor(renderer::Configuration::Accumulate);
        h_->frames.setSettings(s);
        h_->frames.setScene(room.scene);
        const auto camera = cameraAt(room.scene, 0.0f);
        for (int i = 0; i < 3; ++i) h_->frame(camera);
        const auto before = h_->frames.readImages();
        s.exposure = 2.0f;
        s.tonemapper = Tonemapper::AcesFitted;
        h_->frames.setSettings(s);
        QCOMPARE(h_->frames.sampleCount(), 3);
        const auto after = h_->frames.readImages();
        QVERIFY(after.radiance == before.radiance);
        QVERIFY(after.tonemapped != before.tonemapped);
        h_->frame(camera);
        QCOMPARE(h_->frames.sampleCount(), 4);
        s.bounces = 1; // an image setting: starts over
        h_->frames.setSettings(s);
        h_->frame(camera);
        QCOMPARE(h_->frames.sampleCount(), 1);
    }

    // Tolerance: exact counts. A host that stops at a cap (the viewport) asks sampleCount() whether
    // the image is current: every change that makes a new picture reads 0 before the next frame.
    void sampleCountIsZeroAfterEveryChange() {
        const RoomScene room = makeRoom();
        renderer::FrameSettings s = settingsFor(renderer::Configuration::Accumulate);
        s.maxSamples = 2;
        h_->frames.setSettings(s);
        h_->frames.setScene(room.scene);
        const auto camera = cameraAt(room.scene, 0.0f);
        const auto atCap = [&] {
            for (int i = 0; i < 3; ++i) h_->frame(camera);
            return h_->frames.sampleCount() == 2 && h_->frames.imageStage() == renderer::ImageStage::Complete;
        };
        QVERIFY(atCap());
        s.maxSamples = 5; // raising the cap continues the mean
        h_->frames.setSettings(s);
        QCOMPARE(h_->frames.sampleCount(), 2);
        h_->frame(camera);
        QCOMPARE(h_->frames.sampleCount(), 3);
        s.maxSamples = 2;
        h_->frames.setSettings(s);

        s.width = imageSize / 2; // a resize
        h_->frames.setSettings(s);
        QCOMPARE(h_->frames.sampleCount(), 0);
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::None);
        s.width = imageSize;
        h_->frames.setSettings(s);
        QVERIFY(atCap());

        Scene moved = room.scene; // an edit applied in place (a transform)
        moved.setLocal(room.occluder, [&] { Transform t = moved.at(room.occluder).local; t.translation.x += 0.2f; return t; }());
        h_->frames.applyChanges(moved, nodeChange(Change::Transform, room.occluder));
        QCOMPARE(h_->frames.sampleCount(), 0);
        QVERIFY(atCap());

        h_->frames.setCamera(cameraAt(room.scene, 0.3f)); // the camera
        QCOMPARE(h_->frames.sampleCount(), 0);
        h_->frames.setScene(room.scene); // a new GPU scene (the viewport's uploads)
        QCOMPARE(h_->frames.sampleCount(), 0);
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::None);
    }

    // Tolerance: exact (bit for bit). A sample traced in bands of rows under a scissor is the
    // sample traced whole: the per-pixel random numbers do not depend on how the frame is cut.
    void bandsGiveTheWholeFramesPixels() {
        const RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        renderer::FrameSettings whole = settingsFor(renderer::Configuration::Accumulate);
        h_->reference.setSettings(whole);
        h_->reference.setScene(room.scene);
        h_->reference.setCamera(camera);
        for (int i = 0; i < 2; ++i) h_->reference.renderFrame();

        renderer::FrameSettings banded = whole;
        banded.rowsPerFrame = 7; // 48 rows: 7 bands, the last one 6 rows
        h_->frames.setSettings(banded);
        h_->frames.setScene(room.scene);
        h_->frames.setCamera(camera);
        for (int band = 1; band < 7; ++band) {
            h_->frames.renderFrame();
            QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Refining);
            QCOMPARE(h_->frames.sampleCount(), 0);
            QCOMPARE(h_->frames.rowsTraced(), 7 * band);
            QVERIFY(!h_->frames.drawTo(0, imageSize, imageSize)); // nothing whole to show yet
        }
        h_->frames.renderFrame();
        QCOMPARE(h_->frames.sampleCount(), 1);
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Complete);
        QCOMPARE(h_->frames.lastFrameWork().rows, 6);
        for (int band = 0; band < 7; ++band) h_->frames.renderFrame();
        QCOMPARE(h_->frames.sampleCount(), 2);
        QVERIFY(h_->frames.readImages().radiance == h_->reference.readImages().radiance);
    }

    // Tolerance: exact (bit for bit). The still mean's filter run in steps of rows between frames
    // (the viewport's denoise on a slow GL) gives the pixels of the filter run whole; no sample is
    // traced while it runs, and drawTo() keeps showing the last finished filtering until the new one
    // is whole, the sample cap's last one included.
    void denoiseStepsGiveTheWholeFilteringsPixels() {
        const RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        renderer::FrameSettings whole = settingsFor(renderer::Configuration::Accumulate);
        whole.denoise = true;
        whole.maxSamples = 2;
        const HostFramebuffer host(imageSize);
        h_->reference.setSettings(whole);
        h_->reference.setScene(room.scene);
        h_->reference.setCamera(camera);
        std::vector<std::vector<float>> filtered;
        std::vector<std::vector<unsigned char>> shown;
        for (int n = 1; n <= 2; ++n) {
            h_->reference.renderFrame();
            QVERIFY(!h_->reference.denoisePending()); // filtering whole: drawTo() does it
            QVERIFY(h_->reference.drawTo(host.framebuffer, imageSize, imageSize));
            shown.push_back(host.read());
            filtered.push_back(h_->reference.readImages().radiance);
        }

        renderer::FrameSettings stepped = whole;
        stepped.denoiseRowsPerFrame = 50; // 7 stages of 48 rows: 6 steps of 50 rows and one of 36
        h_->frames.setSettings(stepped);
        h_->frames.setScene(room.scene);
        h_->frames.setCamera(camera);
        for (int n = 1; n <= 2; ++n) {
            h_->frames.renderFrame();
            QCOMPARE(h_->frames.sampleCount(), n);
            for (int step = 0; step < 7; ++step) {
                QVERIFY(h_->frames.denoisePending());
                if (n == 2) { // the filtering of one sample stays up meanwhile
                    QVERIFY(h_->frames.drawTo(host.framebuffer, imageSize, imageSize));
                    QVERIFY(host.read() == shown[0]);
                }
                h_->frames.renderFrame();
                QCOMPARE(h_->frames.lastFrameWork().denoiseRows, step < 6 ? 50 : 36);
                QCOMPARE(h_->frames.lastFrameWork().rows, 0);
                QCOMPARE(h_->frames.sampleCount(), n);
            }
            QVERIFY(!h_->frames.denoisePending());
            QVERIFY(h_->frames.drawTo(host.framebuffer, imageSize, imageSize));
            QVERIFY(host.read() == shown[std::size_t(n - 1)]);
            QVERIFY(h_->frames.readImages().radiance == filtered[std::size_t(n - 1)]);
        }
        h_->frames.renderFrame(); // at the cap, filtered: nothing left to do
        QCOMPARE(h_->frames.lastFrameWork().rows + h_->frames.lastFrameWork().denoiseRows, 0);
    }

    // Tolerance: exact bytes. The outline of the selection over the drawn image at twice the
    // image's size: an output pixel takes the selection colour exactly where the object's mask (its
    // first hits' ids, readImages().objectId) differs one output pixel away, and keeps drawTo()'s
    // byte everywhere else; no node, nothing drawn. Drawn again unchanged (the kept line), and after
    // the camera moved (a new picture: the line follows the object).
    void outlinesTheSelectedObjectsEdgesAndNothingElse() {
        const RoomScene room = makeRoom();
        h_->frames.setSettings(settingsFor(renderer::Configuration::Accumulate));
        h_->frames.setScene(room.scene);
        h_->frame(cameraAt(room.scene, 0.0f));
        const int size = 2 * imageSize;
        const HostFramebuffer host(size);
        const GLuint target = host.framebuffer;
        const auto read = [&] { return host.read(); };
        const auto checkOutline = [&]() -> int { // edge pixels; -1 after a failure
            if (!h_->frames.drawTo(target, size, size)) return -1;
            const std::vector<unsigned char> plain = read();
            h_->frames.drawOutline(target, size, size, {});
            if (read() != plain) return -1;
            h_->frames.drawOutline(target, size, size, {room.occluder, NodeId{9999}});
            const std::vector<unsigned char> outlined = read();
            const std::vector<float> ids = h_->frames.readImages().objectId; // top-down
            const auto inside = [&](int x, int y) { // output pixel, rows bottom-up, clamped as the shader
                const int ix = std::clamp(x / 2, 0, imageSize - 1), iy = std::clamp(y / 2, 0, imageSize - 1);
                return ids[std::size_t(imageSize - 1 - iy) * imageSize + std::size_t(ix)] == float(room.occluder.value);
            };
            const unsigned char colour[3] = {255, 158, 41}; // renderer::selectionColour in 8 bits
            int edges = 0;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const bool here = inside(x, y);
                    const bool edge = inside(x + 1, y) != here || inside(x - 1, y) != here || inside(x, y + 1) != here || inside(x, y - 1) != here;
                    const std::size_t at = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4;
                    for (std::size_t c = 0; c < 3; ++c)
                        if (outlined[at + c] != (edge ? colour[c] : plain[at + c])) {
                            qWarning("pixel (%d, %d) channel %zu: %d", x, y, c, outlined[at + c]);
                            return -1;
                        }
                    edges += edge;
                }
            return edges;
        };
        const int edges = checkOutline();
        QVERIFY2(edges > 4 * 20, "the box's outline is drawn"); // the box spans about 7 x 12 image pixels
        QCOMPARE(checkOutline(), edges);
        h_->frame(cameraAt(room.scene, 0.3f));
        QVERIFY(checkOutline() > 4 * 20);
    }

    // Tolerance: exact sizes and stages. With a preview divisor the first frame after a change is a
    // low-resolution sample that drawTo() shows until the first full-resolution one is whole.
    void previewStandsInUntilTheFirstSample() {
        const RoomScene room = makeRoom();
        renderer::FrameSettings s = settingsFor(renderer::Configuration::Accumulate);
        s.rowsPerFrame = imageSize / 2;
        s.previewDivisor = 4;
        h_->frames.setSettings(s);
        h_->frames.setScene(room.scene);
        h_->frame(cameraAt(room.scene, 0.0f));
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Preview);
        QCOMPARE(h_->frames.lastFrameWork().previewRows, imageSize / 4);
        QVERIFY(h_->frames.previewShown());
        QVERIFY(h_->frames.drawTo(0, imageSize, imageSize));
        const renderer::FrameImages preview = h_->frames.readImages();
        QCOMPARE(preview.width, imageSize / 4);
        double sum = 0.0;
        for (std::size_t i = 0; i < preview.radiance.size(); i += 4) sum += preview.radiance[i + 1];
        QVERIFY2(sum > 0.0, "the preview shows the lit room");
        h_->frames.renderFrame();
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Refining);
        QVERIFY(h_->frames.drawTo(0, imageSize, imageSize)); // still the preview
        h_->frames.renderFrame();
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Complete);
        QVERIFY(!h_->frames.previewShown());
        QCOMPARE(h_->frames.readImages().width, imageSize);
        h_->frames.setCamera(cameraAt(room.scene, 0.2f)); // a change: the preview comes first again
        h_->frames.renderFrame();
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Preview);

        // Filtering in steps, the (filtered) preview stays until the first filtered mean replaces it.
        s.denoise = true;
        s.denoiseRowsPerFrame = 4 * imageSize;
        h_->frames.setSettings(s);
        for (int band = 0; band < 2; ++band) h_->frames.renderFrame();
        QCOMPARE(h_->frames.sampleCount(), 1);
        QVERIFY(h_->frames.denoisePending());
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Preview);
        QCOMPARE(h_->frames.readImages().width, imageSize / 4);
        h_->frames.renderFrame();
        QVERIFY(h_->frames.denoisePending()); // 7 stages: two steps
        QVERIFY(h_->frames.previewShown());
        h_->frames.renderFrame();
        QVERIFY(!h_->frames.denoisePending());
        QCOMPARE(h_->frames.imageStage(), renderer::ImageStage::Complete);
        QVERIFY(!h_->frames.previewShown());
        QCOMPARE(h_->frames.readImages().width, imageSize);
    }
};

QTEST_APPLESS_MAIN(TestFrameRendererHost)
#include "test_frame_renderer_host.moc"
