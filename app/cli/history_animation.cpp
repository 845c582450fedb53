#include "history_animation.h"

#include "frame_render.h"
#include "report.h"

#include "app/version.h"
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "renderer/output/frame_check.h"
#include "renderer/output/image_files.h"

#include <cstdio>

namespace glint::cli {

namespace {

FrameJob jobFor(const Scene& scene, const FramePattern& pattern, const Fps& fps, int frame) {
    FrameJob job;
    job.scene = &scene; // planning needs the camera only; FrameRenderer poses the scene itself
    job.out = pattern.frame(frame);
    job.time = frameTime(scene, fps, frame);
    job.frame = frame;
    job.fps = fps;
    job.history = true;
    return job;
}

// A chunk is kept only when every frame it writes is complete with the same settings.
bool chunkComplete(const RenderOptions& o, const Scene& scene, const FramePattern& pattern, const Fps& fps,
                   const ChunkWork& chunk) {
    if (!o.resume) return false;
    for (int f = chunk.firstOutput; f <= chunk.last; ++f) {
        const RenderPlan plan = planImage(o, jobFor(scene, pattern, fps, f));
        if (renderer::completeFrameSettingsHash(pattern.frame(f)) != plan.metadata.at("settingsHash")) return false;
    }
    return true;
}

void writeFrame(renderer::FrameRenderer& frames, const RenderOptions& o, const FrameJob& job) {
    const RenderPlan plan = planImage(o, job);
    renderer::RenderOutput image;
    static_cast<renderer::FrameImages&>(image) = frames.readImages();
    renderer::ImageMetadata metadata = plan.metadata;
    metadata["version"] = kVersion;
    renderer::writeRenderImage(job.out, image, renderer::parseAovList(o.aovs), metadata);
}

} // namespace

int outputFrameCount(const std::vector<ChunkWork>& chunks) {
    int count = 0;
    for (const ChunkWork& c : chunks) count += c.last - c.firstOutput + 1;
    return count;
}

int renderHistoryChunks(const RenderOptions& o, const Scene& scene, const FramePattern& pattern,
                        const std::vector<ChunkWork>& chunks, const Fps& fps, const StopSignal& stop,
                        FrameProgress& progress) {
    if (chunks.empty()) return 0;
    const RenderPlan base = planImage(o, jobFor(scene, pattern, fps, chunks.front().firstOutput));
    gl::HeadlessContext context(gl::HeadlessContextOptions{o.common.requireGpu});
    std::fprintf(stderr, "glint: GL_RENDERER: %s\n", context.renderer().c_str());
    renderer::FrameRenderer frames;
    frames.setSettings(renderer::frameSettingsFor(base.request, o.common.spp.value_or(0))); // 0: the configuration's own
    frames.setScene(scene, renderer::environmentPath(scene, base.request));
    WarningsOnce().report(frames.warnings(), o.scene, o.common.strict); // one upload for all chunks
    frames.useSceneCamera(base.request.cameraName);
    for (const ChunkWork& chunk : chunks) {
        if (chunkComplete(o, scene, pattern, fps, chunk)) {
            for (int f = chunk.firstOutput; f <= chunk.last; ++f) progress.skipped(f, pattern.frame(f).string());
            continue;
        }
        frames.resetHistory();
        for (int f = chunk.historyStart; f <= chunk.last; ++f) {
            if (stop.requested()) {
                std::fprintf(stderr, "glint: stopped by signal %d before frame %d\n", stop.signalNumber(), f);
                return stop.exitCode();
            }
            frames.setTime(frameTime(scene, fps, f));
            frames.renderFrame();
            if (f < chunk.firstOutput) continue; // warm-up: history only
            const FrameJob job = jobFor(scene, pattern, fps, f);
            writeFrame(frames, o, job);
            progress.rendered(f, job.out.string());
        }
    }
    return 0;
}

} // namespace glint::cli
