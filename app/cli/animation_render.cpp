#include "animation_render.h"

#include "exit_codes.h"
#include "frame_pattern.h"
#include "frame_progress.h"
#include "frame_render.h"
#include "history_animation.h"
#include "report.h"
#include "video_from_frames.h"

#include "renderer/configuration.h"
#include "renderer/output/frame_check.h"
#include "renderer/output/image_files.h"
#include "scene/anim/scene_at_time.h"
#include "scene/core/diagnostics.h"
#include "scene/io/project/project_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>

namespace glint::cli {

namespace {

// Configurations that keep history between frames (TAA, SVGF) render in chunks.
bool hasHistory(const RenderOptions& o, const Scene& scene) {
    const auto configuration = renderer::parseConfiguration(o.common.config.value_or(scene.settings.render.configuration));
    return configuration && !renderer::traitsOf(*configuration).accumulate;
}

std::optional<std::string> fromEnvironment(const std::string& name) {
    const char* value = std::getenv(name.c_str());
    return value ? std::optional<std::string>(value) : std::nullopt;
}

// Renders one frame unless --resume finds it complete with the same settings hash.
void renderFrame(renderer::OfflineRenderer& gpu, const RenderOptions& o, const Scene& scene, const FramePattern& pattern,
                 int frame, const Fps& fps, const StopSignal& stop, FrameProgress& progress, WarningsOnce& warnings) {
    FrameJob job;
    job.warnings = &warnings;
    const Scene posed = sceneAt(scene, frameTime(scene, fps, frame));
    job.scene = &posed;
    job.out = pattern.frame(frame);
    job.time = frameTime(scene, fps, frame);
    job.frame = frame;
    job.fps = fps;
    RenderPlan plan = planImage(o, job);
    if (o.resume && renderer::completeFrameSettingsHash(job.out) == plan.metadata.at("settingsHash")) {
        progress.skipped(frame, job.out.string());
        return;
    }
    renderImage(gpu, o, job, std::move(plan), stop, false);
    progress.rendered(frame, job.out.string());
}

int renderConverged(const RenderOptions& o, const Scene& scene, const FramePattern& pattern, const std::vector<int>& frames,
                    const Fps& fps, const StopSignal& stop) {
    renderer::OfflineRenderer gpu(o.common.requireGpu);
    std::fprintf(stderr, "glint: GL_RENDERER: %s\n", gpu.glRenderer().c_str());
    FrameProgress progress(int(frames.size()));
    WarningsOnce warnings;
    for (int frame : frames) {
        try {
            renderFrame(gpu, o, scene, pattern, frame, fps, stop, progress, warnings);
        } catch (const RenderStopped&) {
            std::fprintf(stderr, "glint: stopped by signal %d; frame %d discarded\n", stop.signalNumber(), frame);
            return stop.exitCode();
        }
        if (stop.requested()) {
            std::fprintf(stderr, "glint: stopped by signal %d after frame %d\n", stop.signalNumber(), frame);
            return stop.exitCode();
        }
    }
    return kSuccess;
}

} // namespace

void validateAnimationOptions(const RenderOptions& o) {
    if (!o.animation) {
        if (o.frames || o.fps || o.shard || o.shards || o.video)
            throw CLI::ValidationError("--frames, --fps, --shard, --shards and --video need --animation");
        if (hasFramePlaceholder(o.out))
            throw CLI::ValidationError("--out", "'#' numbers animation frames: add --animation, or rename the still");
        return;
    }
    if (o.time) throw CLI::ValidationError("--time", "--time renders a still; an animation takes --frames");
    try {
        parseFramePattern(o.out);
    } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError("--out", e.what());
    }
    if (o.video && (o.shard || o.shards))
        throw CLI::ValidationError("--video", "a shard has only some frames: encode once all shards are done (glint encode)");
}

int renderAnimation(const RenderOptions& o, const Scene& scene) {
    if (!hasAnimation(scene))
        throw FileError(o.scene, "no-animation", "the scene has no camera path and no animation to render");
    const FramePattern pattern = parseFramePattern(o.out);
    const Fps fps = o.fps.value_or(Fps{scene.settings.timeline.fpsNumerator, scene.settings.timeline.fpsDenominator});
    FrameRange range;
    try {
        range = o.frames ? *o.frames : defaultFrameRange(scene, fps); // the timeline only when --frames is not given
    } catch (const std::invalid_argument& e) {
        throw FileError(projectPathFor(o.scene).string(), "frame-range", e.what());
    }
    Shard shard;
    try {
        shard = selectShard(o.shard, o.shards, fromEnvironment);
    } catch (const std::invalid_argument& e) {
        printError(e.what());
        return kUsage;
    }
    renderer::prepareOutputFolder(pattern.frame(range.first));
    if (o.video) renderer::prepareOutputFolder(*o.video); // before the frames, not after them
    const StopSignal stop;
    int exitCode = kSuccess;
    std::fprintf(stderr, "glint: frames %d-%d at %d/%d fps, shard %d/%d: ", range.first, range.last, fps.numerator,
                 fps.denominator, shard.index, shard.count);
    if (hasHistory(o, scene)) {
        const auto chunks = chunksOfShard(range, shard, o.chunkFrames, o.warmupFrames);
        std::fprintf(stderr, "%d frames in %zu chunks of %d (history reset per chunk, %d warm-up frames)\n",
                     outputFrameCount(chunks), chunks.size(), o.chunkFrames, o.warmupFrames);
        FrameProgress progress(outputFrameCount(chunks));
        exitCode = renderHistoryChunks(o, scene, pattern, chunks, fps, stop, progress);
    } else {
        const std::vector<int> frames = framesOfShard(range, shard);
        std::fprintf(stderr, "%zu frames\n", frames.size());
        exitCode = renderConverged(o, scene, pattern, frames, fps, stop);
    }
    if (exitCode != kSuccess) return exitCode;
    if (o.video) encodeFrames(pattern, range, fps, *o.video, o.codec);
    return kSuccess;
}

} // namespace glint::cli
