#pragma once
// The project's reconstruction parameters (scene/core/settings.h) as the passes take them. The
// project file keeps them in the document, so the editor and the command line filter alike.
#include "renderer/passes/svgf_pass.h"
#include "renderer/passes/taa_pass.h"
#include "scene/core/settings.h"

namespace glint::renderer {

inline TaaSettings taaSettingsOf(const TaaParameters& p) {
    TaaSettings s;
    s.minBlend = p.blend;
    s.clipMode = static_cast<int>(p.clip); // taa.frag.glsl's uClipMode: the enum's order
    s.clipGamma = p.clipGamma;
    s.perceptualBlend = p.perceptualBlend;
    return s;
}

inline SvgfSettings svgfSettingsOf(const SvgfParameters& p) {
    SvgfSettings s;
    s.iterations = p.iterations;
    s.alpha = p.alpha;
    s.momentsAlpha = p.momentsAlpha;
    s.sigmaLuminance = p.sigmaLuminance;
    s.sigmaNormal = p.sigmaNormal;
    s.sigmaDepth = p.sigmaDepth;
    s.fireflyRatio = p.fireflyRatio;
    return s;
}

} // namespace glint::renderer
