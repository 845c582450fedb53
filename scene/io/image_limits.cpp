// The decode limits of image_decoder.h, checked on an image's declared size.
#include "scene/io/image_decoder.h"

#include <algorithm>
#include <cmath>

namespace glint {

std::string decodeLimitError(std::int64_t width, std::int64_t height, std::int64_t channels, int decodedChannels,
                             std::size_t bytesPerValue, const DecodeLimits& limits)
{
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) return "the image declares " + size + " pixels: it has none";
    if (channels <= 0) return "the image declares " + std::to_string(channels) + " channels: it has none";
    // Both sides at most 2^31, so the product fits; beyond maxPixels (at most 2^32 here) nothing
    // else is multiplied in.
    const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    if (pixels > limits.maxPixels)
        return "the image declares " + size + " pixels, more than the limit of " + std::to_string(limits.maxPixels) + " pixels";
    const auto values = static_cast<std::uint64_t>(std::max<std::int64_t>(channels, decodedChannels));
    if (values > limits.maxBytes) // channels alone beyond the limit: never multiply them in
        return "the image declares " + std::to_string(channels) + " channels, more than the limit of " +
               std::to_string(limits.maxBytes) + " bytes allows";
    const std::uint64_t perPixel = values * bytesPerValue;
    if (pixels > limits.maxBytes / perPixel) {
        // In doubles: the product need not fit in 64 bits, and MiB are rounded up anyway.
        const auto mib = [](double bytes) { return std::to_string(static_cast<std::uint64_t>(std::ceil(bytes / 1048576.0))) + " MiB"; };
        return "the image declares " + size + " pixels x " + std::to_string(values) + " channels (" +
               mib(static_cast<double>(pixels) * static_cast<double>(perPixel)) + " decoded), more than the limit of " +
               mib(static_cast<double>(limits.maxBytes));
    }
    return {};
}

std::string chunkLimitError(std::int64_t chunkWidth, std::int64_t chunkHeight, std::int64_t channels, std::size_t bytesPerValue,
                            const DecodeLimits& limits)
{
    std::string error = decodeLimitError(chunkWidth, chunkHeight, channels, 1, bytesPerValue, limits);
    const std::string prefix = "the image declares ";
    if (error.starts_with(prefix)) error.insert(prefix.size(), "tiles or strips of ");
    return error;
}

std::string headerLimitError(std::span<const std::uint8_t> header, std::uint64_t fileSize, int decodedChannels,
                             std::size_t bytesPerValue, const DecodeLimits& limits)
{
    if (std::string problem = imageHeaderProblem(header, fileSize); !problem.empty()) return problem;
    if (const std::optional<ExrChunkShape> chunk = probeExrChunk(header))
        if (std::string error = chunkLimitError(chunk->width, chunk->height, std::max<std::int64_t>(chunk->channels, 1),
                                                std::max(bytesPerValue, chunk->bytesPerValue), limits);
            !error.empty())
            return error;
    const std::optional<ImageSize> size = probeImageHeader(header);
    return size ? decodeLimitError(size->width, size->height, 1, decodedChannels, bytesPerValue, limits) : std::string();
}

} // namespace glint
