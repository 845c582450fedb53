#pragma once
// A frame-based renderer that lives inside any current OpenGL 4.1 core context: the headless EGL one
// (OfflineRenderer, tests, bench) or a QOpenGLWidget's. It never creates, owns or switches a context,
// draws only into its own targets and the framebuffer a caller names, and restores the caller's
// framebuffer bindings and viewport after every call (it never assumes framebuffer 0).
//
// Each renderFrame() is one frame of the configuration: Accumulate/Reference add samples to a running
// mean; the real-time configurations render a few samples and reconstruct them with history (motion
// vectors, SVGF, TAA), fading into the running mean while nothing moves, so a still view converges to
// the accumulated image. Exposure and tonemapper are applied in drawTo()/readImages() and never reset
// anything. All methods must be called with the creating context current; no GL header is needed here.
#include "renderer/configuration.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/prepared_scene.h"
#include "renderer/passes/bloom_pass.h"
#include "renderer/passes/path_trace_pass.h"
#include "renderer/render_region.h"
#include "scene/core/scene.h"
#include "scene/history/change_set.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace glint::renderer {

struct FrameSettings {
    Configuration configuration = Configuration::Accumulate;
    int spp = 0;            // samples per pixel per frame; 0 = the configuration's own (traitsOf)
    int maxSamples = 0;     // Accumulate/Reference stop adding samples here; 0 = no limit (raising it
                            // continues the mean)
    int bounces = 4;        // the configuration may lower it (Baseline: 0)
    std::uint32_t seed = 0;
    float exposure = 0.0f;  // EV added to the camera's
    std::optional<Tonemapper> tonemapper; // unset: the project's
    DebugView view = DebugView::None;
    float clamp = 0.0f;     // per-sample radiance clamp; 0 = off
    int sampleBlock = 1;    // Accumulate/Reference: pixels per side sharing a sample sequence (RenderSettings)
    bool independentSampler = false;
    float aoDistance = 1.0f;
    AreaLightStrategy areaLightStrategy = AreaLightStrategy::Mis; // tests only: one strategy alone
    int width = 640;
    int height = 360;
    // Samples go only into this region; outside it the last image stays (renderer/render_region.h).
    // Accumulation, reconstruction and sampleCount() then refer to the region's pixels; the
    // G-buffer images read back are valid inside it only. Real-time configurations path trace a
    // margin around it as wide as their filters reach (reconstructionReach), so the filters at the
    // region's edge read this frame's samples, not the frozen image's.
    RenderRegion region;
    // Progressive refinement on a slow GL (the viewport), Accumulate/Reference only; neither
    // changes the picture, so changing them keeps the mean. rowsPerFrame > 0: each renderFrame()
    // traces this many rows of the next sample (under a scissor), and the sample joins the mean
    // when its last row is traced; the pixels equal those of whole-frame samples. previewDivisor > 1:
    // until the first full-resolution sample is complete, one sample at 1/previewDivisor of the
    // size stands in (one renderFrame() call; drawTo() shows it scaled up). Not with a region.
    int rowsPerFrame = 0;
    int previewDivisor = 1;
    // Accumulate/Reference: drawTo() and readImages() show the mean filtered by MeanDenoisePass
    // (guided by albedo, normal and depth, its strength falling with the mean's variance), the
    // preview too; the mean itself stays raw. Display-only: changing it keeps the mean. (The
    // real-time configurations always fade into the filtered mean.) Not with a region.
    bool denoise = false;
    // With denoise, Accumulate/Reference: > 0 filters each new mean in steps of this many rows of
    // the filter's stages (MeanDenoisePass::advance), one step per renderFrame() in place of
    // tracing, so the mean being filtered holds still and the filtered pixels are those of a whole
    // filtering; until a step finishes it, drawTo() shows the last filtered mean (the preview, while
    // none is). 0: drawTo() filters whole. Display-only, like rowsPerFrame.
    int denoiseRowsPerFrame = 0;
    // Bloom on what drawTo() and readImages() show, before tone mapping (display-only: it keeps
    // every history). The linear radiance readImages() gives (EXR) stays unbloomed unless
    // bloomLinear.
    BloomSettings bloom;
    bool bloomLinear = false;
    // The EXR's render passes (FrameImages::lightPasses and vectors): Accumulate/Reference whole
    // frames only (no bands, no preview), where the path tracer's RENDER_PASSES variant writes them
    // (shaders/pathtrace/render_passes.glsl). Off, nothing of them is compiled, allocated or run.
    // The light passes sum to the raw mean (what readImages() gives without denoise and
    // bloomLinear); on, diffuseAlbedo and specularAlbedo read back hold passes, not albedos.
    bool renderPasses = false;
    // Adaptive sampling (Accumulate/Reference; renderer/passes/adaptive_sampling.h): pixels whose
    // mean has converged stop taking samples. threshold 0: off. minSamples 0: automatic, clamped to
    // maxSamples (the offline renderer passes its spp resolved: frameSettingsFor).
    AdaptiveSampling adaptive;
    friend bool operator==(const FrameSettings&, const FrameSettings&) = default;
};

// What the last renderFrame() traced: full-resolution rows (all of them for whole frames, times
// their samples), or the preview's rows.
struct FrameWork {
    int rows = 0;
    int previewRows = 0;
    int denoiseRows = 0; // rows of the still mean's filter stages (FrameSettings::denoiseRowsPerFrame)
};

// The rows of one whole filtering of a still mean `height` rows high, as FrameWork::denoiseRows
// counts them (every stage's rows).
int denoiseRowsPerFiltering(int height);

// Where the shown image stands, for a host that schedules frames (the viewport).
enum class ImageStage {
    None,       // nothing of the current picture yet (drawTo() draws nothing)
    Preview,    // the low-resolution stand-in (FrameSettings::previewDivisor)
    Refining,   // full resolution; a sample is partly traced (samples may still be 0: the preview shows)
    Complete,   // full resolution, every sample whole
};

// The light passes of FrameImages::lightPasses, which sum to the radiance (docs/CLI.md, "Render
// passes"): the EXR layers DiffDir, DiffInd, GlossDir, GlossInd, Emit and Env, in that order.
enum class LightPass { DiffuseDirect, DiffuseIndirect, GlossyDirect, GlossyIndirect, Emission, Environment };
inline constexpr int lightPassCount = 6;

// Linear images read back from the last frame, rows top-down (as image files want them).
struct FrameImages {
    int width = 0;
    int height = 0;
    ImageWindow window;           // the pixels this frame rendered: the region, else the whole image
                                  // (empty: the whole image too)
    std::vector<float> radiance;  // RGBA: linear Rec.709, A = coverage (the reconstructed frame)
    std::vector<float> albedo;    // RGB
    std::vector<float> normal;    // XYZ, world space
    std::vector<float> depth;     // along the view axis in metres, +inf where nothing is hit
    std::vector<float> objectId;  // node id, 0 where nothing is hit
    std::vector<float> diffuseAlbedo;  // RGB, what the denoiser demodulates by (with specularAlbedo)
    std::vector<float> specularAlbedo; // RGBA: A = roughness
    std::vector<float> variance;  // RGB sample variance of one sample (Accumulate/Reference; else empty)
    std::vector<float> sampleCounts; // samples in each pixel's mean (Accumulate/Reference; else empty):
                                     // fewer where adaptive sampling stopped the pixel
    std::vector<float> motion;    // RG: previous minus current position in pixels (real-time configs)
    std::vector<std::uint8_t> tonemapped; // RGBA8, sRGB, as drawTo shows it
    std::vector<float> bvhCost;   // the optional bvh_cost AOV (renderer/bvh_cost_render.h); else empty
    // FrameSettings::renderPasses (else empty): RGB each, indexed by LightPass; and the motion
    // vectors, XY in pixels: where the pixel's surface was at the motion reference
    // (setMotionReference) minus where it is now, x to the right, y down (image rows).
    std::array<std::vector<float>, lightPassCount> lightPasses;
    std::vector<float> vectors;
};

class FrameRenderer {
public:
    FrameRenderer();  // uses the current context; compiles lazily
    ~FrameRenderer(); // the same context must be current
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    // Full upload. `environmentFile`: an equirectangular image or empty (the project's colour).
    // Throws std::runtime_error when the scene exceeds GPU limits or a file cannot be read.
    void setScene(const Scene& scene, const std::filesystem::path& environmentFile = {});
    // Resets accumulation only if the picture changes (affectsImage). Transform and light edits
    // re-upload shapes, lights and the top-level BVH alone; other image changes rebuild the GPU
    // scene, reusing the BVHs of unchanged meshes.
    void applyChanges(const Scene& scene, const ChangeSet& changes);
    // The GL stage of setScene alone, for a host that prepares on a worker thread: uploads what
    // prepareScene made of the document posed at `seconds` (renderer/scene_snapshot.h).
    void setPreparedScene(Scene document, double seconds, PreparedScene prepared);
    // Whether changes like these may be applied without a new GPU scene (transforms, lights,
    // material values; a material edit that needs other textures still returns false below).
    static bool mayApplyInPlace(const ChangeSet& changes);
    // applyChanges when it needs no new GPU scene (true); else false and nothing is changed: the
    // host prepares a new scene (setScene or setPreparedScene).
    bool applyChangesInPlace(const Scene& scene, const ChangeSet& changes);
    bool hasScene() const;
    // Problems of the current GPU scene that did not stop it (missing or undecodable textures,
    // resampled texture sizes), each naming the texture; `file` is left to the host.
    const Warnings& warnings() const;
    void setSettings(const FrameSettings& settings); // display-only changes keep all history
    void setCamera(const CameraSetup& camera);       // a moving camera keeps reprojected history
    // Follow the scene's camera (by name, empty = active) at the current time instead of setCamera.
    void useSceneCamera(const std::string& name = {});
    void setTime(double seconds); // node animations (and a followed camera) at this time
    // The same for the next sample of a motion-blurred still: the accumulation goes on, so the mean
    // averages the scene over the instants its samples were given.
    void setShutterTime(double seconds);
    void cut();                   // camera cut: history is dropped, as after a resize
    // What the render passes' motion vectors (FrameImages::vectors) measure from: the camera and
    // the scene (its instances' world transforms) of the previous frame. Unset: no motion.
    void setMotionReference(const CameraSetup& previousCamera, const Scene& previousPose);

    void renderFrame();
    // Tonemaps the last frame into `framebuffer` (any id, 0 included) scaled to width x height.
    // False, drawing nothing, while no frame of the current scene has been rendered yet.
    bool drawTo(unsigned int framebuffer, int width, int height);
    // Outlines the objects `nodes` (any order) over what drawTo() drew into `framebuffer`
    // at width x height, along the edges of their pixels as the shown image's first hits see them:
    // the preview's, the accumulated mean's or this frame's (renderer/passes/selection_outline_pass.h).
    // Display only. Draws nothing while drawTo() would draw nothing.
    void drawOutline(unsigned int framebuffer, int width, int height, const std::vector<NodeId>& nodes);
    FrameImages readImages();

    // Samples in the running mean behind the current frame; 0 as soon as the picture changed (scene,
    // camera, size, settings, time), before the next renderFrame() renders it.
    int sampleCount() const;
    // Adaptive sampling stopped every pixel it traces: more frames add nothing.
    bool converged() const;
    // The share of the traced pixels adaptive sampling has stopped in the current picture, 0 to 1;
    // unset without adaptive sampling.
    std::optional<double> convergedShare() const;
    ImageStage imageStage() const;
    // Rows of the sample in progress already traced, of rowsToTrace() (banded Accumulate).
    int rowsTraced() const;
    int rowsToTrace() const;
    bool previewShown() const; // the preview stands in for the picture (no full sample, or none filtered yet)
    // A filtering of the mean is due or under way in steps (FrameSettings::denoiseRowsPerFrame):
    // the next renderFrame() calls run it, and what drawTo() shows changes when they finish it.
    bool denoisePending() const;
    FrameWork lastFrameWork() const;
    int frameIndex() const;    // frames rendered since the last reset
    void resetHistory();
    const FrameSettings& settings() const;

private:
    void dropHistoryFor(const ChangeSet& changes);
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace glint::renderer
