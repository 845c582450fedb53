// The glTF surface BSDF in the local shading frame (normal = +Z), as one mixture of lobes:
//   metallic                         GGX conductor, Schlick Fresnel tinted by baseColor
//   (1 - metallic) transmission      dielectric interface (dielectric.glsl), transmission tinted
//   (1 - metallic)(1 - transmission) KHR_materials_specular layer (GGX, F = specularFactor *
//                                    Schlick(F0)) over Lambert, which is scaled by
//                                    (1 - R(wo)) (1 - R(wi)) / (1 - average R), R the layer's albedo
// Roughness below sqrt(GGX_DELTA_ALPHA) makes the specular lobes deltas. Opaque lobes are two-sided
// (mirrored when wo.z < 0); the dielectric uses the side to pick eta. The reflective GGX lobes are
// compensated for multiple scattering (ggx_energy.glsl); the dielectric's are not: see
// docs/MATERIALS.md for the energy each keeps.
#ifdef __cplusplus
#pragma once
#endif
#include "bsdf/bsdf_sample.glsl"
#include "bsdf/dielectric.glsl"
#include "bsdf/ggx_energy.glsl"
#include "bsdf/lambert.glsl"

// The glass lobe is compiled in only where a material of the scene transmits (HAS_TRANSMISSION):
// llvmpipe runs both sides of every branch, so an opaque scene would pay for it at every vertex.
// The CPU twin always has it.
#if defined(__cplusplus) || defined(HAS_TRANSMISSION)
#define BSDF_TRANSMISSION 1
#else
#define BSDF_TRANSMISSION 0
#endif

// Mixture weights and the probabilities of sampling each lobe, from the material and wo.
struct BsdfLobes {
    float metal;        // weights of the three parts
    float glass;
    float layered;
    float alpha;
    vec3 layerF0;       // KHR_materials_specular F0 of the dielectric layer
    vec3 metalEnergyScale; // multiple-scattering compensation of the two GGX lobes at wo
    vec3 layerEnergyScale;
    float pMetal;       // lobe choice probabilities, summing to 1 (or all 0: a black surface)
    float pGlass;
    float pLayerSpecular;
    float pDiffuse;
};

BsdfLobes bsdfLobes(SurfaceMaterial m, float cosWo) {
    float metal = clamp(m.metallic, 0.0f, 1.0f);
#if BSDF_TRANSMISSION
    float glass = (1.0f - metal) * clamp(m.transmission, 0.0f, 1.0f);
#else
    float glass = 0.0f;
#endif
    float layered = (1.0f - metal) - glass;
    vec3 f0 = dielectricF0(m.ior, m.specularColor);
    float layerF = m.specularFactor * maxComponent(fresnelSchlick(f0, abs(cosWo)));
    float pMetal = metal;
    float pGlass = glass;
    float pLayerSpecular = layered * layerF;
    float pDiffuse = layered * (1.0f - layerF) * maxComponent(m.baseColor);
    float total = pMetal + pGlass + pLayerSpecular + pDiffuse;
    float scale = total > 0.0f ? 1.0f / total : 0.0f;
    float mu = abs(cosWo);
    vec3 metalEnergyScale = ggxMultipleScatteringScale(m.baseColor, mu, m.roughness);
    vec3 layerEnergyScale = ggxMultipleScatteringScale(m.specularFactor * f0, mu, m.roughness);
    return BsdfLobes(metal, glass, layered, ggxAlphaFromRoughness(m.roughness), f0, metalEnergyScale,
                     layerEnergyScale, pMetal * scale, pGlass * scale, pLayerSpecular * scale, pDiffuse * scale);
}

// What the KHR_materials_specular layer reflects of light arriving at cos(theta) to the normal: the
// smooth Fresnel for a mirror, the (compensated) GGX albedo for a rough layer.
float layerReflectance(SurfaceMaterial m, BsdfLobes l, float cosTheta) {
    if (l.alpha < GGX_DELTA_ALPHA) return m.specularFactor * maxComponent(fresnelSchlick(l.layerF0, cosTheta));
    vec3 f0 = m.specularFactor * l.layerF0;
    vec3 scale = ggxMultipleScatteringScale(f0, cosTheta, m.roughness);
    return m.specularFactor * maxComponent(ggxSchlickAlbedo(l.layerF0, cosTheta, m.roughness) * scale);
}

// The cosine-weighted average of layerReflectance over all directions (Schlick's integrates to
// F0 + (1 - F0) / 21).
float layerAverageReflectance(SurfaceMaterial m, BsdfLobes l) {
    if (l.alpha < GGX_DELTA_ALPHA) return m.specularFactor * maxComponent(l.layerF0 + (vec3(1.0f) - l.layerF0) / 21.0f);
    vec3 average = ggxAverageSchlickAlbedo(l.layerF0, m.roughness);
    vec3 f0 = m.specularFactor * l.layerF0;
    float e = max(ggxAverageSchlickAlbedo(vec3(1.0f), m.roughness).x, 0.05f);
    return m.specularFactor * maxComponent(average * (vec3(1.0f) + f0 * ((1.0f - e) / e)));
}

// Opaque (metal + layered) part for wo.z > 0: f * cos(wi) and the lobe-weighted pdf.
vec3 opaqueEval(SurfaceMaterial m, BsdfLobes l, vec3 wo, vec3 wi, OUT(float) pdf) {
    pdf = 0.0f;
    if (wi.z <= 0.0f) return vec3(0.0f);
    // The diffuse under the specular layer keeps what the layer does not reflect on the way in and
    // on the way out, normalised so that a white diffuse returns exactly what the layer leaves
    // (reciprocal; the glTF spec's 1 - F(wo.h) gains up to 6 % at grazing angles, and the smooth
    // 1 - F(wo) loses up to half the light of a rough layer there; see docs/MATERIALS.md).
    float diffuseScale = (1.0f - layerReflectance(m, l, wo.z)) * (1.0f - layerReflectance(m, l, wi.z)) /
                         max(1.0f - layerAverageReflectance(m, l), 1e-6f);
    vec3 f = l.layered * diffuseScale * m.baseColor * lambertReflection(wo, wi);
    pdf = l.pDiffuse * lambertPdf(wo, wi);
    if (l.alpha >= GGX_DELTA_ALPHA) {
        float cosOH = max(dot(wo, normalize(wo + wi)), 0.0f);
        float microfacet = ggxReflectionNoFresnel(wo, wi, l.alpha);
        vec3 layerF = m.specularFactor * fresnelSchlick(l.layerF0, cosOH);
        vec3 specular = l.metal * l.metalEnergyScale * fresnelSchlick(m.baseColor, cosOH) +
                        l.layered * l.layerEnergyScale * layerF;
        f += specular * microfacet;
        pdf += (l.pMetal + l.pLayerSpecular) * ggxReflectionPdf(wo, wi, l.alpha);
    }
    return f;
}

// The non-delta part of the BSDF: f * |cos(wi)|, and in `pdf` the density with which bsdfSample
// returns wi (delta lobes excluded).
vec3 bsdfEval(SurfaceMaterial m, vec3 wo, vec3 wi, OUT(float) pdf) {
    pdf = 0.0f;
    if (wo.z == 0.0f) return vec3(0.0f);
    BsdfLobes l = bsdfLobes(m, wo.z);
    float glassPdf = 0.0f;
    vec3 f = vec3(0.0f);
#if BSDF_TRANSMISSION
    if (l.pGlass > 0.0f) {
        f = l.glass * dielectricEval(wo, wi, m.ior, m.thinWalled, l.alpha, m.baseColor, glassPdf);
    }
#endif
    float opaquePdf = 0.0f;
    vec3 woUp = wo.z > 0.0f ? wo : flipZ(wo);
    vec3 wiUp = wo.z > 0.0f ? wi : flipZ(wi);
    f += opaqueEval(m, l, woUp, wiUp, opaquePdf);
    pdf = l.pGlass * glassPdf + opaquePdf;
    return f;
}

float bsdfPdf(SurfaceMaterial m, vec3 wo, vec3 wi) {
    float pdf;
    bsdfEval(m, wo, wi, pdf);
    return pdf;
}

// A delta lobe of the opaque part (roughness ~ 0): the mirror direction, weighted by its Fresnel.
BsdfSample sampleOpaqueMirror(SurfaceMaterial m, BsdfLobes l, vec3 wo, bool metalLobe) {
    vec3 f = metalLobe ? l.metal * fresnelSchlick(m.baseColor, wo.z)
                       : l.layered * m.specularFactor * fresnelSchlick(l.layerF0, wo.z);
    float p = metalLobe ? l.pMetal : l.pLayerSpecular;
    return BsdfSample(mirrorAboutNormal(wo), f / p, p, LOBE_SPECULAR, 1.0f);
}

// u.x picks the lobe (and is reused, rescaled, by the dielectric's reflect/refract choice); u.yz the
// direction. weight = f * |cos| / pdf of the whole non-delta mixture, so it agrees with bsdfEval.
bool bsdfSample(SurfaceMaterial m, vec3 wo, vec3 u, OUT(BsdfSample) s) {
    s = noBsdfSample();
    if (wo.z == 0.0f) return false;
    BsdfLobes l = bsdfLobes(m, wo.z);
    bool rough = l.alpha >= GGX_DELTA_ALPHA;
    float choice = u.x;
#if BSDF_TRANSMISSION
    if (choice < l.pGlass) {
        vec3 uGlass = vec3(choice / l.pGlass, u.y, u.z);
        if (!dielectricSample(wo, m.ior, m.thinWalled, l.alpha, m.baseColor, uGlass, s)) return false;
        if (!rough) {
            s.weight *= l.glass / l.pGlass;
            s.pdf *= l.pGlass;
            return true;
        }
    } else
#endif
    {
        bool below = wo.z < 0.0f;
        vec3 woUp = below ? flipZ(wo) : wo;
        choice -= l.pGlass;
        bool metalLobe = choice < l.pMetal;
        bool specularLobe = metalLobe || choice < l.pMetal + l.pLayerSpecular;
        if (specularLobe && !rough) {
            s = sampleOpaqueMirror(m, l, woUp, metalLobe);
        } else if (specularLobe) {
            s.wi = reflect(-woUp, sampleGgxVisibleNormal(woUp, l.alpha, vec2(u.y, u.z)));
            s.lobe = LOBE_GLOSSY;
        } else if (l.pDiffuse > 0.0f) {
            s.wi = sampleLambert(vec2(u.y, u.z));
            s.lobe = LOBE_DIFFUSE;
        } else {
            return false;
        }
        if (below) s.wi = flipZ(s.wi);
        if (specularLobe && !rough) return true;
    }
    float pdf;
    vec3 f = bsdfEval(m, wo, s.wi, pdf);
    if (pdf <= 0.0f) return false;
    s.weight = f / pdf;
    s.pdf = pdf;
    return true;
}

// Directional albedo estimates at wo for demodulation (diffuse and specular apart): single-bounce
// Fresnel at wo, no shadowing; transmission counts as specular.
struct BsdfAlbedo {
    vec3 diffuse;
    vec3 specular;
};

BsdfAlbedo bsdfAlbedo(SurfaceMaterial m, vec3 wo) {
    BsdfLobes l = bsdfLobes(m, wo.z);
    float cosWo = abs(wo.z);
    vec3 layerF = m.specularFactor * fresnelSchlick(l.layerF0, cosWo);
    float glassF = fresnelDielectric(cosWo, relativeEta(m.ior, m.thinWalled, wo.z));
    vec3 diffuse = l.layered * (1.0f - layerReflectance(m, l, cosWo)) * m.baseColor;
    vec3 specular = l.metal * fresnelSchlick(m.baseColor, cosWo) + l.layered * layerF +
                    l.glass * (glassF + (1.0f - glassF) * m.baseColor);
    return BsdfAlbedo(diffuse, specular);
}
