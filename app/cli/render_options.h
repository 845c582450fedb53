#pragma once
// Everything `glint render` accepts, stills and animations alike.
#include "common_options.h"
#include "frame_timing.h"
#include "region_option.h"
#include "shard_plan.h"

#include <optional>
#include <string>

namespace glint::cli {

struct RenderOptions {
    std::string scene;
    std::string out;      // empty: the project file's output.path
    std::string aovs = "all";
    bool aovsGiven = false; // --aovs on the command line (else the project's output.aovs)
    std::string passes;     // --passes: EXR render passes; empty: none
    bool passesGiven = false; // --passes on the command line (else the project's output.passes)
    std::optional<double> time;
    std::optional<ImageWindow> region; // --region: pixels from the top-left corner; unset: the whole image
    bool animation = false;
    std::optional<FrameRange> frames; // default: the animation's span
    std::optional<Fps> fps;           // default: the project's
    bool resume = true;
    std::optional<Shard> shard;
    std::optional<int> shards; // N for Kubernetes indexed jobs
    int chunkFrames = kDefaultChunkFrames;   // history configurations: frames per chunk (K)
    int warmupFrames = kDefaultWarmupFrames; // and discarded warm-up frames before a chunk (W)
    std::optional<std::string> video;
    std::optional<std::string> codec;
    CommonRenderOptions common;
};

} // namespace glint::cli
