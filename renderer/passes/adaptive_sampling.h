#pragma once
// Adaptive sampling for Accumulate and Reference stills (AdaptiveSampling in scene/core/settings.h):
// every few samples a test stops the pixels whose mean has converged. The stops live in a depth
// texture attached to the path tracer's targets: a pixel still sampling holds 1, a stopped one
// n / 2^24, n being the samples in its mean. The path tracer and the accumulation draw their
// full-screen triangles at depth 0.5 under GL_LESS (CullStoppedPixels), so stopped pixels fail the
// early depth test and cost nothing; the test copies a pixel's mean into the accumulation's other
// target as it stops, so both targets of the ping-pong hold it. (The render passes' mean, rarely
// asked for, reads the stops instead: ADAPTIVE_STOPS in shaders/passes/adaptive_stop.glsl.)
// Pixels stop by tiles of adaptiveTile x adaptiveTile (from the bottom-left corner), when every
// pixel of the tile has converged: GPUs shade pixels in groups, so a lone pixel still sampling costs
// its group anyway. A tile's stop depends on its own pixels alone, and a region traces whole tiles
// (alignedToTiles), so the same pixels stop for the same seed in a region, a shard and the whole
// image, on every node.
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "renderer/render_region.h"
#include "scene/core/settings.h"

#include <optional>
#include <vector>

namespace glint::renderer {

inline constexpr int adaptiveTile = 8;

// `rect` grown to whole tiles, clipped to the width x height image.
PixelRect alignedToTiles(const PixelRect& rect, int width, int height);

// Samples before the first test: the setting's, else automatic (Even: Cycles' 16 / threshold^0.3;
// Mean: 16), at least 2 (one sample has no variance) and at most `spp`.
int adaptiveMinSamples(const AdaptiveSampling& settings, int spp);
// Whether the test runs once the mean holds `samples`: at the minimum, then every 4 samples.
bool adaptiveTestDue(int samples, int minSamples);

class AdaptiveSamplingPass {
public:
    AdaptiveSamplingPass(gl::ProgramCache& programs, int width, int height);
    // The depth texture to attach to every target the path tracer draws (gl::RenderTarget).
    GLuint stopTexture() const { return stops_.get(); }
    // Every pixel samples again; `traced` pixels are counted as sampling.
    void reset(const PixelRect& traced);
    // Stops the pixels whose `mean` (an accumulation buffer of `samples` samples) has converged by
    // the settings' goal and threshold, and copies their mean into `next` (the accumulation's other
    // target, which has the stops attached). Draws into the traced pixels only when the caller's
    // scissor is set.
    void test(const gl::RenderTarget& mean, const gl::RenderTarget& next, int samples, const AdaptiveSampling& settings);
    bool anyStopped() const { return stopped_ > 0; }
    bool allStopped() const { return stopped_ >= traced_; }
    int stoppedPixels() const { return stopped_; }
    // Samples in each pixel's mean, rows bottom-up as GL stores them: `samples` (the running mean's
    // count) where the pixel still samples.
    std::vector<float> sampleCounts(int samples) const;

private:
    void markConvergedTiles(const gl::RenderTarget& mean, int samples, const AdaptiveSampling& settings);

    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    int width_;
    int height_;
    gl::Texture stops_;
    gl::Framebuffer fbo_;
    gl::RenderTarget tiles_; // 1 per converged tile
    gl::Query query_;
    int traced_ = 0;
    int stopped_ = 0;
};

// Binds the stops as `uStopDepth` of shaders/passes/adaptive_stop.glsl on texture `unit`.
void bindStopTexture(GLuint stopTexture, GLuint unit, const gl::ShaderProgram& program);

// The depth state a pass changes, to put back when it ends.
struct SavedDepthState {
    GLboolean test = GL_FALSE;
    GLboolean mask = GL_TRUE;
    GLint func = GL_LESS;
    static SavedDepthState current();
    void restore() const;
};

// While alive: the depth test that keeps stopped pixels out of the path tracer's draw (depth writes
// off), restoring the depth state it found.
class CullStoppedPixels {
public:
    explicit CullStoppedPixels(bool active);
    ~CullStoppedPixels();
    CullStoppedPixels(const CullStoppedPixels&) = delete;
    CullStoppedPixels& operator=(const CullStoppedPixels&) = delete;

private:
    std::optional<SavedDepthState> saved_;
};

} // namespace glint::renderer
