#pragma once
// An energy-conserving bloom on linear radiance, before tone mapping: a chain of half-size levels
// (each a 4x4 tent of the one above), summed back up bilinearly, and the image mixed with the mean of
// those blurs by `strength`. Each filter keeps the image's mean, so bloom spreads light without
// adding any (a bright lamp's glare takes its energy from the lamp). Deterministic: texelFetch
// filtering only. Inputs: attachment 0 of a radiance target. Stages: down x N -> up x (N - 1) ->
// composite. Targets follow the input's size.
#include "renderer/passes/fullscreen_stage.h"

#include <memory>
#include <vector>

namespace glint::renderer {

struct BloomSettings {
    float strength = 0.0f; // 0: off (the pass returns its input); the share of light spread
    float radius = 0.05f;  // the widest blur, as a fraction of the image height
    friend bool operator==(const BloomSettings&, const BloomSettings&) = default;
};

// Levels of the chain for an image `height` pixels high: the widest blur spans about
// radius x height pixels, at least 1 level, at most 8.
int bloomLevels(float radius, int height);

class BloomPass {
public:
    explicit BloomPass(gl::ProgramCache& programs);
    ~BloomPass();
    // `image` itself when strength is 0.
    const gl::RenderTarget& execute(const gl::RenderTarget& image, const BloomSettings& settings);

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    std::vector<gl::RenderTarget> down_; // levels 1..N
    std::vector<gl::RenderTarget> up_;   // sums of levels i..N, for i = 1..N-1
    std::unique_ptr<gl::RenderTarget> output_;
};

} // namespace glint::renderer
