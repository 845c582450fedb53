// glint render --region X,Y,W,H (docs/FARM.md "Render regions"): bad values are usage errors
// naming the option; EXR writes the region as the data window in the whole display window; 8-bit
// images keep the whole size, transparent outside; the region's pixels equal a full render's bit
// for bit (Accumulate); `glint encode` places a region frame in the whole frame; animations with
// history and shards take the region too, and --resume notices a changed region.
// Cornell box 40x32 (not square, so X/Y mix-ups show), seed 0, 2 spp.
#include "cli_runner.h"

#include "renderer/output/video_frame_image.h"

#include <OpenImageIO/imageio.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <vector>

namespace {

const QString cornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QString dolly = QStringLiteral(GLINT_RESOURCES_DIR "/farm/cornell_dolly.gltf"); // 1 s camera path
const QStringList small = {"--size", "40x32", "--spp", "2"};
constexpr int kX = 5, kY = 9, kW = 16, kH = 12; // the region: 5,9,16,12
const QString region = "5,9,16,12";

// An image as stored: its data window, display window, channels and pixels (data window only).
struct Stored {
    bool ok = false;
    OIIO::ImageSpec spec;
    std::vector<float> pixels;
    std::string attribute(const char* name) const { return spec.get_string_attribute(name); }
};

Stored readStored(const QString& file) {
    Stored s;
    auto in = OIIO::ImageInput::open(file.toStdString());
    if (!in) {
        (void)OIIO::geterror();
        return s;
    }
    s.spec = in->spec();
    s.pixels.resize(s.spec.image_pixels() * std::size_t(s.spec.nchannels));
    s.ok = in->read_image(0, 0, 0, s.spec.nchannels, OIIO::TypeDesc::FLOAT, s.pixels.data());
    return s;
}

// Every channel of `part` (a data window) against the same pixels of `whole`, bit for bit.
bool samePixels(const Stored& part, const Stored& whole) {
    const int n = part.spec.nchannels;
    if (n != whole.spec.nchannels || part.spec.channelnames != whole.spec.channelnames) return false;
    for (int y = 0; y < part.spec.height; ++y)
        for (int x = 0; x < part.spec.width; ++x) {
            const std::size_t from = (std::size_t(y) * std::size_t(part.spec.width) + std::size_t(x)) * std::size_t(n);
            const std::size_t at = (std::size_t(y + part.spec.y) * std::size_t(whole.spec.width) + std::size_t(x + part.spec.x)) *
                                   std::size_t(n);
            if (std::memcmp(&part.pixels[from], &whole.pixels[at], sizeof(float) * std::size_t(n)) != 0) return false;
        }
    return true;
}

bool insideRegion(int x, int y) { return x >= kX && x < kX + kW && y >= kY && y < kY + kH; }

} // namespace

class TestCliRegion : public QObject {
    Q_OBJECT
private slots:
    void badRegionsAreUsageErrors() {
        QTemporaryDir dir;
        const QString out = dir.filePath("r.exr");
        const QList<QPair<QString, QString>> cases = {
            {"-1,0,8,8", "X and Y must be 0 or more"},
            {"0,0,0,8", "the region is empty"},
            {"30,0,11,8", "reaches outside the 40x32 image"}, // X + W = 41
            {"abc", "expected X,Y,W,H"},
            {"1,2,3", "expected X,Y,W,H"},
        };
        for (const auto& [value, message] : cases) {
            const CliResult r = runGlint(QStringList{"render", cornell, "--out", out, "--region", value} + small);
            QVERIFY2(r.exitCode == 2, qPrintable(value + " -> " + QString::number(r.exitCode) + ": " + r.err));
            QVERIFY2(r.err.startsWith("glint: --region: ") && r.err.contains(message) && r.err.count('\n') == 1,
                     qPrintable(value + ": " + r.err));
        }
        QVERIFY(!QFile::exists(out));
        const CliResult help = runGlint({"render", "--help"});
        QVERIFY2(help.out.contains("--region") && help.out.contains("default: none, the whole image"), qPrintable(help.out));
    }

    void exrRegionIsTheDataWindowWithTheFullRendersPixels() {
        QTemporaryDir dir;
        const QStringList args = QStringList{"render", cornell, "--config", "accumulate", "--aovs",
                                             "albedo,normal,depth,id,variance"} + small;
        QCOMPARE(runGlint(args + QStringList{"--out", dir.filePath("full.exr")}).exitCode, 0);
        const CliResult r = runGlint(args + QStringList{"--out", dir.filePath("part.exr"), "--region", region});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Stored full = readStored(dir.filePath("full.exr")), part = readStored(dir.filePath("part.exr"));
        QVERIFY(full.ok && part.ok);
        const OIIO::ImageSpec& s = part.spec;
        QCOMPARE(QList<int>({s.x, s.y, s.width, s.height}), QList<int>({kX, kY, kW, kH}));
        QCOMPARE(QList<int>({s.full_x, s.full_y, s.full_width, s.full_height}), QList<int>({0, 0, 40, 32}));
        QVERIFY2(samePixels(part, full), "the region's pixels differ from the full render's (every channel, bit for bit)");
        QCOMPARE(part.attribute("glint:region"), std::string("5,9,16,12"));
        // glint encode's reader puts the region where it belongs in the whole frame, black around it.
        const glint::video::Rgba8Image frame = glint::video::loadFrameForVideo(dir.filePath("part.exr").toStdString());
        QCOMPARE(QList<int>({frame.width, frame.height}), QList<int>({40, 32}));
        const auto rgbAt = [&frame](int x, int y) {
            const std::size_t i = (std::size_t(y) * 40 + std::size_t(x)) * 4;
            return int(frame.pixels[i]) + frame.pixels[i + 1] + frame.pixels[i + 2];
        };
        QVERIFY2(rgbAt(kX - 1, kY) == 0 && rgbAt(kX + kW, kY + kH - 1) == 0 && rgbAt(kX, kY + kH) == 0, "not black outside");
        QVERIFY2(rgbAt(kX + kW / 2, kY + kH / 2) > 0, "the region is black in the video frame");
        QVERIFY(part.attribute("glint:settingsHash") != full.attribute("glint:settingsHash"));
    }

    void eightBitImagesKeepTheSizeTransparentOutside() {
        QTemporaryDir dir;
        const QStringList args = QStringList{"render", cornell, "--config", "accumulate"} + small;
        QCOMPARE(runGlint(args + QStringList{"--out", dir.filePath("full.png")}).exitCode, 0);
        QCOMPARE(runGlint(args + QStringList{"--out", dir.filePath("part.png"), "--region", region}).exitCode, 0);
        const Stored full = readStored(dir.filePath("full.png")), part = readStored(dir.filePath("part.png"));
        QVERIFY(full.ok && part.ok);
        QCOMPARE(QList<int>({part.spec.x, part.spec.y, part.spec.width, part.spec.height, part.spec.nchannels}),
                 QList<int>({0, 0, 40, 32, 4}));
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 40; ++x)
                for (int c = 0; c < 4; ++c) {
                    const std::size_t i = (std::size_t(y) * 40 + std::size_t(x)) * 4 + std::size_t(c);
                    const float expected = insideRegion(x, y) ? full.pixels[i] : 0.0f; // exact: 8-bit values
                    QVERIFY2(part.pixels[i] == expected, qPrintable(QString("pixel %1,%2 channel %3").arg(x).arg(y).arg(c)));
                }
    }

    // A history chunk in a shard takes the region. Realistic (TAA) reads 4 pixels around a pixel,
    // so its margin leaves an outside here: the shard's frames equal the same region rendered in
    // one run bit for bit (history is reset, and the outside zeroed, at every chunk start). (The
    // margin rule against full frames: tests/renderer/test_render_region.cpp.) --resume keeps
    // them, and renders them again for another region.
    void animationShardsTakeTheRegionAndResumeNoticesAChange() {
        QTemporaryDir dir;
        const QStringList base = {"render", dolly, "--animation", "--size", "40x32", "--config", "realistic", "--chunk",
                                  "2", "--warmup", "1", "--frames", "0-3", "--aovs", "none"};
        QCOMPARE(runGlint(base + QStringList{"--out", dir.filePath("one_####.exr"), "--region", region}).exitCode, 0);
        const QStringList shard = base + QStringList{"--shard", "1/2", "--out", dir.filePath("part_####.exr"), "--region"};
        const CliResult first = runGlint(shard + QStringList{region});
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QVERIFY(!QFile::exists(dir.filePath("part_0000.exr")) && !QFile::exists(dir.filePath("part_0001.exr")));
        for (const char* n : {"0002", "0003"}) {
            const Stored one = readStored(dir.filePath(QString("one_%1.exr").arg(n)));
            const Stored part = readStored(dir.filePath(QString("part_%1.exr").arg(n)));
            QVERIFY(one.ok && part.ok && part.spec.x == kX && part.spec.y == kY && part.spec.full_width == 40);
            QVERIFY2(part.pixels == one.pixels, qPrintable(QString("frame %1: the shard differs from one run").arg(n)));
        }
        QCOMPARE(runGlint(shard + QStringList{region}).err.count(" kept: "), 2);
        const CliResult moved = runGlint(shard + QStringList{"6,9,16,12"});
        QVERIFY2(moved.exitCode == 0 && moved.err.count(" kept: ") == 0, qPrintable(moved.err));
        QCOMPARE(readStored(dir.filePath("part_0003.exr")).spec.x, 6);
    }
};

QTEST_GUILESS_MAIN(TestCliRegion)
#include "test_cli_region.moc"
