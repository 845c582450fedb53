// The environment map: orientation as docs/UNITS.md "Environment" says, rotation, and importance
// sampling with MIS giving the irradiance integral. The HDR is tests/data/env (see its LICENSES.md).
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"
#include "renderer_twin/bilinear_map_read.h"

#include "renderer/gpu_scene/environment_cube.h"
#include "renderer/gpu_scene/environment_image.h"
#include "renderer/offline_render.h"
#include "scene/core/diagnostics.h"

#include <OpenImageIO/imageio.h>

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::test;

namespace {

const std::filesystem::path hdr = std::filesystem::path(GLINT_TEST_DATA_DIR) / "env" / "studio_small_03_1k.hdr";

// The green channel of the map as the path tracer reads it at (u, v).
double bilinearGreen(const renderer::EnvironmentImage& image, double u, double v) {
    return bilinearMapRead(image.rgb, image.width, image.height, u, v, {0.0, 1.0, 0.0});
}

// The map's green irradiance on an upward-facing plane: its read times cos(theta) over the upper
// hemisphere, summed at sub x sub points per texel (sub = 1: at the texel centres, where the read is
// the texel itself, so the map summed as stored).
double upwardIrradiance(const renderer::EnvironmentImage& image, int sub) {
    double irradiance = 0.0;
    for (int row = 0; row < image.height * sub / 2; ++row) {
        const double v = (row + 0.5) / (image.height * sub), theta = v * M_PI;
        const double solidAngle = (2 * M_PI / (image.width * sub)) * (M_PI / (image.height * sub)) * std::sin(theta);
        for (int column = 0; column < image.width * sub; ++column)
            irradiance += bilinearGreen(image, (column + 0.5) / (image.width * sub), v) * std::cos(theta) * solidAngle;
    }
    return irradiance;
}

// Cube faces in the order +X, -X, +Y, -Y, +Z, -Z (cube-map names): a colour each, and on +Z a left
// half in red and a right half in blue, which tells a mirrored map from a right one.
constexpr float kFaceGreen[6] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};

std::array<float, 3> faceColour(int face, double s) {
    if (face == 4) return s < 0.5 ? std::array<float, 3>{1.0f, kFaceGreen[4], 0.0f} : std::array<float, 3>{0.0f, kFaceGreen[4], 1.0f};
    return {0.0f, kFaceGreen[face], 0.0f};
}

// Writes the six faces (side n) in `layout` as an EXR: crosses with their empty cells black.
std::filesystem::path writeCube(const std::filesystem::path& folder, renderer::CubeLayout layout, int n) {
    struct Cell { int column, row; bool rotated; };
    std::array<Cell, 6> cells{};
    int columns = 0, rows = 0;
    switch (layout) {
    case renderer::CubeLayout::HorizontalCross: cells = {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}}; columns = 4; rows = 3; break;
    case renderer::CubeLayout::VerticalCross: cells = {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}}; columns = 3; rows = 4; break;
    case renderer::CubeLayout::HorizontalStrip: for (int f = 0; f < 6; ++f) cells[std::size_t(f)] = {f, 0, false}; columns = 6; rows = 1; break;
    case renderer::CubeLayout::VerticalStrip: for (int f = 0; f < 6; ++f) cells[std::size_t(f)] = {0, f, false}; columns = 1; rows = 6; break;
    }
    const int width = columns * n, height = rows * n;
    std::vector<float> rgb(std::size_t(width) * std::size_t(height) * 3, 0.0f);
    for (int f = 0; f < 6; ++f)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Cell c = cells[std::size_t(f)];
                const int fi = c.rotated ? n - 1 - i : i; // the face's column stored here
                const auto colour = faceColour(f, (fi + 0.5) / n);
                const std::size_t at = (std::size_t(c.row * n + j) * std::size_t(width) + std::size_t(c.column * n + i)) * 3;
                std::copy(colour.begin(), colour.end(), rgb.begin() + std::ptrdiff_t(at));
            }
    const std::filesystem::path file = folder / ("cube" + std::to_string(int(layout)) + ".exr");
    auto out = OIIO::ImageOutput::create(file.string());
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    if (!out || !out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close()) return {};
    return file;
}

// A 64 x 32 map of an even sky (0.05) with a sun of 1000 in the one pixel (40, 8), about 42
// degrees up, as a float EXR.
std::filesystem::path writeSunInOnePixel(const std::filesystem::path& folder) {
    const int width = 64, height = 32;
    std::vector<float> rgb(std::size_t(width * height * 3), 0.05f);
    for (int c = 0; c < 3; ++c) rgb[std::size_t((8 * width + 40) * 3 + c)] = 1000.0f;
    const std::filesystem::path file = folder / "sun.exr";
    auto out = OIIO::ImageOutput::create(file.string());
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    if (!out || !out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close()) return {};
    return file;
}

} // namespace

class TestRenderEnvironment : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        renderer::RenderRequest request = test::stillRequest(size, spp, seed, bounces);
        request.envFile = hdr;
        return renderer_->render(scene, request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 4x4, 1 spp, seed 0, a 0.001 rad field of view: each view direction d must show the map at
    // u = 0.5 + atan2(z, x) / 2pi, v = acos(y) / pi (and, rotated by 90 degrees about +Y, at the
    // direction turned back by -90 degrees). Tolerance 1 % of the bilinear value.
    // Image bombs found by fuzz_image_decode (tests/fuzz/seeds/image_decode): a 7 x 38661 image,
    // whose sampling table (quadratic in the height) asked for 6 GB, and a Radiance header declaring
    // 65535 x 65535 pixels; both refused before anything is allocated, naming the file and the limit.
    void environmentsBeyondTheLimitsAreRefused() {
        const std::string seeds = GLINT_TEST_DATA_DIR "/../fuzz/seeds/image_decode/";
        for (const std::string name : {"crash-environment-tall-sampling-table.tif", "bomb-65535x65535.hdr"}) {
            try {
                renderer::loadEnvironmentImage(seeds + name);
                QFAIL(name.c_str());
            } catch (const FileError& e) {
                QCOMPARE(e.code(), std::string("environment-too-large"));
                QCOMPARE(e.file(), seeds + name);
                QVERIFY2(e.message().find("more than the limit") != std::string::npos, e.what());
            }
        }
    }

    // A JPEG environment is read as textures are, from memory without its metadata: these files'
    // broken IPTC blocks made OpenImageIO 2.4 read past a buffer (found by fuzz_image_decode). Their
    // pixels are whole, and load as the in-memory path decodes them.
    void jpegEnvironmentsLoadWithoutTheirMetadata() {
        const std::string seeds = GLINT_TEST_DATA_DIR "/../fuzz/seeds/image_decode/";
        for (const std::string name : {"crash-jpeg-iptc-past-its-segment.jpg", "crash-jpeg-iptc-after-a-scan.jpg", "metadata.jpg"}) {
            const renderer::EnvironmentImage loaded = renderer::loadEnvironmentImage(seeds + name);
            std::ifstream in(seeds + name, std::ios::binary);
            const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const renderer::EnvironmentImage decoded = renderer::decodeEnvironmentImage(bytes, name);
            QCOMPARE(loaded.width, 8);
            QCOMPARE(loaded.height, 8);
            QVERIFY2(loaded.rgb == decoded.rgb, name.c_str());
        }
    }

    // An OpenEXR header longer than the first bytes Glint reads before opening a file: fuzz_image_decode's
    // seed with a second data window 7,995,396 pixels wide (DWAA, 32 lines a chunk), behind a 300 KiB
    // comment. OpenEXR takes the last data window, and OpenImageIO opened the file with it; the whole
    // header is checked now, and the file refused before OpenEXR opens it.
    void longOpenExrHeadersAreCheckedWhole() {
        std::ifstream in(GLINT_TEST_DATA_DIR "/../fuzz/seeds/image_decode/crash-exr-second-data-window-dwaa.exr", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        using namespace std::string_literals; // names and types end in a zero byte
        const std::string dataWindow = "dataWindow\0box2i\0"s;
        const std::size_t second = bytes.find(dataWindow, bytes.find(dataWindow) + 1);
        QVERIFY(second != std::string::npos);
        const std::uint32_t commentBytes = 300 * 1024;
        std::string comment = "comments\0string\0"s;
        for (int shift = 0; shift < 32; shift += 8) comment += char((commentBytes >> shift) & 0xFFu);
        comment += std::string(commentBytes, 'x');
        bytes.insert(second, comment);
        QTemporaryDir dir;
        const std::string file = dir.filePath("long-header.exr").toStdString();
        std::ofstream(file, std::ios::binary) << bytes;
        try {
            renderer::loadEnvironmentImage(file);
            QFAIL("a long header's second data window was not seen");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("environment-too-large"));
            QCOMPARE(e.file(), file);
            QVERIFY2(e.message().find("7995396x32 pixels") != std::string::npos, e.what());
        }
    }

    // A file Glint reads whole is held to twice the decode limit first: here 1 MiB, and a Radiance
    // header of 8 x 4 pixels with 2 MiB and one byte of data behind it.
    void environmentFilesBeyondTwiceTheLimitAreRefusedByTheirSize() {
        QTemporaryDir dir;
        const std::string file = dir.filePath("padded.hdr").toStdString();
        std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
        bytes.resize(2 * 1024 * 1024 + 1, '\x7f');
        std::ofstream(file, std::ios::binary) << bytes;
        DecodeLimits limits;
        limits.maxBytes = 1024 * 1024;
        try {
            renderer::loadEnvironmentImage(file, limits);
            QFAIL("a file beyond twice the limit was read");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("environment-too-large"));
            QVERIFY2(e.message().find("the file holds 2097153 bytes, more than twice the 1048576 bytes") != std::string::npos, e.what());
        }
    }

    void orientationFollowsTheContract_data() {
        QTest::addColumn<float>("x");
        QTest::addColumn<float>("y");
        QTest::addColumn<float>("z");
        QTest::addColumn<float>("rotation");
        QTest::newRow("+X is the centre") << 1.0f << 0.0f << 0.0f << 0.0f;
        QTest::newRow("-Z is u = 0.25") << 0.0f << 0.0f << -1.0f << 0.0f;
        QTest::newRow("+Z is u = 0.75") << 0.0f << 0.0f << 1.0f << 0.0f;
        QTest::newRow("up 60 degrees") << 0.5f << 0.866f << 0.0f << 0.0f;
        QTest::newRow("rotated 90: -Z shows +X") << 0.0f << 0.0f << -1.0f << 90.0f;
    }
    void orientationFollowsTheContract() {
        QFETCH(float, x);
        QFETCH(float, y);
        QFETCH(float, z);
        QFETCH(float, rotation);
        Scene scene;
        scene.settings.environment.rotationDegrees = rotation;
        addPerspectiveCamera(scene, glm::vec3(0.0f), glm::vec3(x, y, z), 0.001f);
        const auto out = render(scene, 4, 1, 0, 0);
        const auto image = renderer::loadEnvironmentImage(hdr);
        const double angle = glm::radians(-rotation); // the map turns by +rotation: look up at -rotation
        const glm::dvec3 d = glm::normalize(glm::dvec3(std::cos(angle) * x + std::sin(angle) * z, y, -std::sin(angle) * x + std::cos(angle) * z));
        const double expected = bilinearGreen(image, 0.5 + std::atan2(d.z, d.x) / (2 * M_PI), std::acos(d.y) / M_PI);
        const double actual = channelStats(out.radiance, 1).mean;
        QVERIFY2(std::abs(actual - expected) < 0.01 * expected, qPrintable(QString("%1 vs %2").arg(actual).arg(expected)));
    }

    // Cube maps in every layout: looking along each world axis through a 0.001 rad view shows the face
    // docs/UNITS.md names (+X, +Y as glTF's; the cube's +Z in front of the default camera, towards
    // glTF's -Z), and a view a little right of the default camera's shows +Z's right (blue) half.
    void cubeMapsFaceTheirNamedDirections_data() {
        QTest::addColumn<int>("layout");
        QTest::newRow("horizontal cross") << int(renderer::CubeLayout::HorizontalCross);
        QTest::newRow("vertical cross") << int(renderer::CubeLayout::VerticalCross);
        QTest::newRow("horizontal strip") << int(renderer::CubeLayout::HorizontalStrip);
        QTest::newRow("vertical strip") << int(renderer::CubeLayout::VerticalStrip);
    }
    void cubeMapsFaceTheirNamedDirections() {
        QFETCH(int, layout);
        QTemporaryDir dir;
        const auto file = writeCube(dir.path().toStdString(), renderer::CubeLayout(layout), 16);
        QVERIFY(!file.empty());
        const renderer::EnvironmentImage loaded = renderer::loadEnvironmentImage(file);
        QCOMPARE(loaded.width, 64); // read as a latitude-longitude map 4 faces wide, 2 high
        QCOMPARE(loaded.height, 32);
        struct View { glm::vec3 direction; int face; };
        const View views[] = {{{1, 0, 0}, 0}, {{-1, 0, 0}, 1}, {{0, 1, 0}, 2}, {{0, -1, 0}, 3}, {{0, 0, -1}, 4}, {{0, 0, 1}, 5}};
        for (const View& v : views) {
            Scene scene;
            addPerspectiveCamera(scene, glm::vec3(0.0f), v.direction, 0.001f);
            renderer::RenderRequest request = test::stillRequest(4, 1, 0, 0);
            request.envFile = file;
            const double green = channelStats(renderer_->render(scene, request).radiance, 1).mean;
            QVERIFY2(std::abs(green - kFaceGreen[v.face]) < 1e-3, qPrintable(QString("face %1: %2").arg(v.face).arg(green)));
        }
        Scene scene;
        addPerspectiveCamera(scene, glm::vec3(0.0f), glm::vec3(0.3f, 0.0f, -1.0f), 0.001f);
        renderer::RenderRequest request = test::stillRequest(4, 1, 0, 0);
        request.envFile = file;
        const auto out = renderer_->render(scene, request);
        QVERIFY(channelStats(out.radiance, 2).mean > 0.99 && channelStats(out.radiance, 0).mean < 0.01); // blue, not red
    }

    // A sun in one pixel of a small map lights a white Lambert ground plane (16x16 pixels, 64 spp,
    // seed 3, 0 bounces, orthographic view from above). The map is read bilinearly, so the sun's
    // light reaches into its eight neighbours; light sampling must cover them, or BSDF rays find them
    // as fireflies. Expected radiance: 1/pi x the bilinear map's cos-weighted integral over the upper
    // hemisphere (8x8 points per texel). Mean within 2 %, and the brightest pixel under 1.5x the
    // mean (1.25x here). The old table (each texel weighted by itself) gave 4.9x and a mean 5 % low.
    void aSunInOnePixelLightsWithoutFireflies() {
        QTemporaryDir dir;
        const auto file = writeSunInOnePixel(dir.path().toStdString());
        QVERIFY(!file.empty());
        Scene scene;
        const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
        addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        renderer::RenderRequest request = test::stillRequest(16, 64, 3, 0);
        request.envFile = file;
        const auto out = renderer_->render(scene, request);
        const double irradiance = upwardIrradiance(renderer::loadEnvironmentImage(file), 8);
        const double expected = irradiance / M_PI;
        const ChannelStats green = channelStats(out.radiance, 1);
        QVERIFY2(std::abs(green.mean - expected) < 0.02 * expected, qPrintable(QString("%1 vs %2").arg(green.mean).arg(expected)));
        QVERIFY2(green.maximum < 1.5 * green.mean, qPrintable(QString("brightest pixel %1 times the mean").arg(green.maximum / green.mean)));
    }

    // 16x16, 256 spp, seed 7, 0 bounces. An orthographic camera looks down on a white Lambert ground
    // plane lit by the map alone: L = 1/pi * integral over the upper hemisphere of L_env cos(theta),
    // summed on the CPU over the map's texels (piecewise constant). Mean within 2 %.
    void lambertPlaneIntegratesTheMap() {
        Scene scene;
        const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
        addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        const auto out = render(scene, 16, 256, 7, 0);
        const double irradiance = upwardIrradiance(renderer::loadEnvironmentImage(hdr), 1);
        const double expected = irradiance / M_PI;
        const double actual = channelStats(out.radiance, 1).mean;
        QVERIFY2(std::abs(actual - expected) < 0.02 * expected, qPrintable(QString("%1 vs %2").arg(actual).arg(expected)));
    }
};

QTEST_APPLESS_MAIN(TestRenderEnvironment)
#include "test_render_environment.moc"
