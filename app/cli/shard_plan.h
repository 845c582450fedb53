#pragma once
// Which frames one shard of a farm job renders (docs/CLI.md, "Shards and job arrays"). Pure
// functions: the same inputs give the same plan on every node, which is what makes a frame
// rendered on a farm identical to the same frame rendered in one run.
#include "frame_timing.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glint::cli {

struct Shard {
    int index = 0; // 0 <= index < count
    int count = 1;
};

// "I/N" with 0 <= I < N; throws std::invalid_argument.
Shard parseShard(const std::string& text);

// The shard of this process: an explicit --shard wins; else Slurm's job array
// (I = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN, N = SLURM_ARRAY_TASK_COUNT); else a Kubernetes
// indexed job (I = JOB_COMPLETION_INDEX, N = --shards); else the whole range (0/1).
// `env` looks a variable up (nullopt when unset). Throws std::invalid_argument for values that
// do not make a shard (JOB_COMPLETION_INDEX without --shards, an index past the count, ...).
using EnvLookup = std::function<std::optional<std::string>(const std::string& name)>;
Shard selectShard(const std::optional<Shard>& explicitShard, const std::optional<int>& shards, const EnvLookup& env);

// Configurations without history: frames first+I, first+I+N, ... of the range.
std::vector<int> framesOfShard(const FrameRange& range, const Shard& shard);

// Configurations with history. The animation is cut into chunks of K frames anchored at frame 0
// (chunk c is frames cK .. cK+K-1), whatever range is asked for, so a frame's history is the same
// in every run. History restarts at each chunk: the first `warmup` frames before the chunk
// (never before frame 0) are rendered and discarded, and so are the chunk's own frames before the
// range start. Shards take whole chunks, round robin over the chunks that touch the range.
struct ChunkWork {
    int historyStart = 0; // first frame rendered after the history reset
    int firstOutput = 0;  // first frame written
    int last = 0;         // last frame written (inclusive)
};
std::vector<ChunkWork> chunksOfShard(const FrameRange& range, const Shard& shard, int chunkFrames, int warmupFrames);

// Documented defaults (docs/FARM.md): one second of frames at 24 fps, 8 warm-up frames.
constexpr int kDefaultChunkFrames = 24;
constexpr int kDefaultWarmupFrames = 8;

} // namespace glint::cli
