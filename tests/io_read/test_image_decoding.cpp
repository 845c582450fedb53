// Image headers probed without a library, and OpenImageIO decoding from memory with its caps.
#include "scene/io/image_decoder.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include "io_read_helpers.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace glint;
using namespace glint::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> readAll(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

const fs::path kSwatches = fs::path(GLINT_TEST_DATA_DIR) / "gltf/MorphStressTest/glTF/ColorSwatches.png"; // 64x64 RGB
const fs::path kArrow = fs::path(GLINT_TEST_DATA_DIR) / "gltf/TextureTransformTest/Arrow.png";             // 128x128 RGBA
const fs::path kHdr = fs::path(GLINT_TEST_DATA_DIR) / "env/studio_small_03_1k.hdr";                       // 1024x512

// SOI, an APP0 segment, then a baseline start-of-frame: precision, height, width, components.
std::vector<std::uint8_t> jpegHeader(std::uint16_t width, std::uint16_t height)
{
    std::vector<std::uint8_t> b = {0xFF, 0xD8, 0xFF, 0xE0, 0, 16, 'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1, 0, 1, 0, 0};
    const std::uint8_t frame[] = {0xFF, 0xC0, 0, 17, 8, std::uint8_t(height >> 8), std::uint8_t(height), std::uint8_t(width >> 8), std::uint8_t(width), 3};
    for (std::uint8_t v : frame) b.push_back(v);
    return b;
}

// The magic number, version, then attributes up to an empty name; only dataWindow matters here.
std::vector<std::uint8_t> exrHeader(std::int32_t xMax, std::int32_t yMax)
{
    std::vector<std::uint8_t> b = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    const std::string name = "dataWindow", type = "box2i";
    b.insert(b.end(), name.begin(), name.end());
    b.push_back(0);
    b.insert(b.end(), type.begin(), type.end());
    b.push_back(0);
    for (std::int32_t v : {16, 0, 0, xMax, yMax})
        for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(static_cast<std::uint32_t>(v) >> (8 * i)));
    b.push_back(0);
    return b;
}

} // namespace

class TestImageDecoding : public QObject {
    Q_OBJECT

private slots:
    void probesPng()
    {
        QCOMPARE(probeImageHeader(readAll(kArrow)), std::optional(ImageSize{128, 128}));
        QCOMPARE(probeImageHeader(pngHeader(65535, 65535)), std::optional(ImageSize{65535, 65535}));
    }

    void probesJpeg() { QCOMPARE(probeImageHeader(jpegHeader(640, 480)), std::optional(ImageSize{640, 480})); }

    void probesHdr() { QCOMPARE(probeImageHeader(readAll(kHdr)), std::optional(ImageSize{1024, 512})); }

    void probesExr() { QCOMPARE(probeImageHeader(exrHeader(299, 99)), std::optional(ImageSize{300, 100})); }

    void brokenHeadersGiveNothing()
    {
        std::vector<std::uint8_t> png = pngHeader(4, 4);
        png.resize(20);
        QVERIFY(!probeImageHeader(png));
        std::vector<std::uint8_t> jpeg = jpegHeader(8, 8);
        jpeg.resize(24);
        QVERIFY(!probeImageHeader(jpeg));
        std::vector<std::uint8_t> exr = exrHeader(9, 9);
        exr.resize(exr.size() - 10);
        QVERIFY(!probeImageHeader(exr));
        QVERIFY(!probeImageHeader(pngHeader(0, 4)));
        QVERIFY(!probeImageHeader(bytesOf("GIF89a")));
        QVERIFY(!probeImageHeader({}));
    }

    void decodesRgbPngWithOpaqueAlpha()
    {
        const OiioImageDecoder decoder;
        const DecodedImage<std::uint8_t> image = decoder.decode8(readAll(kSwatches), {});
        QVERIFY2(image.ok(), image.error.c_str());
        QCOMPARE(image.width, 64);
        QCOMPARE(image.height, 64);
        QCOMPARE(image.rgba.size(), std::size_t(64 * 64 * 4));
        auto pixel = [&](int x, int y) { const auto* p = &image.rgba[std::size_t(y * 64 + x) * 4]; return std::vector<int>{p[0], p[1], p[2], p[3]}; };
        QCOMPARE(pixel(0, 0), (std::vector<int>{229, 177, 22, 255}));
        QCOMPARE(pixel(20, 10), (std::vector<int>{22, 229, 34, 255}));
    }

    void decodesRgbaPngAsFloats()
    {
        const OiioImageDecoder decoder;
        const DecodedImage<float> image = decoder.decodeFloat(readAll(kArrow), {});
        QVERIFY2(image.ok(), image.error.c_str());
        QCOMPARE(image.rgba[0], 224.0f / 255.0f);
        QCOMPARE(image.rgba[3], 1.0f);
        const std::size_t centre = std::size_t(64 * 128 + 64) * 4;
        QCOMPARE(image.rgba[centre], 0.0f);
    }

    void decodesHdr()
    {
        const OiioImageDecoder decoder;
        QCOMPARE(decoder.probe(readAll(kHdr)), std::optional(ImageSize{1024, 512}));
        const DecodedImage<float> image = decoder.decodeFloat(readAll(kHdr), {});
        QVERIFY2(image.ok(), image.error.c_str());
        QCOMPARE(image.rgba.size(), std::size_t(1024 * 512 * 4));
        for (float v : image.rgba) QVERIFY(std::isfinite(v) && v >= 0.0f);
    }

    void refusesBeyondTheCapsBeforeDecoding()
    {
        const OiioImageDecoder decoder;
        DecodeLimits limits;
        limits.maxPixels = 1000;
        const DecodedImage<std::uint8_t> image = decoder.decode8(readAll(kSwatches), limits);
        QVERIFY(!image.ok());
        QCOMPARE(QString::fromStdString(image.error), QStringLiteral("image of 64x64 pixels exceeds the limits"));
        QVERIFY(image.rgba.empty());
    }

    void refusesGarbage()
    {
        const OiioImageDecoder decoder;
        QVERIFY(!decoder.decode8(bytesOf("not an image at all"), {}).ok());
        QVERIFY(!decoder.probe(bytesOf("not an image at all")));
    }

    void loaderUsesTheDecoderForFormatsTheProbeDoesNotKnow()
    {
        // A TIFF header is not probed by hand; with the OpenImageIO decoder its size is known.
        const OiioImageDecoder decoder;
        QTemporaryDir dir;
        const fs::path folder = dir.path().toStdString();
        const fs::path tiff = folder / "t.tif";
        QCOMPARE(std::system(("oiiotool --pattern constant:color=1,0,0 5x3 3 -o " + tiff.string() + " 2>/dev/null").c_str()) == 0, true);
        Json doc = triangle().finish();
        doc["images"] = Json::array({{{"uri", "t.tif"}}});
        LoadOptions options;
        const Image without = loadJson(doc, folder, options).scene.images.begin()->second;
        QVERIFY(without.missing);
        options.images = &decoder;
        const Image with = loadJson(doc, folder, options).scene.images.begin()->second;
        QVERIFY(!with.missing);
        QCOMPARE(with.width, 5);
        QCOMPARE(with.height, 3);
    }
};

QTEST_APPLESS_MAIN(TestImageDecoding)
#include "test_image_decoding.moc"
