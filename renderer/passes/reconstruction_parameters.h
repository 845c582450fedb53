#pragma once
// The project's reconstruction parameters (scene/core/settings.h) as the passes take them. The
// project file keeps them in the document, so the editor and the command line filter alike.
#include "renderer/passes/svgf_pass.h"
#include "renderer/passes/taa_pass.h"
#include "scene/core/settings.h"

namespace glint::renderer {

inline TaaSettings taaSettingsOf(const TaaParameters& p) { return {p.blend, p.clipGamma, p.perceptualBlend}; }

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
