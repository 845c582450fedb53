// The first hit's radiance split by the lobe that carried it, for the denoiser (SVGF filters the
// two apart, each demodulated by its own albedo: albedo_split.glsl). The split is a partition of
// the path's contributions, so diffuse + specular = radiance up to float rounding:
// - next-event estimation at the first hit: each light sample by the share of the BSDF value that
//   the diffuse (Lambert) lobe holds in that direction;
// - everything found after the first bounce: the lobe that bounce sampled (diffuse, or any of the
//   specular ones: metal, the dielectric layer, glass reflection and transmission);
// - the first hit's emission, misses and Baseline's ambient term: diffuse (they pass the filter's
//   demodulation unchanged).
// `reflectionDistance`: how far the first bounce's ray went when that bounce was a reflection by a
// specular lobe (metal, the dielectric layer, glass reflection): what SVGF's virtual motion vectors
// place the reflected image by (motion.frag.glsl). 0: no such bounce (a diffuse or transmitted
// bounce, or none); REFLECTION_AT_INFINITY: it left the scene (the image moves with rotation only).
struct LobeRadiance {
    vec3 diffuse;
    vec3 specular;
    float reflectionDistance;
};

const float REFLECTION_AT_INFINITY = 1.0e20; // far enough, and finite through a 4x4 transform

LobeRadiance noLobeRadiance() { return LobeRadiance(vec3(0.0), vec3(0.0), 0.0); }

// f * cos(wi) of the diffuse lobe alone: the Lambert term of opaqueEval (bsdf/bsdf.glsl).
vec3 diffuseLobeEval(SurfaceMaterial m, vec3 wo, vec3 wi) {
    if (wo.z == 0.0) return vec3(0.0);
    BsdfLobes l = bsdfLobes(m, wo.z);
    vec3 woUp = wo.z > 0.0 ? wo : flipZ(wo);
    vec3 wiUp = wo.z > 0.0 ? wi : flipZ(wi);
    if (wiUp.z <= 0.0) return vec3(0.0);
    float diffuseScale = (1.0 - layerReflectance(m, l, woUp.z)) * (1.0 - layerReflectance(m, l, wiUp.z)) /
                         max(1.0 - layerAverageReflectance(m, l), 1e-6);
    return l.layered * diffuseScale * m.baseColor * lambertReflection(woUp, wiUp);
}

// The diffuse lobe's part of a light sample's `contribution` (proportional to bsdfEval(m, wo, wi)).
vec3 diffusePart(SurfaceMaterial m, vec3 wo, vec3 wi, vec3 contribution) {
    float pdf;
    vec3 f = bsdfEval(m, wo, wi, pdf);
    vec3 share = clamp(diffuseLobeEval(m, wo, wi) / max(f, vec3(1e-30)), 0.0, 1.0);
    return contribution * mix(vec3(0.0), share, greaterThan(f, vec3(0.0)));
}

void addRadiance(INOUT(vec3) radiance, INOUT(LobeRadiance) lobes, vec3 c, bool specular) {
    radiance += c;
    if (specular) lobes.specular += c;
    else lobes.diffuse += c;
}

// `c` of which `diffuse` went through the diffuse lobe, the rest through the others.
void addSplitRadiance(INOUT(vec3) radiance, INOUT(LobeRadiance) lobes, vec3 c, vec3 diffuse) {
    radiance += c;
    lobes.diffuse += diffuse;
    lobes.specular += c - diffuse;
}

// The per-sample clamp keeps the lobes' proportions.
void clampRadiance(INOUT(vec3) radiance, INOUT(LobeRadiance) lobes, float limit) {
    vec3 clamped = min(radiance, vec3(limit));
    vec3 scale = mix(vec3(1.0), clamped / max(radiance, vec3(1e-30)), greaterThan(radiance, clamped));
    lobes.diffuse *= scale;
    lobes.specular *= scale;
    PASSES_SCALE(scale); // render_passes.glsl
    radiance = clamped;
}
