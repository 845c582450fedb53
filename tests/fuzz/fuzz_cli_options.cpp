// Fuzzes the command line's option parsers (docs/CLI.md): --frames A-B, --fps N[/D], --region
// X,Y,W,H, --size WxH, --shard I/N and the job-array environment. The first byte picks the
// parser, the rest is the option's text. A parser either returns a value inside its documented
// range or throws std::invalid_argument; anything else (another exception, a value out of range,
// UB, a crash) is a bug. What parses goes on through the plans built from it.
#include "app/cli/frame_timing.h"
#include "app/cli/region_option.h"
#include "app/cli/shard_plan.h"
#include "app/cli/size_option.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

using namespace glint::cli;

namespace {

void require(bool ok) {
    if (!ok) std::abort();
}

// The frame plans of a parsed range, for a few shards; their size is bounded by the range, so
// the range is narrowed to keep one input fast (the planning arithmetic still sees the extremes).
void planFrames(const FrameRange& range) {
    require(range.first >= 0 && range.first <= range.last);
    require(range.count() >= 1);
    const FrameRange narrow{range.first, range.first + std::min(range.last - range.first, 1000)};
    for (const Shard shard : {Shard{0, 1}, Shard{1, 3}, Shard{6, 7}}) {
        for (int frame : framesOfShard(narrow, shard)) require(frame >= narrow.first && frame <= narrow.last);
        for (const ChunkWork& w : chunksOfShard(narrow, shard, kDefaultChunkFrames, kDefaultWarmupFrames))
            require(w.historyStart >= 0 && w.historyStart <= w.firstOutput && w.firstOutput <= w.last &&
                    w.firstOutput >= narrow.first && w.last <= narrow.last);
    }
}

// "NAME=VALUE" lines after the first byte: the job-array environment of selectShard.
void selectFromEnvironment(const std::string& text) {
    std::map<std::string, std::string> env;
    std::size_t at = 0;
    while (at <= text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(at, end - at);
        if (const std::size_t eq = line.find('='); eq != std::string::npos) env[line.substr(0, eq)] = line.substr(eq + 1);
        at = end + 1;
    }
    std::optional<int> shards;
    if (auto it = env.find("--shards"); it != env.end() && !it->second.empty())
        shards = static_cast<int>(static_cast<unsigned char>(it->second[0])) - 64;
    const auto lookup = [&env](const std::string& name) -> std::optional<std::string> {
        if (auto it = env.find(name); it != env.end()) return it->second;
        return std::nullopt;
    };
    const Shard s = selectShard(std::nullopt, shards, lookup);
    require(s.count >= 1 && s.index >= 0 && s.index < s.count);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        switch (data[0] % 6) {
        case 0: planFrames(parseFrameRange(text)); break;
        case 1: {
            const Fps fps = parseFps(text);
            require(fps.numerator >= 1 && fps.denominator >= 1 && fps.value() > 0.0);
            break;
        }
        case 2: {
            const ImageWindow r = parseRegion(text);
            require(r.x >= 0 && r.y >= 0 && r.width >= 1 && r.height >= 1);
            require(parseRegion(formatRegion(r)) == r);
            // Inside a 16384 x 16384 image or refused, without overflow.
            try {
                checkRegionInside(r, kMaxImageDimension, kMaxImageDimension);
                require(r.x + r.width <= kMaxImageDimension && r.y + r.height <= kMaxImageDimension);
            } catch (const std::invalid_argument&) {
            }
            break;
        }
        case 3: {
            const WidthHeight s = parseWidthHeight(text);
            require(s.width >= 1 && s.width <= kMaxImageDimension && s.height >= 1 && s.height <= kMaxImageDimension);
            break;
        }
        case 4: {
            const Shard s = parseShard(text);
            require(s.count >= 1 && s.index >= 0 && s.index < s.count);
            break;
        }
        default: selectFromEnvironment(text); break;
        }
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
