#include "frame_render.h"

#include "app/version.h"
#include "renderer/bvh_cost_render.h"
#include "renderer/output/image_files.h"

#include <cstdio>

namespace glint::cli {

namespace {

// One line, rewritten in place, at most ~100 times per render.
void printSampleProgress(int done, int total) {
    if (total < 100 || done % (total / 100) == 0 || done == total)
        std::fprintf(stderr, "\rglint: rendering %d/%d samples", done, total);
    if (done == total) std::fprintf(stderr, "\n");
}

} // namespace

RenderPlan planImage(const RenderOptions& o, const FrameJob& job) {
    RenderPlan plan = planRender(*job.scene, o.scene, o.common);
    if (o.region) { // other pixels, another file: hashed, so --resume renders the frame again
        plan.request.region = o.region;
        plan.metadata["region"] = formatRegion(*o.region);
    }
    if (job.history) {
        // The noise varies with the frame index inside the chunk; K and W decide the history.
        plan.metadata["spp"] = o.common.spp ? std::to_string(*o.common.spp) : std::string("configuration");
        plan.metadata["chunk"] = std::to_string(o.chunkFrames) + "+" + std::to_string(o.warmupFrames) + " warm-up";
        if (job.frame) plan.metadata["frame"] = std::to_string(*job.frame);
    } else if (job.frame) {
        // Each frame its own noise (a fixed pattern would crawl over a moving image), and the
        // same noise for the same frame in every run and shard.
        plan.request.seed = o.common.seed + static_cast<std::uint32_t>(*job.frame);
        plan.metadata["seed"] = std::to_string(plan.request.seed);
        plan.metadata["frame"] = std::to_string(*job.frame);
    }
    if (job.fps) {
        plan.metadata["fps"] = std::to_string(job.fps->numerator) + "/" + std::to_string(job.fps->denominator);
        plan.request.motionSeconds = double(job.fps->denominator) / double(job.fps->numerator);
    }
    if (job.time) {
        plan.request.time = *job.time;
        plan.metadata["time"] = formatNumber(*job.time);
    }
    if (renderer::imageFormatFor(job.out) == renderer::ImageFormat::Exr) {
        plan.metadata["aovs"] = o.aovs;
        renderer::planRenderPasses(plan, renderer::parsePassList(o.passes));
    }
    sealSettings(plan.metadata);
    return plan;
}

void renderImage(renderer::OfflineRenderer& gpu, const RenderOptions& o, const FrameJob& job, RenderPlan plan,
                 const StopSignal& stop, bool sampleProgress) {
    plan.request.progress = [&stop, sampleProgress](int done, int total) {
        if (stop.requested()) throw RenderStopped{};
        if (sampleProgress) printSampleProgress(done, total);
    };
    if (stop.requested()) throw RenderStopped{};
    renderer::RenderOutput image = gpu.render(*job.scene, plan.request);
    if (job.warnings) job.warnings->report(image.warnings, o.scene, o.common.strict);
    renderer::ExrLayers layers = renderer::parseAovList(o.aovs);
    if (renderer::imageFormatFor(job.out) == renderer::ImageFormat::Exr) layers.passes = renderer::parsePassList(o.passes);
    if (layers.bvhCost && renderer::imageFormatFor(job.out) == renderer::ImageFormat::Exr)
        image.bvhCost = renderer::renderBvhCost(gpu, *job.scene, plan.request); // a debug pass of its own
    renderer::ImageMetadata metadata = plan.metadata;
    metadata["version"] = kVersion;
    metadata["renderTimeMs"] = formatNumber(image.timings.setupMs + image.timings.renderMs);
    // Written even when a signal arrived meanwhile: the frame is finished, and the write is atomic.
    renderer::writeRenderImage(job.out, image, layers, metadata);
}

} // namespace glint::cli
