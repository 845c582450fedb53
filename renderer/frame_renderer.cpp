#include "renderer/frame_renderer.h"

#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "renderer/gl/scissor_guard.h"
#include "renderer/passes/accumulate_pass.h"
#include "renderer/passes/adaptive_sampling.h"
#include "renderer/passes/mean_denoise_pass.h"
#include "renderer/passes/motion_pass.h"
#include "renderer/passes/reconstruction.h"
#include "renderer/passes/reconstruction_parameters.h"
#include "renderer/passes/region_composite.h"
#include "renderer/passes/render_passes_pass.h"
#include "renderer/passes/selection_outline_pass.h"
#include "renderer/passes/tonemap_pass.h"
#include "renderer/scene_snapshot.h"
#include "scene/anim/node_animation.h"
#include "scene/anim/scene_at_time.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace glint::renderer {
namespace {

// Saves what the passes change and puts the caller's state back: a host (QOpenGLWidget) keeps its
// own framebuffer, viewport and enables across our calls.
class CallerGlState {
public:
    CallerGlState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
        for (int i = 0; i < capabilityCount; ++i) {
            enabled_[i] = glIsEnabled(capabilities[i]);
            glDisable(capabilities[i]);
        }
    }
    ~CallerGlState() {
        for (int i = 0; i < capabilityCount; ++i)
            if (enabled_[i]) glEnable(capabilities[i]);
        glBindVertexArray(static_cast<GLuint>(vertexArray_));
        glActiveTexture(static_cast<GLenum>(activeTexture_));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_)); // on the caller's active unit
        glUseProgram(static_cast<GLuint>(program_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFbo_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFbo_));
    }
    CallerGlState(const CallerGlState&) = delete;
    CallerGlState& operator=(const CallerGlState&) = delete;

private:
    static constexpr int capabilityCount = 6;
    static constexpr GLenum capabilities[capabilityCount] = {GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST,
                                                             GL_CULL_FACE, GL_STENCIL_TEST, GL_FRAMEBUFFER_SRGB};
    GLint drawFbo_ = 0, readFbo_ = 0, program_ = 0, activeTexture_ = GL_TEXTURE0, texture_ = 0, vertexArray_ = 0;
    GLint viewport_[4] = {0, 0, 0, 0};
    GLboolean enabled_[capabilityCount] = {};
};

// GL rows run bottom-up; images run top-down. Keeps `channels` of each texel of `stride` (RGBA: 4).
template <class T>
std::vector<T> topDown(const std::vector<T>& rgba, int width, int height, int channels, std::size_t stride = 4) {
    std::vector<T> out;
    out.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels));
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                out.push_back(rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * stride + static_cast<std::size_t>(c)]);
    return out;
}

// Per-pixel sample variance n/(n-1) (E[x^2] - E[x]^2), clamped at 0 against rounding; n is
// `samples`, or the pixel's entry of `counts` (adaptive sampling) where that is given.
std::vector<float> sampleVariance(const std::vector<float>& mean, const std::vector<float>& meanSquared, int samples,
                                  const std::vector<float>& counts) {
    std::vector<float> variance;
    variance.reserve(mean.size() / 4 * 3);
    for (std::size_t i = 0; i < mean.size(); i += 4) {
        const double n = counts.empty() ? double(samples) : double(counts[i / 4]);
        const double correction = n > 1.0 ? n / (n - 1.0) : 0.0;
        for (std::size_t c = 0; c < 3; ++c)
            variance.push_back(static_cast<float>(
                std::max(0.0, correction * (static_cast<double>(meanSquared[i + c]) - static_cast<double>(mean[i + c]) * mean[i + c]))));
    }
    return variance;
}

void readGBuffer(const gl::RenderTarget& gbuffer, FrameImages& out) {
    const int w = out.width;
    const int h = out.height;
    out.albedo = topDown(gbuffer.readRgba(albedoAttachment), w, h, 3);
    const auto normalDepth = topDown(gbuffer.readRgba(normalDepthAttachment), w, h, 4);
    for (std::size_t i = 0; i < normalDepth.size(); i += 4) {
        out.normal.insert(out.normal.end(), normalDepth.begin() + static_cast<std::ptrdiff_t>(i),
                          normalDepth.begin() + static_cast<std::ptrdiff_t>(i + 3));
        out.depth.push_back(normalDepth[i + 3] < 0.0f ? std::numeric_limits<float>::infinity() : normalDepth[i + 3]);
    }
    out.objectId = topDown(gbuffer.readRgba(objectIdAttachment), w, h, 1);
    out.diffuseAlbedo = topDown(gbuffer.readRgba(diffuseAlbedoAttachment), w, h, 3);
    out.specularAlbedo = topDown(gbuffer.readRgba(specularAlbedoAttachment), w, h, 4);
}

bool sameCamera(const CameraSetup& a, const CameraSetup& b) {
    return a.worldFromCamera == b.worldFromCamera && a.orthographic == b.orthographic && a.halfExtent == b.halfExtent &&
           a.lensRadius == b.lensRadius && a.focusDistance == b.focusDistance;
}

// Whether `changes` leave the visible nodes, meshes, materials, textures and environment as they
// were, so that GpuScene::updateTransforms is enough.
bool onlyTransformsOrLights(const ChangeSet& changes) {
    const std::uint32_t enough = static_cast<std::uint32_t>(Change::Transform) | static_cast<std::uint32_t>(Change::Light) |
            static_cast<std::uint32_t>(Change::Camera) | static_cast<std::uint32_t>(Change::Animation) |
            static_cast<std::uint32_t>(Change::Display) | static_cast<std::uint32_t>(Change::Name) |
            static_cast<std::uint32_t>(Change::Project);
    return (changes.flags & ~enough) == 0;
}

// Material content alone: no image was re-encoded, nothing else changed.
bool onlyMaterials(const ChangeSet& changes) {
    return changes.flags == static_cast<std::uint32_t>(Change::Material) && changes.images.empty();
}

// World transforms of the nodes that carry geometry, for per-instance motion vectors.
std::map<NodeId, glm::mat4> instanceTransforms(const Scene& scene) {
    std::map<NodeId, glm::mat4> transforms;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (node.get<MeshInstance>() || node.get<Shape>()) transforms[id] = scene.worldFromNode(id);
    }
    return transforms;
}

// Samples per frame of real-time frames, and the bounce count the configuration allows.
int framesSpp(const FrameSettings& s) { return s.spp > 0 ? s.spp : traitsOf(s.configuration).sppPerFrame; }
int effectiveBounces(const FrameSettings& s) { return traitsOf(s.configuration).gi ? s.bounces : 0; }

// Settings whose change makes a different picture (everything but exposure, tonemapper, the
// sample cap and how the samples are sliced into frames).
bool sameImageSettings(const FrameSettings& a, const FrameSettings& b) {
    return a.configuration == b.configuration && framesSpp(a) == framesSpp(b) &&
           effectiveBounces(a) == effectiveBounces(b) && a.seed == b.seed && a.view == b.view && a.clamp == b.clamp && a.sampleBlock == b.sampleBlock &&
           a.independentSampler == b.independentSampler && a.aoDistance == b.aoDistance && a.areaLightStrategy == b.areaLightStrategy && a.width == b.width &&
           a.height == b.height && a.renderPasses == b.renderPasses && a.adaptive == b.adaptive;
}

} // namespace

// Size-dependent targets, re-made on a resize.
struct FrameTargets {
    FrameTargets(gl::ProgramCache& programs, int width, int height)
        : adaptive(programs, width, height), sample(makeGBuffer(width, height, adaptive.stopTexture())), frameMean(programs, width, height),
          stillMean(programs, width, height, adaptive.stopTexture()),
          display(width, height, {GL_RGBA8}), reconstruction(programs, width, height) {}
    AdaptiveSamplingPass adaptive; // before the targets its stops are attached to (sample, stillMean)
    gl::RenderTarget sample;     // one path-traced sample
    AccumulatePass frameMean;    // this frame's samples (real-time configurations with spp > 1)
    AccumulatePass stillMean;    // every sample since the picture last changed
    gl::RenderTarget display;    // tonemapped RGBA8
    Reconstruction reconstruction;
};

// The render passes' targets (FrameSettings::renderPasses), made only when they are asked for: the
// RENDER_PASSES variant's sample, the passes' running mean and the motion vectors.
struct RenderPassTargets {
    RenderPassTargets(gl::ProgramCache& programs, int width, int height, GLuint stopTexture)
        : sample(makeRenderPassesGBuffer(width, height, stopTexture)), mean(programs, width, height), motion(programs, width, height) {}
    gl::RenderTarget sample;
    RenderPassesMean mean;
    MotionPass motion;
};

// The low-resolution stand-in shown until the first full-resolution sample is complete
// (FrameSettings::previewDivisor): one sample, kept as a mean so that it reads like the full one.
struct PreviewTargets {
    PreviewTargets(gl::ProgramCache& programs, int width, int height)
        : sample(makeGBuffer(width, height)), mean(programs, width, height), display(width, height, {GL_RGBA8}) {}
    gl::RenderTarget sample;
    AccumulatePass mean;
    gl::RenderTarget display;
};

struct FrameRenderer::State {
    gl::ProgramCache programs; // before the passes that refer to it
    PathTracePass pathTrace{programs};
    TonemapPass tonemap{programs};
    MeanDenoisePass meanDenoise{programs};
    MeanDenoisePass previewDenoise{programs};
    BloomPass bloom{programs};
    BloomPass previewBloom{programs};
    SelectionOutlinePass outline{programs};
    std::unique_ptr<FrameTargets> targets;
    std::unique_ptr<PreviewTargets> preview;
    std::unique_ptr<RenderPassTargets> passTargets;

    FrameSettings settings;
    SceneSnapshot scene = snapshotOf(Scene{}, 0.0); // the document and the scene posed at scene.time
    std::filesystem::path environmentFile;
    MeshBvhCache meshCache; // mesh BVHs survive uploads: only changed meshes are rebuilt
    TextureCache textureCache; // decoded, mip-mapped images survive uploads: only new image bytes are decoded
    std::unique_ptr<GpuScene> gpu;
    Warnings noWarnings; // what warnings() returns before a scene is set
    bool followSceneCamera = false;
    std::string cameraName;
    CameraSetup camera;
    bool cameraSet = false;

    // History bookkeeping.
    CameraSetup previousCamera;
    std::map<NodeId, glm::mat4> previousInstances;
    std::map<NodeId, glm::mat4> instances;
    bool pictureChanged = true; // the still mean must restart
    bool shutterSample = false; // the next frame is one instant of a motion-blurred still: keep the mean
    bool historyValid = false;  // reprojection has a previous frame to read
    int frames = 0;
    std::uint32_t frameSampleIndex = 0; // real-time frames' sample counter: decorrelates frames
    const gl::RenderTarget* result = nullptr; // linear radiance of the last frame (attachment 0)
    bool previewShown = false;  // the preview stands for the picture: no full-resolution sample, or none filtered (denoiseInSteps)
    std::uint64_t shownIdsVersion = 0; // counts changes of shownGBuffer()'s object ids (the selection outline keeps its mask)
    int nextRow = 0;            // banded Accumulate: the first row of the sample in progress not traced
    FrameWork lastWork;
    int denoisedSamples = 0; // the still mean's sample count when it was last filtered; 0: not since it changed
    bool previewDenoised = false; // previewDenoise holds the filtered preview
    bool regionChanged = false; // set, moved or cleared since the last frame
    // The render passes' motion vectors measure from this camera and these instance transforms.
    std::optional<CameraSetup> motionCamera;
    std::map<NodeId, glm::mat4> motionInstances;
    RegionComposite region;     // with a render region: the image outside it stays (across resizes)

    void upload() {
        gpu = std::make_unique<GpuScene>(posed(), environmentFile, meshCache, &textureCache);
        instances = instanceTransforms(posed());
    }
    // Transforms (node animations included) and light parameters: shapes, lights, the top-level
    // BVH and the emissive triangles are re-uploaded; mesh BVHs, textures and materials stay.
    void uploadTransforms() {
        gpu->updateTransforms(posed());
        instances = instanceTransforms(posed());
    }
    const Scene& document() const { return *scene.document; }
    const Scene& posed() const { return *scene.posed; }
    FrameTargets& sized() {
        if (!targets || targets->sample.width() != settings.width || targets->sample.height() != settings.height) {
            passTargets.reset(); // their sample holds the old targets' stops
            targets = std::make_unique<FrameTargets>(programs, settings.width, settings.height);
            resetAll();
        }
        return *targets;
    }
    void resetAll() {
        pictureChanged = true;
        historyValid = false;
        frames = 0;
        frameSampleIndex = 0;
        result = nullptr;
        previewShown = false;
        nextRow = 0;
        forgetFiltered();
    }
    // The filtered mean is of an older picture (and a filtering in steps of it is of no use).
    void forgetFiltered() {
        denoisedSamples = 0;
        meanDenoise.cancel();
    }
    PathTraceSettings pathTraceSettings() const {
        const ConfigurationTraits traits = traitsOf(settings.configuration);
        // The real-time filters estimate noise from neighbouring pixels, which sample blocks correlate.
        const int sampleBlock = traits.accumulate ? settings.sampleBlock : 1;
        return {settings.seed, effectiveBounces(settings), settings.clamp, settings.independentSampler, settings.view,
                settings.aoDistance, traits.svgf, traits.ao, settings.areaLightStrategy, false, sampleBlock};
    }
    // Render passes are traced in whole Accumulate/Reference frames of the plain view only.
    bool renderingPasses() const {
        return settings.renderPasses && traitsOf(settings.configuration).accumulate && settings.view == DebugView::None &&
               settings.rowsPerFrame <= 0 && settings.previewDivisor <= 1;
    }
    RenderPassTargets& passes() {
        if (!passTargets || passTargets->sample.width() != settings.width || passTargets->sample.height() != settings.height)
            passTargets = std::make_unique<RenderPassTargets>(programs, settings.width, settings.height,
                                                              targets->adaptive.stopTexture());
        return *passTargets;
    }
    bool adaptive() const { return settings.adaptive.threshold > 0.0f && traitsOf(settings.configuration).accumulate; }
    // Whether the path tracer and the accumulations skip stopped pixels: not while none has stopped,
    // so until then every draw is the one a render without adaptive sampling makes.
    bool cullStopped() const { return adaptive() && targets->adaptive.anyStopped(); }
    bool adaptiveDone() const { return adaptive() && targets->adaptive.allStopped(); }
    void testAdaptive() {
        FrameTargets& t = *targets;
        const int n = t.stillMean.sampleCount();
        const int cap = settings.maxSamples > 0 ? settings.maxSamples : std::numeric_limits<int>::max();
        if (adaptive() && adaptiveTestDue(n, adaptiveMinSamples(settings.adaptive, cap)))
            t.adaptive.test(t.stillMean.mean(), t.stillMean.next(), n, settings.adaptive);
    }
    // Sample `index` of the still mean into `target`, but for stopped pixels where `culled`.
    void traceStillSample(const PathTraceSettings& pt, std::uint32_t index, const gl::RenderTarget& target, bool culled) {
        const CullStoppedPixels cull(culled);
        pathTrace.render(*gpu, camera, pt, index, target);
    }
    // One whole sample into the still mean, with the render passes where they are asked for.
    void traceAccumulatedSample(const PathTraceSettings& pt) {
        FrameTargets& t = *targets;
        const auto index = static_cast<std::uint32_t>(t.stillMean.sampleCount());
        const bool culled = cullStopped();
        if (!renderingPasses()) {
            traceStillSample(pt, index, t.sample, culled);
            t.stillMean.add(t.sample, culled);
            testAdaptive();
            return;
        }
        RenderPassTargets& p = passes();
        PathTraceSettings withPasses = pt;
        withPasses.renderPasses = true;
        traceStillSample(withPasses, index, p.sample, culled);
        t.stillMean.add(p.sample, culled); // targets 0-6: the beauty and the G-buffer, as without passes
        p.mean.add(p.sample, t.stillMean.sampleCount(), culled ? t.adaptive.stopTexture() : 0);
        testAdaptive();
    }
    void readRenderPasses(FrameImages& out);
    // The pixels the path tracer covers: the region plus the reconstruction's reach around it.
    // With adaptive sampling, grown to its whole tiles, whose stops depend on all their pixels.
    PixelRect tracedPixels() const {
        const ConfigurationTraits traits = traitsOf(settings.configuration);
        const int margin = reconstructionReach(traits, svgfSettingsOf(document().settings.render.svgf).iterations);
        const PixelRect traced = grown(regionPixels(settings.region, settings.width, settings.height), margin, settings.width, settings.height);
        return adaptive() ? alignedToTiles(traced, settings.width, settings.height) : traced;
    }
    void renderAccumulated();
    bool wantsPreview() const;
    void renderPreview();
    void traceRows();
    void renderRealTime();
    FrameImages readPreview();
    bool denoising() const;
    bool denoiseInSteps() const;
    bool denoiseDue(int samples) const;
    bool denoisePending() const;
    bool meanShown() const;
    const gl::RenderTarget& denoisedMean(bool exact);
    const gl::RenderTarget& shown(bool exact);
    const gl::RenderTarget& shownPreview();
    const gl::RenderTarget* shownGBuffer() const;
    void beginRegion();
    void endRegion();
};

// A new, moved or cleared region restarts the samples (inside it); a set one freezes the last
// image for the outside and keeps the path tracer and accumulation inside the region and its
// margin (tracedPixels) with the scissor.
void FrameRenderer::State::beginRegion() {
    if (regionChanged) {
        pictureChanged = true;
        historyValid = false;
        regionChanged = false;
        if (settings.region.active) region.freeze(result, settings.width, settings.height);
        else region.clear();
    }
    if (!settings.region.active) return;
    if (!region.fits(settings.width, settings.height)) region.freeze(result, settings.width, settings.height);
    if (!historyValid && !traitsOf(settings.configuration).accumulate) {
        // The filters also read beyond the margin (with weights too small to matter, but not 0):
        // zeros there, not whatever was rendered before, keep a region's frames the same in every
        // run, shard and chunk.
        targets->sample.clear();
        targets->frameMean.clear();
    }
    const PixelRect r = tracedPixels();
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, r.y, r.width, r.height);
}

void FrameRenderer::State::endRegion() {
    if (!settings.region.active) return;
    glDisable(GL_SCISSOR_TEST);
    if (result) region.update(*result, regionPixels(settings.region, settings.width, settings.height));
    result = &region.image();
}

void FrameRenderer::State::renderAccumulated() {
    FrameTargets& t = *targets;
    if (pictureChanged) {
        t.stillMean.reset();
        t.adaptive.reset(tracedPixels());
        nextRow = 0;
        previewShown = false;
        forgetFiltered();
    }
    pictureChanged = false;
    const bool meanShownBefore = t.stillMean.sampleCount() > 0 && !previewShown; // `result` is of the last picture
    const int limit = settings.maxSamples > 0 ? settings.maxSamples : std::numeric_limits<int>::max();
    if (denoisePending()) {
        lastWork.denoiseRows = meanDenoise.advance(t.stillMean.mean(), t.stillMean.sampleCount(), settings.denoiseRowsPerFrame);
        if (!meanDenoise.inProgress()) denoisedSamples = t.stillMean.sampleCount();
    } else if (wantsPreview()) {
        renderPreview();
    } else if (settings.rowsPerFrame > 0) {
        if (t.stillMean.sampleCount() < limit && !adaptiveDone()) traceRows();
    } else {
        const PathTraceSettings pt = pathTraceSettings();
        for (int i = 0; i < framesSpp(settings) && t.stillMean.sampleCount() < limit && !adaptiveDone(); ++i) {
            traceAccumulatedSample(pt);
            lastWork.rows += tracedPixels().height;
        }
    }
    result = t.stillMean.sampleCount() > 0 ? &t.stillMean.mean() : nullptr;
    // A filtering in steps keeps the preview up until the first filtered mean replaces it.
    if (result && !(denoiseInSteps() && denoisedSamples == 0)) previewShown = false;
    if (meanShown() && !meanShownBefore) ++shownIdsVersion; // the mean keeps its first sample's ids
}

// Whether drawTo() shows the still mean (filtered or not), not the preview or nothing.
bool FrameRenderer::State::meanShown() const { return result && !previewShown; }

bool FrameRenderer::State::denoiseInSteps() const { return denoising() && settings.denoiseRowsPerFrame > 0; }

// The filtered mean is refreshed as the mean grows (every sample up to 8, then at every 25 % more,
// and at the sample cap or when adaptive sampling has stopped every pixel): a pure function of the
// mean, so deterministic.
bool FrameRenderer::State::denoiseDue(int samples) const {
    const bool atCap = (settings.maxSamples > 0 && samples >= settings.maxSamples) || adaptiveDone();
    return samples > 0 && samples != denoisedSamples &&
           (denoisedSamples == 0 || samples <= 8 || 4 * samples >= 5 * denoisedSamples || atCap);
}

bool FrameRenderer::State::denoisePending() const {
    return denoiseInSteps() && targets && !pictureChanged && nextRow == 0 && denoiseDue(targets->stillMean.sampleCount());
}

bool FrameRenderer::State::wantsPreview() const {
    return settings.previewDivisor > 1 && !settings.region.active && !previewShown && nextRow == 0 &&
           targets->stillMean.sampleCount() == 0;
}

void FrameRenderer::State::renderPreview() {
    const int width = std::max(1, settings.width / settings.previewDivisor);
    const int height = std::max(1, settings.height / settings.previewDivisor);
    if (!preview || preview->sample.width() != width || preview->sample.height() != height)
        preview = std::make_unique<PreviewTargets>(programs, width, height);
    preview->mean.reset();
    pathTrace.render(*gpu, camera, pathTraceSettings(), 0, preview->sample);
    preview->mean.add(preview->sample);
    previewShown = true;
    previewDenoised = false;
    ++shownIdsVersion;
    lastWork.previewRows = height;
}

// One band of rows of the next sample, under a scissor inside the pixels the frame traces; the
// sample joins the mean with its last band.
void FrameRenderer::State::traceRows() {
    FrameTargets& t = *targets;
    const PixelRect traced = tracedPixels();
    const int end = traced.y + traced.height;
    nextRow = std::clamp(nextRow, traced.y, end);
    const int rows = std::min(settings.rowsPerFrame, end - nextRow);
    const bool culled = cullStopped();
    {
        const gl::ScissorGuard guard;
        glEnable(GL_SCISSOR_TEST);
        glScissor(traced.x, nextRow, traced.width, rows);
        traceStillSample(pathTraceSettings(), static_cast<std::uint32_t>(t.stillMean.sampleCount()), t.sample, culled);
    }
    nextRow += rows;
    lastWork.rows = rows;
    if (nextRow < end) return;
    t.stillMean.add(t.sample, culled);
    testAdaptive();
    nextRow = 0;
}

void FrameRenderer::State::renderRealTime() {
    FrameTargets& t = *targets;
    if (pictureChanged) {
        t.stillMean.reset();
        denoisedSamples = 0;
    }
    pictureChanged = false;
    const int spp = framesSpp(settings);
    const PathTraceSettings pt = pathTraceSettings();
    if (spp > 1) t.frameMean.reset();
    ++shownIdsVersion;
    lastWork.rows = spp * tracedPixels().height;
    for (int i = 0; i < spp; ++i) {
        pathTrace.render(*gpu, camera, pt, frameSampleIndex++, t.sample);
        t.stillMean.add(t.sample);
        if (spp > 1) t.frameMean.add(t.sample);
    }
    // The filters run on the whole frame: cheap next to path tracing, and anti-lag's per-stratum
    // target (a third of the size) would not match a scissor given in full-size pixels.
    glDisable(GL_SCISSOR_TEST);
    const gl::RenderTarget& frame = spp > 1 ? t.frameMean.mean() : t.sample;
    // The still view fades into the filtered mean, refreshed as it grows and exactly where the fade
    // ends; the first sample gets no weight (converge.frag.glsl), so a moving view skips the filter.
    const int stillSamples = t.stillMean.sampleCount();
    const gl::RenderTarget& stillMean = stillSamples > 1 ? denoisedMean(stillSamples == convergeFadeSamples) : t.stillMean.mean();
    ReconstructionInputs in{frame, stillMean, stillSamples, camera, previousCamera,
                            historyValid, traitsOf(settings.configuration), {}};
    for (const auto& [id, worldFromNode] : instances) {
        const auto previous = previousInstances.find(id);
        if (previous != previousInstances.end() && previous->second != worldFromNode)
            in.movedInstances.push_back({static_cast<float>(id.value), previous->second * glm::inverse(worldFromNode)});
    }
    t.reconstruction.taa = taaSettingsOf(document().settings.render.taa); // the project's, as the CLI renders it
    t.reconstruction.svgf = svgfSettingsOf(document().settings.render.svgf);
    result = &t.reconstruction.run(in);
    historyValid = true;
}

// The render passes of the still mean (layout: render_passes_pass.h), rows top-down, and the
// motion vectors from the motion reference (none set: the current camera and instances, so 0).
void FrameRenderer::State::readRenderPasses(FrameImages& out) {
    RenderPassTargets& p = passes();
    const int w = out.width;
    const int h = out.height;
    const auto rgb = [](const std::vector<float>& rgba) {
        std::vector<float> plane;
        plane.reserve(rgba.size() / 4 * 3);
        for (std::size_t i = 0; i < rgba.size(); i += 4) plane.insert(plane.end(), rgba.begin() + std::ptrdiff_t(i), rgba.begin() + std::ptrdiff_t(i + 3));
        return plane;
    };
    const auto plane = [&](int attachment) { return topDown(p.mean.mean().readRgba(attachment), w, h, 4); };
    const auto env = plane(0);
    const auto diffuseDirect = plane(1);
    const auto diffuseIndirect = plane(2);
    const auto glossyDirect = plane(3);
    const auto glossyIndirect = plane(4);
    auto& passes = out.lightPasses;
    passes[std::size_t(LightPass::DiffuseDirect)] = rgb(diffuseDirect);
    passes[std::size_t(LightPass::DiffuseIndirect)] = rgb(diffuseIndirect);
    passes[std::size_t(LightPass::GlossyDirect)] = rgb(glossyDirect);
    passes[std::size_t(LightPass::GlossyIndirect)] = rgb(glossyIndirect);
    auto& emission = passes[std::size_t(LightPass::Emission)];
    auto& environment = passes[std::size_t(LightPass::Environment)];
    for (std::size_t i = 0; i < env.size(); i += 4) {
        emission.insert(emission.end(), {diffuseDirect[i + 3], diffuseIndirect[i + 3], glossyDirect[i + 3]});
        environment.insert(environment.end(), {env[i + 1], env[i + 2], env[i + 3]});
    }
    // Motion from the first sample's depth and id (as the depth and id AOVs), in GL's pixels (y up).
    std::vector<MovedInstance> moved;
    for (const auto& [id, worldFromNode] : instances) {
        const auto previous = motionInstances.find(id);
        if (motionCamera && previous != motionInstances.end() && previous->second != worldFromNode)
            moved.push_back({static_cast<float>(id.value), previous->second * glm::inverse(worldFromNode)});
    }
    const auto motion = topDown(p.motion.execute(targets->stillMean.mean(), camera, motionCamera.value_or(camera), moved).readRgba(0), w, h, 2);
    out.vectors.reserve(motion.size());
    for (std::size_t i = 0; i < motion.size(); i += 2) out.vectors.insert(out.vectors.end(), {motion[i], -motion[i + 1]});
}

// The preview's images: one accumulated sample, at its own size.
FrameImages FrameRenderer::State::readPreview() {
    CallerGlState guard;
    FrameImages out;
    const gl::RenderTarget& mean = preview->mean.mean();
    const gl::RenderTarget& shown = shownPreview();
    out.width = mean.width();
    out.height = mean.height();
    out.window = imageWindowOf(PixelRect{0, 0, out.width, out.height}, out.height);
    tonemap.render(previewBloom.execute(shown, settings.bloom), camera.exposure + settings.exposure, settings.tonemapper.value_or(document().settings.render.tonemapper),
                   preview->display);
    out.tonemapped = topDown(preview->display.readRgba8(0), out.width, out.height, 4);
    out.radiance = topDown(shown.readRgba(0), out.width, out.height, 4);
    readGBuffer(mean, out);
    out.variance.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 3, 0.0f);
    return out;
}

bool FrameRenderer::State::denoising() const {
    return settings.denoise && traitsOf(settings.configuration).accumulate && !settings.region.active;
}

// The still mean filtered. Filtering a full-resolution mean costs a few frames' worth of fill on a
// slow GL, so unless `exact` it is refreshed only when due (denoiseDue).
const gl::RenderTarget& FrameRenderer::State::denoisedMean(bool exact) {
    const int n = targets->stillMean.sampleCount();
    // Filtering in steps, renderFrame() runs it: drawTo() shows what it last finished.
    const bool filterHere = exact ? n > 0 && n != denoisedSamples : denoiseDue(n) && !denoiseInSteps();
    if (filterHere) {
        meanDenoise.execute(targets->stillMean.mean(), n);
        denoisedSamples = n;
    }
    return denoisedSamples > 0 ? meanDenoise.output() : targets->stillMean.mean();
}

// What drawTo() and readImages() show of a full-resolution frame.
const gl::RenderTarget& FrameRenderer::State::shown(bool exact) {
    if (!denoising() || result != &targets->stillMean.mean()) return *result;
    return denoisedMean(exact);
}

const gl::RenderTarget& FrameRenderer::State::shownPreview() {
    if (!denoising()) return preview->mean.mean();
    if (!previewDenoised) previewDenoise.execute(preview->mean.mean(), 1); // once per preview, not per paint
    previewDenoised = true;
    return previewDenoise.output();
}

// The G-buffer whose first hits drawTo() shows (its object ids, depth, normals): the preview's, the
// still mean's (the first sample's ids and depths), or this frame's; null when nothing is shown.
const gl::RenderTarget* FrameRenderer::State::shownGBuffer() const {
    if (!meanShown()) return previewShown && preview ? &preview->mean.mean() : nullptr;
    if (traitsOf(settings.configuration).accumulate) return &targets->stillMean.mean();
    return framesSpp(settings) > 1 ? &targets->frameMean.mean() : &targets->sample;
}

int denoiseRowsPerFiltering(int height) { return MeanDenoisePass::stageCount() * std::max(1, height); }

FrameRenderer::FrameRenderer() : state_(std::make_unique<State>()) {}
FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::setScene(const Scene& scene, const std::filesystem::path& environmentFile) {
    CallerGlState guard;
    state_->scene = snapshotOf(scene, state_->scene.time);
    state_->environmentFile = environmentFile;
    state_->upload();
    state_->previousInstances = state_->instances;
    state_->resetAll();
}

void FrameRenderer::setPreparedScene(Scene document, double seconds, PreparedScene prepared) {
    CallerGlState guard;
    State& s = *state_;
    s.scene = snapshotOf(std::move(document), seconds);
    s.environmentFile = prepared.environmentFile;
    s.gpu = std::make_unique<GpuScene>(std::move(prepared));
    s.instances = instanceTransforms(s.posed());
    s.previousInstances = s.instances;
    s.resetAll();
}

bool FrameRenderer::mayApplyInPlace(const ChangeSet& changes) {
    return !affectsImage(changes) || onlyTransformsOrLights(changes) || onlyMaterials(changes);
}

bool FrameRenderer::applyChangesInPlace(const Scene& scene, const ChangeSet& changes) {
    State& s = *state_;
    if (!affectsImage(changes)) {
        s.scene = snapshotOf(scene, s.scene.time); // names, display settings: the posed scene follows too
        return true;
    }
    if (!s.gpu || !mayApplyInPlace(changes)) return false;
    CallerGlState guard;
    if (onlyTransformsOrLights(changes)) {
        s.scene = snapshotOf(scene, s.scene.time);
        s.uploadTransforms();
    } else {
        SceneSnapshot next = snapshotOf(scene, s.scene.time);
        if (!s.gpu->updateMaterials(*next.posed)) return false; // other textures or variant: nothing changed here
        s.scene = std::move(next);
    }
    s.pictureChanged = true;
    dropHistoryFor(changes);
    return true;
}

bool FrameRenderer::hasScene() const { return state_->gpu != nullptr; }

const Warnings& FrameRenderer::warnings() const { return state_->gpu ? state_->gpu->warnings() : state_->noWarnings; }

void FrameRenderer::applyChanges(const Scene& scene, const ChangeSet& changes) {
    if (applyChangesInPlace(scene, changes)) return;
    State& s = *state_;
    CallerGlState guard;
    s.scene = snapshotOf(scene, s.scene.time);
    s.upload(); // rebuilds the GPU scene, reusing the BVHs of unchanged meshes
    s.pictureChanged = true;
    dropHistoryFor(changes);
}

void FrameRenderer::dropHistoryFor(const ChangeSet& changes) {
    State& s = *state_;
    // Light edits keep the history: anti-lag (anti_lag_pass.h) shortens it where the lighting
    // changed, so a switched-off light goes in a frame and unchanged pixels stay converged. Edits
    // that change what surfaces are (materials, structure, environment image) or settings drop it.
    if (changes.has(Change::Settings) || changes.has(Change::Structure) || changes.has(Change::Material) ||
        changes.has(Change::Environment))
        s.historyValid = false;
}

void FrameRenderer::setSettings(const FrameSettings& settings) {
    State& s = *state_;
    const bool image = !sameImageSettings(s.settings, settings);
    if (!(settings.region == s.settings.region)) {
        s.regionChanged = true;
        if (s.targets) s.targets->stillMean.reset(); // the count restarts now (the mean's pixels stay)
        if (settings.region.active && s.result) { // keep the last image before a new size drops it
            CallerGlState guard;
            s.region.freeze(s.result, s.result->width(), s.result->height());
        }
    }
    s.settings = settings;
    if (image) s.resetAll();
}

void FrameRenderer::setCamera(const CameraSetup& camera) {
    State& s = *state_;
    s.followSceneCamera = false;
    if (s.cameraSet && sameCamera(camera, s.camera)) return;
    s.camera = camera;
    s.cameraSet = true;
    s.pictureChanged = true;
}

void FrameRenderer::useSceneCamera(const std::string& name) {
    state_->followSceneCamera = true;
    state_->cameraName = name;
}

void FrameRenderer::setTime(double seconds) {
    State& s = *state_;
    if (seconds == s.scene.time) return;
    if (!sceneAnimates(s.document())) {
        s.scene.time = seconds;
        return;
    }
    CallerGlState guard;
    s.scene = retimed(std::move(s.scene), seconds);
    if (s.gpu) s.uploadTransforms(); // animations move nodes (and cameras) only
    else s.upload();
    s.pictureChanged = true;
}

void FrameRenderer::setShutterTime(double seconds) {
    State& s = *state_;
    const bool changed = s.pictureChanged;
    setTime(seconds);
    s.pictureChanged = changed;
    s.shutterSample = true;
}

void FrameRenderer::setMotionReference(const CameraSetup& previousCamera, const Scene& previousPose) {
    state_->motionCamera = previousCamera;
    state_->motionInstances = instanceTransforms(previousPose);
}

void FrameRenderer::cut() { state_->historyValid = false; state_->pictureChanged = true; }

void FrameRenderer::resetHistory() { state_->resetAll(); }

void FrameRenderer::renderFrame() {
    State& s = *state_;
    if (!s.gpu) throw std::runtime_error("FrameRenderer: no scene set");
    CallerGlState guard;
    s.sized();
    if (s.followSceneCamera || !s.cameraSet) {
        const CameraSetup camera = resolveCamera(s.posed(), s.cameraName, s.settings.width, s.settings.height);
        if (!s.cameraSet || (!sameCamera(camera, s.camera) && !s.shutterSample)) s.pictureChanged = true;
        s.camera = camera;
        s.cameraSet = true;
    }
    s.lastWork = {};
    s.beginRegion();
    if (!s.historyValid) s.previousCamera = s.camera;
    if (traitsOf(s.settings.configuration).accumulate) s.renderAccumulated();
    else s.renderRealTime();
    s.endRegion();
    s.previousCamera = s.camera;
    s.previousInstances = s.instances;
    s.shutterSample = false;
    ++s.frames;
}

bool FrameRenderer::drawTo(unsigned int framebuffer, int width, int height) {
    State& s = *state_;
    const bool preview = s.previewShown;
    if (!s.result && !preview) return false;
    CallerGlState guard;
    const gl::RenderTarget& display = preview ? s.preview->display : s.targets->display;
    const gl::RenderTarget& linear = preview ? s.previewBloom.execute(s.shownPreview(), s.settings.bloom)
                                             : s.bloom.execute(s.shown(false), s.settings.bloom);
    s.tonemap.render(linear, s.camera.exposure + s.settings.exposure,
                     s.settings.tonemapper.value_or(s.document().settings.render.tonemapper), display);
    display.bindForDrawing(); // the display target becomes the read framebuffer below
    GLint displayFbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &displayFbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(displayFbo));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    const bool sameSize = width == display.width() && height == display.height();
    glBlitFramebuffer(0, 0, display.width(), display.height(), 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                      sameSize ? GL_NEAREST : GL_LINEAR);
    return true;
}

void FrameRenderer::drawOutline(unsigned int framebuffer, int width, int height, const std::vector<NodeId>& nodes) {
    State& s = *state_;
    const gl::RenderTarget* gbuffer = s.shownGBuffer();
    if (!gbuffer || nodes.empty()) return;
    CallerGlState guard;
    std::vector<std::uint32_t> ids;
    for (const NodeId node : nodes) ids.push_back(node.value);
    s.outline.draw(*gbuffer, s.shownIdsVersion, std::move(ids), framebuffer, width, height);
}

FrameImages FrameRenderer::readImages() {
    State& s = *state_;
    FrameImages out;
    if (s.previewShown) return s.readPreview();
    if (!s.result) return out;
    CallerGlState guard;
    FrameTargets& t = *s.targets;
    out.width = t.sample.width();
    out.height = t.sample.height();
    out.window = imageWindowOf(regionPixels(s.settings.region, out.width, out.height), out.height);
    const gl::RenderTarget& shown = s.shown(true);
    const gl::RenderTarget& bloomed = s.bloom.execute(shown, s.settings.bloom);
    s.tonemap.render(bloomed, s.camera.exposure + s.settings.exposure,
                     s.settings.tonemapper.value_or(s.document().settings.render.tonemapper), t.display);
    out.tonemapped = topDown(t.display.readRgba8(0), out.width, out.height, 4);
    out.radiance = topDown((s.settings.bloomLinear ? bloomed : shown).readRgba(0), out.width, out.height, 4);
    readGBuffer(*s.shownGBuffer(), out);
    if (traitsOf(s.settings.configuration).accumulate) {
        const int samples = t.stillMean.sampleCount();
        out.sampleCounts = s.adaptive() ? topDown(t.adaptive.sampleCounts(samples), out.width, out.height, 1, 1)
                                        : std::vector<float>(std::size_t(out.width) * std::size_t(out.height), float(samples));
        out.variance = sampleVariance(out.radiance, topDown(t.stillMean.mean().readRgba(radianceSquaredAttachment), out.width, out.height, 4),
                                      samples, out.sampleCounts);
        if (s.renderingPasses() && s.passTargets) s.readRenderPasses(out);
    } else {
        out.motion = topDown(t.reconstruction.motion().readRgba(0), out.width, out.height, 2);
    }
    return out;
}

int FrameRenderer::sampleCount() const {
    const State& s = *state_;
    if (!s.targets || s.pictureChanged || !s.result) return 0;
    return s.targets->stillMean.sampleCount();
}

bool FrameRenderer::converged() const {
    const State& s = *state_;
    return s.targets && !s.pictureChanged && s.adaptiveDone();
}

std::optional<double> FrameRenderer::convergedShare() const {
    const State& s = *state_;
    if (!s.adaptive()) return std::nullopt;
    if (!s.targets || s.pictureChanged) return 0.0;
    const PixelRect traced = s.tracedPixels();
    return double(s.targets->adaptive.stoppedPixels()) / double(std::max(1, traced.width * traced.height));
}

ImageStage FrameRenderer::imageStage() const {
    const State& s = *state_;
    if (s.pictureChanged) return ImageStage::None;
    if (s.nextRow > 0) return ImageStage::Refining;
    if (s.previewShown) return ImageStage::Preview;
    if (s.result) return ImageStage::Complete;
    return ImageStage::None;
}

int FrameRenderer::rowsTraced() const {
    const State& s = *state_;
    return s.nextRow > 0 ? s.nextRow - s.tracedPixels().y : 0;
}

int FrameRenderer::rowsToTrace() const { return state_->tracedPixels().height; }
bool FrameRenderer::previewShown() const { return state_->previewShown; }
bool FrameRenderer::denoisePending() const { return state_->denoisePending(); }
FrameWork FrameRenderer::lastFrameWork() const { return state_->lastWork; }
int FrameRenderer::frameIndex() const { return state_->frames; }
const FrameSettings& FrameRenderer::settings() const { return state_->settings; }

} // namespace glint::renderer
