// The CPU side of material textures, without a GL context: mip chains (box filter, sRGB-correct),
// bucketing by colour space and size, merging when sampler units run out, limits, placeholders,
// the packed texture references (sampler flags, transform matrix, the KHR_materials_* textures and
// their shader variants), and the decode cache (hits bit-identical to decoding, LRU by bytes).
#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/texture_refs.h"
#include "renderer/gpu_scene/texture_set.h"

#include <QTest>

#include <cmath>
#include <stdexcept>

using namespace glint;
using namespace glint::renderer;

namespace {

// Decodes "images" whose encoded bytes are (width, height, value): a constant RGBA image.
class FakeDecoder final : public ImageDecoder {
public:
    std::optional<ImageSize> probe(std::span<const std::uint8_t> e) const override { return ImageSize{e[0], e[1]}; }
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t>, const DecodeLimits&) const override { return {}; }
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> e, const DecodeLimits&) const override {
        DecodedImage<std::uint8_t> d;
        if (e.size() < 3) {
            d.error = "broken";
            return d;
        }
        d.width = e[0];
        d.height = e[1];
        d.rgba.assign(static_cast<std::size_t>(e[0]) * e[1] * 4, e[2]);
        return d;
    }
};

// Counts decode8 calls (a cache hit must make none); decodes like FakeDecoder, with a gradient so
// that mip levels differ from level 0.
class CountingDecoder final : public ImageDecoder {
public:
    mutable int decodes = 0;
    std::optional<ImageSize> probe(std::span<const std::uint8_t> e) const override { return ImageSize{e[0], e[1]}; }
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t>, const DecodeLimits&) const override { return {}; }
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> e, const DecodeLimits&) const override {
        ++decodes;
        DecodedImage<std::uint8_t> d;
        d.width = e[0];
        d.height = e[1];
        for (int i = 0; i < e[0] * e[1] * 4; ++i) d.rgba.push_back(static_cast<std::uint8_t>(e[2] + 37 * i));
        return d;
    }
};

TextureRef addImage(Scene& scene, int width, int height, std::uint8_t value) {
    Image image;
    image.encoded = {static_cast<std::uint8_t>(width), static_cast<std::uint8_t>(height), value};
    Texture texture;
    texture.image = scene.images.add(std::move(image));
    TextureRef ref;
    ref.texture = scene.textures.add(std::move(texture));
    return ref;
}

// A scene whose one visible mesh uses `m`.
Scene withMeshMaterial(Scene scene, const Material& m) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    p.material = scene.materials.add(m);
    Mesh mesh;
    mesh.primitives.push_back(p);
    Node node;
    node.component = MeshInstance{scene.meshes.add(std::move(mesh))};
    scene.addNode(std::move(node));
    return scene;
}

// Every level of every layer, bucket by bucket, and where each image lives.
void compareSets(const TextureSet& a, const TextureSet& b) {
    QCOMPARE(a.buckets.size(), b.buckets.size());
    QVERIFY(a.slotOf.size() == b.slotOf.size());
    for (const auto& [use, slot] : a.slotOf) {
        QCOMPARE(b.find(use.first, use.second).bucket, slot.bucket);
        QCOMPARE(b.find(use.first, use.second).layer, slot.layer);
    }
    for (std::size_t i = 0; i < a.buckets.size(); ++i) {
        QCOMPARE(a.buckets[i].layers.size(), b.buckets[i].layers.size());
        for (std::size_t l = 0; l < a.buckets[i].layers.size(); ++l) {
            const MipChain& x = *a.buckets[i].layers[l];
            const MipChain& y = *b.buckets[i].layers[l];
            QCOMPARE(x.size(), y.size());
            for (std::size_t level = 0; level < x.size(); ++level) QVERIFY(x[level].rgba == y[level].rgba);
        }
    }
}

MipChain chainOf(int width, int height, std::uint8_t value) {
    return buildMipChain(TextureLevel{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4, value)}, false);
}

} // namespace

class TestRenderTexturesCpu : public QObject {
    Q_OBJECT
private slots:
    // sRGB 0 and 255 average to linear 0.5, encoded 188 (not the 128 of averaging bytes); linear
    // data and alpha average as stored (128); odd sizes fold the last column in; the chain ends at 1x1.
    void mipChainsAverageInLinearLight() {
        TextureLevel base{3, 2, std::vector<std::uint8_t>(3 * 2 * 4)};
        for (std::size_t i = 0; i < base.rgba.size(); ++i) base.rgba[i] = (i / 4) % 2 ? 255 : 0;
        const auto srgb = buildMipChain(base, true);
        QCOMPARE(int(srgb.size()), 2);
        QCOMPARE(srgb[1].width, 1);
        QCOMPARE(srgb[1].height, 1);
        QCOMPARE(int(srgb[1].rgba[0]), 188);
        QCOMPARE(int(srgb[1].rgba[3]), 128);
        QCOMPARE(int(buildMipChain(base, false)[1].rgba[0]), 128);
        QCOMPARE(int(linearToSrgb8(0.5f)), 188);
        QVERIFY(std::abs(srgbToLinear(188) - 0.5029) < 1e-4);
        QCOMPARE(int(buildMipChain(TextureLevel{64, 16, std::vector<std::uint8_t>(64 * 16 * 4, 7)}, true).size()), 7);
    }

    // Base colour (sRGB) and normal (linear) of one size are two buckets; a second size of sRGB is a
    // third; with two units the smaller sRGB bucket is resampled into the larger, with a warning.
    void bucketsByColourSpaceAndSize() {
        Scene scene;
        Material a, b;
        a.baseColorTexture = addImage(scene, 4, 4, 200);
        a.normalTexture = addImage(scene, 4, 4, 128);
        b.emissiveTexture = addImage(scene, 8, 4, 50);
        scene = withMeshMaterial(withMeshMaterial(scene, a), b);
        FakeDecoder decoder;
        const TextureSet three = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 16, 64});
        QCOMPARE(int(three.buckets.size()), 3);
        QVERIFY(three.warnings.empty());
        const auto baseSlot = three.find(scene.textures.at(a.baseColorTexture.texture).image, true);
        QVERIFY(baseSlot.bucket >= 0 && three.buckets[std::size_t(baseSlot.bucket)].srgb);
        QCOMPARE(three.find(scene.textures.at(a.baseColorTexture.texture).image, false).bucket, -1);
        const TextureSet two = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{2, 16, 64});
        QCOMPARE(int(two.buckets.size()), 2);
        QCOMPARE(int(two.warnings.size()), 1);
        const auto merged = two.find(scene.textures.at(a.baseColorTexture.texture).image, true);
        QCOMPARE(two.buckets[std::size_t(merged.bucket)].width, 8);
        QCOMPARE(int(two.buckets[std::size_t(merged.bucket)].layers.size()), 2);
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{1, 16, 64}));
    }

    // Too many layers fail with a message naming the limit; oversized images use a mip level that
    // fits; a broken colour image becomes the 8x8 checker, a broken linear one is dropped.
    void limitsAndPlaceholders() {
        Scene scene;
        Material a, b;
        a.baseColorTexture = addImage(scene, 32, 32, 1);
        b.baseColorTexture = addImage(scene, 32, 32, 2);
        scene = withMeshMaterial(withMeshMaterial(scene, a), b);
        FakeDecoder decoder;
        try {
            buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 1, 64});
            QFAIL("no error for too many layers");
        } catch (const std::runtime_error& e) {
            QVERIFY2(std::string(e.what()).find("limit of 1 texture array layers") != std::string::npos, e.what());
        }
        QCOMPARE(buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 16, 8}).buckets[0].width, 8);

        Scene broken;
        Material c;
        c.baseColorTexture = addImage(broken, 4, 4, 9);
        c.normalTexture = addImage(broken, 4, 4, 9);
        broken.images.at(broken.textures.at(c.baseColorTexture.texture).image).encoded.resize(2);
        broken.images.at(broken.textures.at(c.normalTexture.texture).image).missing = true;
        broken = withMeshMaterial(broken, c);
        const TextureSet set = buildTextureSet(broken, meshMaterials(broken), decoder, TextureLimits{});
        QCOMPARE(int(set.buckets.size()), 1);
        QCOMPARE(set.buckets[0].width, 8);
        QCOMPARE(int(set.warnings.size()), 2);
    }

    // Sampler flags and the KHR_texture_transform matrix as the shader reads them.
    void textureReferencesPackSamplerAndTransform() {
        Sampler s;
        s.wrapS = Wrap::ClampToEdge;
        s.wrapT = Wrap::MirroredRepeat;
        s.magFilter = Filter::Nearest;
        s.minFilter = Filter::LinearMipmapNearest;
        QCOMPARE(samplerFlags(s), 1.0f + 3.0f * 2.0f + 9.0f + 36.0f);
        TextureRef ref;
        ref.texCoord = 0;
        ref.transform.rotation = 0.5f;
        ref.transform.scale = {2.0f, 3.0f};
        ref.transform.offset = {0.25f, 0.5f};
        ref.transform.texCoord = 1;
        std::vector<glm::vec4> texels;
        appendTextureRef(texels, ref, TextureSlot{2, 5}, s);
        QCOMPARE(int(texels.size()), textureRefTexels);
        QCOMPARE(texels[0], glm::vec4(2.0f, 5.0f, samplerFlags(s), 1.0f));
        // u' = a u + b v + tx must equal the extension's translation * rotation * scale.
        const float c = std::cos(0.5f), sn = std::sin(0.5f);
        QVERIFY(std::abs(texels[1].x - c * 2.0f) < 1e-6f && std::abs(texels[1].y - sn * 3.0f) < 1e-6f);
        QVERIFY(std::abs(texels[1].z + sn * 2.0f) < 1e-6f && std::abs(texels[1].w - c * 3.0f) < 1e-6f);
        QCOMPARE(texels[2], glm::vec4(0.25f, 0.5f, 1.0f, 0.0f));
        QCOMPARE(int(packMaterial(Material{}).size()), materialTexels);
    }

    // KHR_materials_specular (A, linear), specular colour (sRGB), transmission (R, linear) and
    // thickness (G, linear) textures: decoded into buckets of their colour space, packed as
    // references 4..7 after the four core ones, and each family switches on its shader variant.
    void extensionTexturesArePackedWithTheirVariants() {
        Scene scene;
        Material m;
        m.specularTexture = addImage(scene, 4, 4, 10);
        m.specularColorTexture = addImage(scene, 4, 4, 20);
        m.transmissionTexture = addImage(scene, 4, 4, 30);
        m.thicknessTexture = addImage(scene, 4, 4, 40);
        m.occlusionTexture = addImage(scene, 4, 4, 50);
        scene = withMeshMaterial(scene, m);
        const auto image = [&](const TextureRef& r) { return scene.textures.at(r.texture).image; };
        const auto used = texturesUsed(scene, meshMaterials(scene));
        QCOMPARE(int(used.size()), 4); // never the occlusion texture
        QVERIFY(used.contains({image(m.specularColorTexture), true}));
        QVERIFY(used.contains({image(m.specularTexture), false}));
        FakeDecoder decoder;
        const TextureSet set = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{});
        QCOMPARE(int(set.buckets.size()), 2);
        const auto texels = packMaterial(scene.materials.begin()->second, &scene, &set);
        QCOMPARE(int(texels.size()), materialTexels);
        const auto refAt = [&](int index) { return texels[std::size_t(materialBaseTexels + index * textureRefTexels)]; };
        const TextureRef* refs[] = {&m.specularTexture, &m.specularColorTexture, &m.transmissionTexture, &m.thicknessTexture};
        for (int i = 0; i < 4; ++i) {
            const TextureSlot slot = set.find(image(*refs[i]), i == 1);
            QVERIFY(slot.bucket >= 0);
            QCOMPARE(refAt(specularRef + i).x, float(slot.bucket));
            QCOMPARE(refAt(specularRef + i).y, float(slot.layer));
        }
        QVERIFY(set.buckets[std::size_t(set.find(image(m.specularColorTexture), true).bucket)].srgb);
        QCOMPARE(extensionTexturesUsed(scene, meshMaterials(scene), set),
                 unsigned(specularTextureBit | transmissionTextureBit | thicknessTextureBit));
        QCOMPARE(extensionTextureDefines(transmissionTextureBit), std::vector<std::string>{"HAS_TRANSMISSION_TEXTURES"});

        // Without them: no variant, and empty references.
        Scene plain = withMeshMaterial(Scene{}, Material{});
        const TextureSet none = buildTextureSet(plain, meshMaterials(plain), decoder, TextureLimits{});
        QCOMPARE(extensionTexturesUsed(plain, meshMaterials(plain), none), 0u);
        QVERIFY(extensionTextureDefines(0).empty());
        QCOMPARE(packMaterial(Material{})[std::size_t(materialBaseTexels + thicknessRef * textureRefTexels)].x, -1.0f);
    }

    // A second build through the cache decodes nothing and gives the same bytes as decoding afresh
    // (every level of every layer, and every slot); changed bytes decode again; the same bytes in the
    // other colour space are another entry (their mips differ).
    void cacheHitsAreBitIdenticalAndSkipDecoding() {
        Scene scene;
        Material a, b;
        a.baseColorTexture = addImage(scene, 8, 8, 3);
        a.normalTexture = addImage(scene, 8, 8, 5);
        b.emissiveTexture = addImage(scene, 4, 8, 7);
        b.metallicRoughnessTexture = b.emissiveTexture; // same image, linear this time
        scene = withMeshMaterial(withMeshMaterial(scene, a), b);
        TextureCache cache;
        CountingDecoder decoder;
        const TextureSet first = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{}, &cache);
        QCOMPARE(decoder.decodes, 4);
        QCOMPARE(int(cache.entries()), 4);
        const TextureSet second = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{}, &cache);
        QCOMPARE(decoder.decodes, 4);
        CountingDecoder freshDecoder;
        const TextureSet fresh = buildTextureSet(scene, meshMaterials(scene), freshDecoder, TextureLimits{});
        compareSets(second, fresh);
        compareSets(first, fresh);

        // A factor edit: nothing decoded. New bytes for one image: that one alone.
        for (auto& [id, m] : scene.materials) m.roughnessFactor = 0.25f;
        buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{}, &cache);
        QCOMPARE(decoder.decodes, 4);
        scene.images.at(scene.textures.at(a.normalTexture.texture).image).encoded[2] = 99;
        const TextureSet edited = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{}, &cache);
        QCOMPARE(decoder.decodes, 5);
        compareSets(edited, buildTextureSet(scene, meshMaterials(scene), freshDecoder, TextureLimits{}));
        // A smaller size cap stores another entry (the first level that fits), equal to decoding.
        const TextureSet capped = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 16, 4}, &cache);
        QCOMPARE(decoder.decodes, 9);
        compareSets(capped, buildTextureSet(scene, meshMaterials(scene), freshDecoder, TextureLimits{3, 16, 4}));
    }

    // Bounded by bytes (pixels of every level plus the encoded bytes): the least recently used
    // entry goes first; a look-up refreshes an entry; a chain larger than the budget is not kept;
    // equal hashes never mix different bytes (the bytes are compared).
    void cacheEvictsLeastRecentlyUsedByBytes() {
        const std::vector<std::uint8_t> e1{1}, e2{2}, e3{3};
        const std::size_t one = 16 * 4 + 4 * 4 + 4 + 1; // 4x4, 2x2 and 1x1 RGBA8, one encoded byte
        TextureCache cache(2 * one);
        cache.insert(e1, false, 64, std::make_shared<const MipChain>(chainOf(4, 4, 1)));
        cache.insert(e2, false, 64, std::make_shared<const MipChain>(chainOf(4, 4, 2)));
        QCOMPARE(cache.bytes(), 2 * one);
        QVERIFY(cache.find(e1, false, 64)); // e1 is now the most recent
        QVERIFY(!cache.find(e1, true, 64)); // another colour space
        QVERIFY(!cache.find(e1, false, 32)); // another size cap
        cache.insert(e3, false, 64, std::make_shared<const MipChain>(chainOf(4, 4, 3)));
        QCOMPARE(int(cache.entries()), 2);
        QVERIFY(cache.bytes() <= cache.budget());
        QVERIFY(!cache.find(e2, false, 64));
        QCOMPARE((*cache.find(e1, false, 64))[0].rgba[0], std::uint8_t(1));
        QCOMPARE((*cache.find(e3, false, 64))[0].rgba[0], std::uint8_t(3));
        cache.insert(e2, false, 64, std::make_shared<const MipChain>(chainOf(8, 8, 2)));
        QVERIFY(!cache.find(e2, false, 64));
        QCOMPARE(int(cache.entries()), 2);
        cache.clear();
        QCOMPARE(cache.bytes(), std::size_t{0});
    }
};

QTEST_APPLESS_MAIN(TestRenderTexturesCpu)
#include "test_render_textures_cpu.moc"
