#include "renderer/passes/bloom_pass.h"

#include <algorithm>
#include <cmath>

namespace glint::renderer {

int bloomLevels(float radius, int height) {
    const double span = std::max(1.0, double(radius) * double(height));
    return std::clamp(int(std::ceil(std::log2(span))), 1, 8);
}

BloomPass::BloomPass(gl::ProgramCache& programs) : programs_(programs) {}
BloomPass::~BloomPass() = default;

const gl::RenderTarget& BloomPass::execute(const gl::RenderTarget& image, const BloomSettings& settings) {
    if (!(settings.strength > 0.0f)) return image;
    const int levels = bloomLevels(settings.radius, image.height());
    const auto sizeOf = [&](int level) { // level 0: the image; halves, rounded up
        int w = image.width(), h = image.height();
        for (int i = 0; i < level; ++i) w = std::max(1, (w + 1) / 2), h = std::max(1, (h + 1) / 2);
        return std::pair{w, h};
    };
    const bool resized = !output_ || output_->width() != image.width() || output_->height() != image.height() ||
                         int(down_.size()) != levels;
    if (resized) {
        down_.clear();
        up_.clear();
        for (int i = 1; i <= levels; ++i) {
            const auto [w, h] = sizeOf(i);
            down_.emplace_back(w, h, std::vector<GLenum>{GL_RGBA32F});
            if (i < levels) up_.emplace_back(w, h, std::vector<GLenum>{GL_RGBA32F});
        }
        output_ = std::make_unique<gl::RenderTarget>(image.width(), image.height(), std::vector<GLenum>{GL_RGBA32F});
    }
    const gl::RenderTarget* source = &image;
    for (gl::RenderTarget& level : down_) {
        runStage(programs_, triangle_, {"passes/bloom_downsample.frag.glsl", {"outColor"}, {{"uSource", *source, 0}}, {}}, level);
        source = &level;
    }
    const gl::RenderTarget* sum = &down_.back();
    for (int i = levels - 2; i >= 0; --i) { // up_[i] = down_[i] + the sum of the levels below it
        runStage(programs_, triangle_,
                 {"passes/bloom_upsample.frag.glsl", {"outColor"}, {{"uCoarser", *sum, 0}, {"uLevel", down_[std::size_t(i)], 0}}, {}},
                 up_[std::size_t(i)]);
        sum = &up_[std::size_t(i)];
    }
    runStage(programs_, triangle_,
             {"passes/bloom_composite.frag.glsl",
              {"outColor"},
              {{"uImage", image, 0}, {"uLevels", *sum, 0}},
              [&](const gl::ShaderProgram& p) {
                  glUniform1f(p.uniform("uLevelCount"), float(levels));
                  glUniform1f(p.uniform("uStrength"), std::min(settings.strength, 1.0f));
              }},
             *output_);
    return *output_;
}

} // namespace glint::renderer
