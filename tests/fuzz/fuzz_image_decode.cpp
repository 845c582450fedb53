// Fuzzes Glint's image decode path with the bytes of an image file: OpenImageIO through
// OiioImageDecoder (8-bit and float, as textures and swatches decode), the texture path after it
// (halved to a maximum size, the mip chain, resampling to another size) and the environment path
// (decodeEnvironmentImage, cube maps unfolded, the importance-sampling table). The limits are small,
// so that an image bomb (a few bytes declaring huge sizes or many channels) must be refused on its
// header: -malloc_limit_mb catches any allocation that got past them. What decodes must have the
// declared shape, stay within the limits and give finite, ordered sampling tables.
#include "renderer/cpu_twin/env_sampling.h"
#include "renderer/gpu_scene/environment_image.h"
#include "renderer/gpu_scene/texture_mips.h"
#include "scene/core/diagnostics.h"
#include "scene/io/image_decoder.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

using namespace glint;

namespace {

void require(bool ok) {
    if (!ok) std::abort();
}

constexpr int kMaxTextureSize = 32; // the texture path halves anything larger first

// Small enough that a declared size past them is quick to reach, and that an image within them costs
// little to decode and halve (the seeds are at most 128 x 128): a run's time goes to the parsers.
DecodeLimits fuzzLimits() {
    DecodeLimits limits;
    limits.maxPixels = 1u << 16; // 256 x 256
    limits.maxBytes = 4u << 20;  // 4 MiB decoded
    return limits;
}

template <class T>
void checkShape(const DecodedImage<T>& image, const DecodeLimits& limits) {
    if (!image.ok()) {
        require(image.rgba.empty() && !image.error.empty());
        return;
    }
    require(image.width > 0 && image.height > 0);
    const auto pixels = static_cast<std::uint64_t>(image.width) * static_cast<std::uint64_t>(image.height);
    require(pixels <= limits.maxPixels && image.rgba.size() == pixels * 4 && image.rgba.size() * sizeof(T) <= limits.maxBytes);
}

void checkTexture(std::span<const std::uint8_t> bytes, const ImageDecoder& decoder, const DecodeLimits& limits) {
    const bool srgb = bytes.size() % 2 == 0;
    const renderer::DecodedMipChain chain = renderer::decodeMipChain(decoder, bytes, srgb, kMaxTextureSize, limits);
    if (!chain.error.empty()) {
        require(chain.levels.empty());
        return;
    }
    require(!chain.levels.empty());
    const renderer::TextureLevel& base = chain.levels.front();
    require(base.width >= 1 && base.height >= 1 && base.width <= kMaxTextureSize && base.height <= kMaxTextureSize);
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        const renderer::TextureLevel& level = chain.levels[i];
        require(level.rgba.size() == static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height) * 4);
        if (i > 0) require(level.width == std::max(1, chain.levels[i - 1].width / 2) && level.height == std::max(1, chain.levels[i - 1].height / 2));
    }
    require(chain.levels.back().width == 1 && chain.levels.back().height == 1);
    // Resampled as a merge of texture sizes would, to a size taken from the input.
    const int width = 1 + bytes[bytes.size() / 2] % kMaxTextureSize, height = 1 + bytes[bytes.size() / 3] % kMaxTextureSize;
    const renderer::TextureLevel resampled = renderer::resampleLevel(base, width, height, srgb);
    require(resampled.width == width && resampled.height == height && resampled.rgba.size() == std::size_t(width) * std::size_t(height) * 4);
}

void checkEnvironment(std::span<const std::uint8_t> bytes, const DecodeLimits& limits) {
    renderer::EnvironmentImage image;
    try {
        image = renderer::decodeEnvironmentImage(bytes, "fuzz.input", limits);
    } catch (const FileError& error) {
        require(error.what()[0] != '\0');
        return;
    }
    require(image.width > 0 && image.height > 0);
    require(image.rgb.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
    require(image.rgb.size() * sizeof(float) <= 2 * limits.maxBytes); // a cube map unfolds into at most twice its pixels
    const twin::EnvironmentSamplingTable table = twin::buildEnvironmentSamplingTable(image.width, image.height, image.rgb);
    for (int row = 0; row <= image.height; ++row) {
        const int n = row < image.height ? image.width : image.height;
        const float* cdf = &table.cdf[static_cast<std::size_t>(row) * static_cast<std::size_t>(table.tableWidth)];
        require(cdf[0] == 0.0f && cdf[n] == 1.0f);
        for (int i = 0; i < n; ++i) require(std::isfinite(cdf[i + 1]) && cdf[i + 1] >= cdf[i] && cdf[i + 1] <= 1.0f);
    }
}

} // namespace

// OpenImageIO 2.4's PNG reader formats its error into a std::string, then libpng longjmps past it
// (PNGInput::PngReadCallback -> png_error): a few bytes per corrupt PNG, not Glint's to free. On a
// truncated tEXt chunk the error text ImageInput::geterror() copies leaks the same way (seed
// leak-oiio-png-truncated-text.png). The suppressions need malloc stacks unwound without frame
// pointers (OpenImageIO has none), kept short to stay cheap; ASAN_OPTIONS from the environment
// still apply over these defaults.
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0:malloc_context_size=8"; }
extern "C" const char* __lsan_default_suppressions()
{
    return "leak:OpenImageIO_v2_4::PNGInput::PngReadCallback\n"
           "leak:OpenImageIO_v2_4::ImageInput::geterror\n";
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    OIIO::attribute("threads", 1); // one thread: reproducible runs, and libFuzzer's own accounting
    OIIO::attribute("exr_threads", 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::span<const std::uint8_t> bytes(data, size);
    const DecodeLimits limits = fuzzLimits();
    const OiioImageDecoder decoder;
    checkShape(decoder.decodeFloat(bytes, limits), limits); // decode8 runs inside decodeMipChain
    checkTexture(bytes, decoder, limits);
    checkEnvironment(bytes, limits);
    return 0;
}
