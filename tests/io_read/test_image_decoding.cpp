// Image headers probed without a library, and OpenImageIO decoding from memory with its caps.
#include "scene/io/image_decoder.h"
#include "scene/io/jpeg_segments.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include "io_read_helpers.h"

#include <OpenImageIO/imageio.h>

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
const fs::path kBombs = fs::path(GLINT_FUZZ_SEEDS_DIR) / "image_decode";

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
        QCOMPARE(QString::fromStdString(image.error), QStringLiteral("the image declares 64x64 pixels, more than the limit of 1000 pixels"));
        QVERIFY(image.rgba.empty());
        limits = {};
        limits.maxBytes = 10000;
        QCOMPARE(QString::fromStdString(decoder.decode8(readAll(kSwatches), limits).error),
                 QStringLiteral("the image declares 64x64 pixels x 4 channels (1 MiB decoded), more than the limit of 1 MiB"));
    }

    // Image bombs (docs/RELIABILITY.md): a few bytes declaring a huge image, refused on Glint's own
    // reading of the header before OpenImageIO opens them (libjpeg, libpng and OpenEXR allocate for
    // what a header declares on opening), or on the opened spec before any pixel is read (a TIFF
    // strip). The files are the fuzz target's regression inputs.
    void imageBombsAreRefusedBeforeOpening_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("error");
        QTest::newRow("png") << "bomb-65535x65535.png" << "the image declares 65535x65535 pixels, more than the limit of 268435456 pixels";
        QTest::newRow("hdr") << "bomb-65535x65535.hdr" << "the image declares 65535x65535 pixels, more than the limit of 268435456 pixels";
        QTest::newRow("exr window") << "bomb-65535x65535.exr" << "the OpenEXR header declares 4096 chunks, more than the file can hold";
        QTest::newRow("progressive jpeg") << "crash-progressive-jpeg-65500x65500.jpg"
                                          << "the image declares 65500x65500 pixels, more than the limit of 268435456 pixels";
        QTest::newRow("jpeg frame after garbage") << "crash-jpeg-frame-after-garbage.jpg"
                                                  << "the image declares 65500x65500 pixels, more than the limit of 268435456 pixels";
        QTest::newRow("jpeg frame after an empty app1") << "crash-jpeg-frame-after-empty-app1.jpg"
                                                        << "the image declares 65500x65500 pixels, more than the limit of 268435456 pixels";
        QTest::newRow("exr attribute size") << "crash-exr-attribute-size-bomb.exr" << "declares";
        QTest::newRow("exr channel list") << "crash-exr-channel-list-overrun.exr" << "the OpenEXR attribute 'channels' (chlist) does not end where it says";
        QTest::newRow("tiff strip") << "crash-tiff-strip-taller-than-image.tif"
                                    << "the image declares tiles or strips of 65524x10784 pixels, more than the limit of 268435456 pixels";
    }

    void imageBombsAreRefusedBeforeOpening()
    {
        QFETCH(QString, file);
        QFETCH(QString, error);
        const std::vector<std::uint8_t> bytes = readAll(kBombs / file.toStdString());
        QVERIFY(!bytes.empty());
        const OiioImageDecoder decoder;
        const DecodedImage<std::uint8_t> image = decoder.decode8(bytes, {});
        QVERIFY(!image.ok());
        QVERIFY2(QString::fromStdString(image.error).contains(error), image.error.c_str());
        QVERIFY(!decoder.decodeFloat(bytes, {}).ok());
    }

    // OpenEXR allocates a buffer for one chunk when it opens a file, whatever the image's size: a
    // 16x16 image declaring tiles of 47112x2048 made it ask for 578 MB (fuzz_image_decode). The
    // chunk is held to the limits on the header, before OpenImageIO opens the file.
    void exrTileBeyondTheLimitsIsRefusedBeforeOpening()
    {
        const std::vector<std::uint8_t> bytes = readAll(kBombs / "crash-exr-tile-47112x2048.exr");
        QVERIFY(!bytes.empty());
        QCOMPARE(probeImageHeader(bytes), std::optional(ImageSize{16, 16}));
        const std::optional<ExrChunkShape> tile = probeExrChunk(bytes);
        QVERIFY(tile);
        QCOMPARE(tile->width, std::int64_t(47112));
        QCOMPARE(tile->height, std::int64_t(2048));
        QCOMPARE(tile->channels, std::int64_t(3));
        QCOMPARE(tile->bytesPerValue, std::size_t(2)); // half
        DecodeLimits limits;
        limits.maxBytes = 64u << 20;
        const OiioImageDecoder decoder;
        QCOMPARE(QString::fromStdString(decoder.decodeFloat(bytes, limits).error),
                 QStringLiteral("the image declares tiles or strips of 47112x2048 pixels x 3 channels (1105 MiB decoded), more than the limit of 64 MiB"));
        QCOMPARE(probeExrChunk(readAll(kBombs / "tiled.exr"))->width, std::int64_t(8));
        const std::optional<ExrChunkShape> scanlines = probeExrChunk(readAll(kBombs / "piz.exr")); // 4 wide, 32 lines a chunk
        QVERIFY(scanlines);
        QCOMPARE(scanlines->width, std::int64_t(4));
        QCOMPARE(scanlines->height, std::int64_t(32));
    }

    // A scanline file's chunk is its width by its compression's lines (16 for ZIP, OpenEXR's default
    // without the attribute; 32 for DWAA). These 4-line files repeat dataWindow, and OpenEXR takes
    // the last: 16,187,396 and 7,995,396 pixels wide, for which it asked for 2 GB on opening
    // (fuzz_image_decode). The probes take the last value too.
    void exrChunkOfTheLastDataWindowIsHeldToTheLimits_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("lines");
        QTest::newRow("zip by default") << "crash-exr-second-data-window-16187396-wide.exr" << 16187396 << 16;
        QTest::newRow("dwaa") << "crash-exr-second-data-window-dwaa.exr" << 7995396 << 32;
    }
    void exrChunkOfTheLastDataWindowIsHeldToTheLimits()
    {
        QFETCH(QString, file);
        QFETCH(int, width);
        QFETCH(int, lines);
        const std::vector<std::uint8_t> bytes = readAll(kBombs / file.toStdString());
        QCOMPARE(probeImageHeader(bytes), std::optional(ImageSize{width, 4}));
        const std::optional<ExrChunkShape> chunk = probeExrChunk(bytes);
        QVERIFY(chunk);
        QCOMPARE(chunk->width, std::int64_t(width));
        QCOMPARE(chunk->height, std::int64_t(lines));
        QCOMPARE(chunk->channels, std::int64_t(4));
        DecodeLimits limits;
        limits.maxBytes = 64u << 20;
        const QString error = QString::fromStdString(OiioImageDecoder().decode8(bytes, limits).error);
        QVERIFY2(error.startsWith(QStringLiteral("the image declares tiles or strips of %1x%2 pixels x 4 channels").arg(width).arg(lines)),
                 qPrintable(error));
    }

    // Valid files pass the header checks and decode: the one in the test data, and OpenEXR's
    // layouts written here (scanline ZIP, PIZ and DWAB, tiled, 23 channels, string attributes).
    void validImagesPassTheHeaderChecks()
    {
        QTemporaryDir dir;
        std::vector<fs::path> files = {kSwatches, kArrow, kHdr, fs::path(GLINT_TEST_DATA_DIR) / "renderer/cornell_box_128_4b.exr"};
        const auto write = [&](const std::string& name, int channels, const std::string& compression, int tile) {
            OIIO::ImageSpec spec(37, 19, channels, OIIO::TypeDesc::HALF);
            spec.attribute("compression", compression);
            spec.attribute("glint:settingsHash", "0123456789abcdef");
            spec.attribute("Software", "Glint test");
            std::vector<std::string> names;
            for (int c = 0; c < channels; ++c) names.push_back(c < 4 ? std::string(1, "RGBA"[c]) : "aov" + std::to_string(c) + ".X");
            spec.channelnames = names;
            if (tile) { spec.tile_width = tile; spec.tile_height = tile; }
            const fs::path path = fs::path(dir.path().toStdString()) / name;
            auto out = OIIO::ImageOutput::create(path.string());
            QVERIFY(out && out->open(path.string(), spec));
            std::vector<float> pixels(std::size_t(37 * 19 * channels), 0.5f);
            QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
            QVERIFY(out->close());
            files.push_back(path);
        };
        write("zip.exr", 4, "zip", 0);
        write("piz.exr", 3, "piz", 0);
        write("dwab.exr", 3, "dwab", 0);
        write("aovs.exr", 23, "zip", 0);
        write("tiled.exr", 4, "zip", 8);
        const OiioImageDecoder decoder;
        for (const fs::path& file : files) {
            const std::vector<std::uint8_t> bytes = readAll(file);
            QVERIFY2(headerLimitError(bytes, bytes.size(), 4, 4, {}).empty(), file.c_str());
            const DecodedImage<float> image = decoder.decodeFloat(bytes, {});
            QVERIFY2(image.ok(), (file.string() + ": " + image.error).c_str());
        }
    }

    // OpenImageIO 2.4's IOMemReader reads before its buffer at an offset between -size and 0; a
    // corrupt OpenEXR offset table (the seed below) asked for -1.
    void boundedReaderReadsNothingOutsideItsBuffer()
    {
        const std::string bytes = "abcdefgh";
        BoundedMemReader reader(bytes.data(), bytes.size());
        char out[4] = {};
        QCOMPARE(reader.pread(out, 4, -1), std::size_t(0));
        QCOMPARE(reader.pread(out, 4, -3), std::size_t(0));
        QCOMPARE(reader.pread(out, 4, 8), std::size_t(0));
        QCOMPARE(reader.pread(out, 4, 6), std::size_t(2));
        QCOMPARE(std::string(out, 2), std::string("gh"));
        QCOMPARE(reader.pread(out, 4, 0), std::size_t(4));
        QCOMPARE(std::string(out, 4), std::string("abcd"));
        QVERIFY(reader.seek(-1));
        QCOMPARE(reader.read(out, 4), std::size_t(0));
    }

    void exrWithAnOffsetBeforeTheFileIsRefused()
    {
        const std::vector<std::uint8_t> bytes = readAll(kBombs / "crash-exr-offset-before-buffer.exr");
        QVERIFY(!bytes.empty());
        const OiioImageDecoder decoder;
        const DecodedImage<float> image = decoder.decodeFloat(bytes, {});
        QVERIFY(!image.ok());
        QVERIFY2(QString::fromStdString(image.error).contains("OpenEXR"), image.error.c_str());
    }

    // OpenImageIO 2.4 parses a JPEG's metadata while it opens the file, and its IPTC parser reads
    // past the end of a broken segment (the seed below, found by fuzz_image_decode). Glint opens a
    // JPEG without its metadata: none of it reaches the spec, and the pixels are OpenImageIO's own.
    void jpegIsOpenedWithoutItsMetadata()
    {
        const fs::path file = kBombs / "metadata.jpg"; // 8x8, with Exif, IPTC and a comment
        const MemoryImage ours = openImageFromMemory(readAll(file));
        const std::unique_ptr<OIIO::ImageInput> theirs = OIIO::ImageInput::open(file.string());
        QVERIFY(ours.input && theirs);
        QVERIFY(theirs->spec().find_attribute("IPTC:Caption") && theirs->spec().find_attribute("Exif:ExifVersion") &&
                theirs->spec().find_attribute("ImageDescription"));
        for (const OIIO::ParamValue& attribute : ours.input->spec().extra_attribs) {
            const std::string name = attribute.name().string();
            QVERIFY2(!name.starts_with("Exif:") && !name.starts_with("IPTC:") && name != "ImageDescription", name.c_str());
        }
        QCOMPARE(ours.input->spec().width, 8);
        std::vector<std::uint8_t> a(8 * 8 * 3), b(8 * 8 * 3, 1);
        QVERIFY(ours.input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, a.data()));
        QVERIFY(theirs->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, b.data()));
        QVERIFY(a == b);

        // Their pixels are whole: only their metadata is broken (an IPTC block before the first scan, and one after it).
        for (const char* name : {"crash-jpeg-iptc-past-its-segment.jpg", "crash-jpeg-iptc-after-a-scan.jpg"}) {
            const DecodedImage<std::uint8_t> broken = OiioImageDecoder().decode8(readAll(kBombs / name), {});
            QVERIFY2(broken.ok(), (name + (": " + broken.error)).c_str());
            QCOMPARE(broken.width, 8);
        }
    }

    // Segments are found as libjpeg finds them, scans' entropy-coded data included (a stuffed 0xFF00
    // and a restart marker are data; metadata may follow a scan in a progressive file). The metadata
    // segments go; the rest stays byte for byte, bar garbage and fill bytes between segments.
    void jpegWithoutMetadataKeepsEverythingElse()
    {
        const std::vector<std::uint8_t> soi = {0xFF, 0xD8}, jfif = {0xFF, 0xE0, 0, 4, 'J', 'F'}, garbage = {0x12, 0x34},
                                         exif = {0xFF, 0xE1, 0, 4, 'E', 'x'}, comment = {0xFF, 0xFE, 0, 3, 'c'},
                                         adobe = {0xFF, 0xEE, 0, 3, 'A'}, fill = {0xFF}, table = {0xFF, 0xDB, 0, 3, 7},
                                         restart = {0xFF, 0xD0}, iptc = {0xFF, 0xED, 0, 3, 'P'},
                                         scan = {0xFF, 0xDA, 0, 3, 1, 0x55, 0xFF, 0x00, 0x66, 0xFF, 0xD0, 0x77},
                                         lastScan = {0xFF, 0xDA, 0, 3, 2, 0x88}, eoi = {0xFF, 0xD9, 0xAB};
        std::vector<std::uint8_t> file, expected;
        for (const auto* part : {&soi, &jfif, &garbage, &exif, &comment, &adobe, &fill, &table, &restart, &iptc, &scan, &fill, &exif,
                                 &table, &lastScan, &eoi})
            file.insert(file.end(), part->begin(), part->end());
        for (const auto* part : {&soi, &jfif, &adobe, &table, &scan, &table, &lastScan, &eoi}) expected.insert(expected.end(), part->begin(), part->end());
        QCOMPARE(jpegWithoutMetadata(file), expected);
        // A length less than 2 ends the segment after its length field, as libjpeg reads on there (a
        // frame behind such a segment was a 1 GB allocation the probe did not see).
        std::vector<std::uint8_t> broken = soi;
        for (const auto* part : {&exif, &table, &table}) broken.insert(broken.end(), part->begin(), part->end());
        broken[5] = 0; // Exif's length
        broken[5 + exif.size()] = 1; // the first table's
        expected = soi;
        for (const std::uint8_t b : {0xFF, 0xDB, 0, 1}) expected.push_back(b);
        expected.insert(expected.end(), table.begin(), table.end());
        QCOMPARE(jpegWithoutMetadata(broken), expected);
        std::vector<std::uint8_t> hidden = jpegHeader(65500, 65500);
        hidden.insert(hidden.begin() + 2, {0xFF, 0xE1, 0, 0, 'E', 'x', 'i', 'f'});
        QCOMPARE(probeImageHeader(hidden), std::optional(ImageSize{65500, 65500}));
    }

    // Only the reader the signature names sees the bytes, and its complaint is the error.
    void aBrokenFileGetsItsReadersComplaint()
    {
        std::vector<std::uint8_t> png = readAll(kSwatches);
        png.resize(40); // the signature and IHDR, then nothing
        const OiioImageDecoder decoder;
        const DecodedImage<std::uint8_t> image = decoder.decode8(png, {});
        QVERIFY(!image.ok());
        QVERIFY2(QString::fromStdString(image.error).contains("PNG"), image.error.c_str());
        const MemoryImage opened = openImageFromMemory(bytesOf("GIF89a"));
        QVERIFY(!opened.input);
        QCOMPARE(QString::fromStdString(opened.error), QStringLiteral("not a PNG, JPEG, HDR, EXR or TIFF file"));
    }

    // Glint converts the values as stored itself (OpenImageIO 2.4 converts through a 64 MiB
    // buffer): the same floats and bytes as OpenImageIO's own conversion, for every stored type.
    void convertedPixelsEqualOpenImageIOsConversion()
    {
        for (const char* name : {"rgba16.png", "grey.jpg", "greyalpha.png", "piz.exr", "tiled.exr", "float.tif", "strip.hdr"}) {
            const std::vector<std::uint8_t> bytes = readAll(kBombs / name);
            for (const OIIO::TypeDesc type : {OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::UINT8}) {
                MemoryImage ours = openImageFromMemory(bytes);
                MemoryImage theirs = openImageFromMemory(bytes);
                QVERIFY2(ours.input && theirs.input, name);
                const OIIO::ImageSpec& spec = ours.input->spec();
                const int channels = std::min(spec.nchannels, 4);
                const std::size_t size = std::size_t(spec.width) * std::size_t(spec.height) * 4 * type.size();
                std::vector<std::uint8_t> a(size, 7), b(size, 7);
                QVERIFY2(readConvertedPixels(*ours.input, channels, type, a.data(), 4 * type.size()), name);
                QVERIFY2(theirs.input->read_image(0, 0, 0, channels, type, b.data(), OIIO::stride_t(4 * type.size())), name);
                QVERIFY2(a == b, name);
            }
        }
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
