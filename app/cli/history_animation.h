#pragma once
// Animations with a configuration that keeps history (TAA, SVGF): rendered chunk by chunk
// (shard_plan.h, chunksOfShard) through one FrameRenderer, the history reset at every chunk start
// and warm-up frames rendered but not written, so a frame is the same in one run, in any shard,
// and alone.
#include "frame_pattern.h"
#include "frame_progress.h"
#include "render_options.h"
#include "shard_plan.h"
#include "stop_signal.h"

#include "scene/core/scene.h"

namespace glint::cli {

// Returns the exit code (0, or 128+N after a signal). Throws FileError / std::runtime_error.
int renderHistoryChunks(const RenderOptions& options, const Scene& scene, const FramePattern& pattern,
                        const std::vector<ChunkWork>& chunks, const Fps& fps, const StopSignal& stop,
                        FrameProgress& progress);

// The frames written for `chunks` (for the progress total).
int outputFrameCount(const std::vector<ChunkWork>& chunks);

} // namespace glint::cli
