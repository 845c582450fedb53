#pragma once
// The real-time reconstruction chain of one frame: motion vectors -> anti-lag -> SVGF -> TAA -> fade
// into the still mean (converge.frag.glsl). Each stage is its own pass with its own shaders; this
// class wires their targets and keeps the previous frame's normal + depth and id for disocclusion
// tests.
#include "renderer/configuration.h"
#include "renderer/passes/anti_lag_pass.h"
#include "renderer/passes/motion_pass.h"
#include "renderer/passes/svgf_pass.h"
#include "renderer/passes/taa_pass.h"

#include <vector>

namespace glint::renderer {

// Samples after which a still view shows the filtered accumulated mean alone (the real-time
// filters faded out; the mean denoiser's strength falls on with the mean's variance).
inline constexpr int convergeFadeSamples = 16;

struct ReconstructionInputs {
    const gl::RenderTarget& frame;     // this frame's G-buffer (path_trace_pass.h attachments)
    const gl::RenderTarget& stillMean; // running mean since the picture last changed
    int stillSamples = 0;
    const CameraSetup& camera;
    const CameraSetup& previousCamera;
    bool historyValid = false;         // false after resets, cuts and resizes
    ConfigurationTraits traits;
    std::vector<MovedInstance> movedInstances;
};

class Reconstruction {
public:
    Reconstruction(gl::ProgramCache& programs, int width, int height);
    // Returns the target whose attachment 0 holds the frame's linear radiance.
    const gl::RenderTarget& run(const ReconstructionInputs& in);
    const gl::RenderTarget& motion() const { return motion_.output(); }
    const AntiLagPass& antiLag() const { return antiLag_; }

    TaaSettings taa;
    SvgfSettings svgf;
    AntiLagSettings antiLagSettings;

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    MotionPass motion_;
    AntiLagPass antiLag_;
    SvgfPass svgfPass_;
    TaaPass taaPass_;
    gl::RenderTarget previousGBuffer_; // 0: normal + depth, 1: id
    gl::RenderTarget output_;
};

} // namespace glint::renderer
