// A dielectric interface: smooth (delta) or rough (Walter et al. 2007 with visible-normal sampling,
// following pbrt-v4's DielectricBxDF), with total internal reflection, or a thin wall whose
// transmission does not bend. Transmission is tinted by `tint`; reflection is not. Refracted radiance
// is scaled by 1 / eta^2 (radiance, not importance, is transported: camera paths).
//
// All functions take wo on either side: they mirror the frame so that wo.z > 0, where
// eta = n(other side) / n(wo side); ior is the inside's IOR relative to the outside (+Z side).
#ifdef __cplusplus
#pragma once
#endif
#include "bsdf/bsdf_sample.glsl"
#include "bsdf/fresnel.glsl"
#include "bsdf/ggx.glsl"

float relativeEta(float ior, bool thinWalled, float cosWo) {
    if (thinWalled) return ior;
    return cosWo > 0.0f ? ior : 1.0f / ior;
}

// Refracting a rough interface, wo.z > 0 and wi.z < 0: f * |cos(wi)| and pdf (including the 1 - F
// choice). The half vector is wo + eta wi, faced up; back-facing microfacets contribute nothing.
vec3 roughRefraction(vec3 wo, vec3 wi, float eta, float alpha, vec3 tint, OUT(float) pdf) {
    pdf = 0.0f;
    vec3 h = normalize(wo + eta * wi);
    if (h.z < 0.0f) h = -h;
    float cosOH = dot(wo, h);
    float cosIH = dot(wi, h);
    if (cosOH <= 0.0f || cosIH >= 0.0f) return vec3(0.0f);
    float transmitted = 1.0f - fresnelDielectric(cosOH, eta);
    float denom = sqr(cosIH + cosOH / eta);
    float d = ggxD(h, alpha);
    pdf = ggxVisibleNormalPdf(wo, h, alpha) * abs(cosIH) / denom * transmitted;
    float value = transmitted * d * ggxG2(wo, wi, alpha) * abs(cosIH) * cosOH / (wo.z * denom);
    return tint * (value / (eta * eta));
}

// Reflecting a rough dielectric, both directions above: f * cos(wi) and pdf (including the F choice).
float roughDielectricReflection(vec3 wo, vec3 wi, float eta, float alpha, OUT(float) pdf) {
    pdf = 0.0f;
    if (wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    float cosOH = dot(wo, h);
    if (cosOH <= 0.0f) return 0.0f;
    float reflected = fresnelDielectric(cosOH, eta);
    pdf = ggxVisibleNormalPdf(wo, h, alpha) / (4.0f * cosOH) * reflected;
    return reflected * ggxReflectionNoFresnel(wo, wi, alpha);
}

// A thin wall: transmission is the reflection lobe mirrored through the surface (no bending), so
// reflection and transmission together carry the GGX single-scattering energy.
vec3 roughThinTransmission(vec3 wo, vec3 wi, float ior, float alpha, vec3 tint, OUT(float) pdf) {
    pdf = 0.0f;
    vec3 mirrored = flipZ(wi);
    vec3 h = normalize(wo + mirrored);
    float cosOH = dot(wo, h);
    if (cosOH <= 0.0f) return vec3(0.0f);
    float transmitted = 1.0f - fresnelDielectric(cosOH, ior);
    pdf = ggxVisibleNormalPdf(wo, h, alpha) / (4.0f * cosOH) * transmitted;
    return tint * (transmitted * ggxReflectionNoFresnel(wo, mirrored, alpha));
}

// Rough (non-delta) part: f * |cos(wi)| and its sampling pdf. Zero for alpha below GGX_DELTA_ALPHA.
vec3 dielectricEval(vec3 wo, vec3 wi, float ior, bool thinWalled, float alpha, vec3 tint, OUT(float) pdf) {
    pdf = 0.0f;
    if (alpha < GGX_DELTA_ALPHA || wo.z == 0.0f || wi.z == 0.0f) return vec3(0.0f);
    float eta = relativeEta(ior, thinWalled, wo.z);
    if (wo.z < 0.0f) {
        wo = flipZ(wo);
        wi = flipZ(wi);
    }
    if (wi.z > 0.0f) return vec3(roughDielectricReflection(wo, wi, eta, alpha, pdf));
    if (thinWalled) return roughThinTransmission(wo, wi, ior, alpha, tint, pdf);
    return roughRefraction(wo, wi, eta, alpha, tint, pdf);
}

// Smooth interface, wo.z > 0: reflect with probability F, else refract (or pass straight through a
// thin wall). u: the choice.
BsdfSample sampleSmoothDielectric(vec3 wo, float eta, bool thinWalled, vec3 tint, float u) {
    float reflected = fresnelDielectric(wo.z, eta);
    if (u < reflected) return BsdfSample(mirrorAboutNormal(wo), vec3(1.0f), reflected, LOBE_SPECULAR, 1.0f);
    uint lobe = LOBE_SPECULAR | LOBE_TRANSMISSION;
    if (thinWalled) return BsdfSample(-wo, tint, 1.0f - reflected, lobe, 1.0f);
    vec3 wi = refract(-wo, vec3(0.0f, 0.0f, 1.0f), 1.0f / eta);
    return BsdfSample(normalize(wi), tint / (eta * eta), 1.0f - reflected, lobe, eta);
}

// Rough interface, wo.z > 0: a visible microfacet normal from u.yz, then reflect with probability
// F(wo.h), else refract through it (or mirror the reflection through a thin wall).
bool sampleRoughDielectric(vec3 wo, float eta, bool thinWalled, float alpha, vec3 tint, vec3 u, OUT(BsdfSample) s) {
    s = noBsdfSample();
    vec3 h = sampleGgxVisibleNormal(wo, alpha, vec2(u.y, u.z));
    float cosOH = dot(wo, h);
    if (cosOH <= 0.0f) return false;
    float reflected = fresnelDielectric(cosOH, eta);
    vec3 reflectedDir = reflect(-wo, h);
    vec3 wi;
    uint lobe = LOBE_GLOSSY;
    if (u.x < reflected) {
        wi = reflectedDir;
        if (wi.z <= 0.0f) return false;
    } else if (thinWalled) {
        if (reflectedDir.z <= 0.0f) return false;
        wi = flipZ(reflectedDir);
        lobe |= LOBE_TRANSMISSION;
    } else {
        wi = normalize(refract(-wo, h, 1.0f / eta));
        if (wi.z >= 0.0f) return false;
        lobe |= LOBE_TRANSMISSION;
    }
    float pdf;
    // wo is above, so dielectricEval reads `eta` back as the relative IOR.
    vec3 f = dielectricEval(wo, wi, eta, thinWalled, alpha, tint, pdf);
    if (pdf <= 0.0f) return false;
    float crossed = (lobe & LOBE_TRANSMISSION) != 0u && !thinWalled ? eta : 1.0f;
    s = BsdfSample(wi, f / pdf, pdf, lobe, crossed);
    return true;
}

// u.x: reflect/refract choice, u.yz: microfacet normal. Returns false when no direction results.
bool dielectricSample(vec3 wo, float ior, bool thinWalled, float alpha, vec3 tint, vec3 u, OUT(BsdfSample) s) {
    s = noBsdfSample();
    if (wo.z == 0.0f) return false;
    float eta = relativeEta(ior, thinWalled, wo.z);
    bool below = wo.z < 0.0f;
    vec3 woUp = below ? flipZ(wo) : wo;
    if (alpha < GGX_DELTA_ALPHA) {
        s = sampleSmoothDielectric(woUp, eta, thinWalled, tint, u.x);
    } else if (!sampleRoughDielectric(woUp, eta, thinWalled, alpha, tint, u, s)) {
        return false;
    }
    if (below) s.wi = flipZ(s.wi);
    return true;
}
