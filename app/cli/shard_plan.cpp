#include "shard_plan.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace glint::cli {

namespace {

std::optional<int> parseInt(std::string_view text) {
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

int requireInt(const EnvLookup& env, const std::string& name) {
    const auto text = env(name);
    const auto value = text ? parseInt(*text) : std::nullopt;
    if (!value) throw std::invalid_argument(name + " must be an integer, got '" + text.value_or("") + "'");
    return *value;
}

// The index in 64 bits: a job array's task id minus its minimum may not fit an int.
Shard checked(long long index, int count, const std::string& source) {
    if (count < 1 || index < 0 || index >= count)
        throw std::invalid_argument(source + " gives shard " + std::to_string(index) + " of " + std::to_string(count) +
                                    "; expected 0 <= I < N");
    return {static_cast<int>(index), count};
}

} // namespace

Shard parseShard(const std::string& text) {
    const std::size_t slash = text.find('/');
    const auto index = slash == std::string::npos ? std::nullopt : parseInt(std::string_view(text).substr(0, slash));
    const auto count = slash == std::string::npos ? std::nullopt : parseInt(std::string_view(text).substr(slash + 1));
    if (!index || !count) throw std::invalid_argument("expected a shard I/N, got '" + text + "'");
    return checked(*index, *count, "--shard " + text);
}

Shard selectShard(const std::optional<Shard>& explicitShard, const std::optional<int>& shards, const EnvLookup& env) {
    if (explicitShard) return *explicitShard;
    if (env("SLURM_ARRAY_TASK_ID")) {
        const int id = requireInt(env, "SLURM_ARRAY_TASK_ID");
        const int min = env("SLURM_ARRAY_TASK_MIN") ? requireInt(env, "SLURM_ARRAY_TASK_MIN") : 0;
        return checked(static_cast<long long>(id) - min, requireInt(env, "SLURM_ARRAY_TASK_COUNT"), "the Slurm job array");
    }
    if (env("JOB_COMPLETION_INDEX")) {
        if (!shards) throw std::invalid_argument("JOB_COMPLETION_INDEX is set: give the job's completions as --shards N");
        return checked(requireInt(env, "JOB_COMPLETION_INDEX"), *shards, "JOB_COMPLETION_INDEX with --shards");
    }
    if (shards && *shards != 1)
        throw std::invalid_argument("--shards needs JOB_COMPLETION_INDEX (a Kubernetes indexed job); use --shard I/N");
    return {};
}

std::vector<int> framesOfShard(const FrameRange& range, const Shard& shard) {
    std::vector<int> frames;
    for (long long f = range.first + shard.index; f <= range.last; f += shard.count) frames.push_back(int(f));
    return frames;
}

std::vector<ChunkWork> chunksOfShard(const FrameRange& range, const Shard& shard, int chunkFrames, int warmupFrames) {
    if (chunkFrames < 1 || warmupFrames < 0) throw std::invalid_argument("chunks need K >= 1 frames and W >= 0 warm-up frames");
    std::vector<ChunkWork> work;
    const int firstChunk = range.first / chunkFrames;
    const int lastChunk = range.last / chunkFrames;
    for (long long c = firstChunk + shard.index; c <= lastChunk; c += shard.count) {
        const int chunkStart = int(c * chunkFrames);
        ChunkWork w;
        w.historyStart = std::max(0, chunkStart - warmupFrames);
        w.firstOutput = std::max(chunkStart, range.first);
        w.last = int(std::min<long long>(c * chunkFrames + chunkFrames - 1, range.last));
        work.push_back(w);
    }
    return work;
}

} // namespace glint::cli
