// FrameRenderer as a host sees it: it draws into the framebuffer it is given (not 0), puts the
// caller's framebuffer, viewport, vertex array and enables back, and keeps accumulating through exposure and
// tonemapper changes.
#include "reconstruction_fixture.h"

#include <epoxy/gl.h>

#include <QtTest>

using namespace glint;
using namespace glint::test;

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

        GLuint texture = 0, target = 0, other = 0;
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, imageSize, imageSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glGenFramebuffers(1, &target);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
        QCOMPARE(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
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

        std::vector<unsigned char> pixels(static_cast<std::size_t>(imageSize * imageSize * 4));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target);
        glReadPixels(0, 0, imageSize, imageSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        const auto expected = h_->frames.readImages().tonemapped; // top-down
        for (int y = 0; y < imageSize; ++y)
            for (int x = 0; x < imageSize * 4; ++x)
                QCOMPARE(pixels[static_cast<std::size_t>((imageSize - 1 - y) * imageSize * 4 + x)],
                         expected[static_cast<std::size_t>(y * imageSize * 4 + x)]);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &target);
        glDeleteFramebuffers(1, &other);
        glDeleteTextures(1, &texture);
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
};

QTEST_APPLESS_MAIN(TestFrameRendererHost)
#include "test_frame_renderer_host.moc"
