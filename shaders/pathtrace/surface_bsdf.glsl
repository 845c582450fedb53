// The glTF metallic-roughness BSDF in a local frame whose +Z faces wo: Lambert diffuse plus GGX
// specular mixed by metallic and KHR_materials_specular, and a smooth dielectric for
// KHR_materials_transmission (thin-walled or refracting). Roughness below DELTA_ROUGHNESS is a
// perfect mirror. Rough transmission is rendered smooth (a documented simplification).
const float DELTA_ALPHA = 1e-3;

struct BsdfSample {
    vec3 wi;
    vec3 weight;  // f * |cos| / pdf
    float pdf;    // 0 for delta lobes
    bool isDelta;
};


float ggxAlpha(Surface s) { return s.roughness * s.roughness; }
float glassProbability(Surface s) { return (1.0 - s.metallic) * s.transmission; }

vec3 dielectricF0(Surface s) {
    float r = (s.ior - 1.0) / (s.ior + 1.0);
    return min(r * r * s.specularColor, vec3(1.0));
}

// Probability of sampling the specular lobe among the opaque lobes, from the Fresnel at wo.
float specularProbability(Surface s, vec3 wo) {
    if (s.metallic >= 1.0) return 1.0;
    if (s.specular <= 0.0) return s.metallic;
    float dielectric = clamp(2.0 * s.specular * maxComponent(fresnelSchlick(dielectricF0(s), wo.z)), 0.1, 0.9);
    return mix(dielectric, 1.0, s.metallic);
}

// The specular colour at a microfacet (dielectric part scaled by KHR specular, metal part by base colour).
vec3 specularFresnel(Surface s, float cosH, out float diffuseScale) {
    vec3 dielectric = s.specular * fresnelSchlick(dielectricF0(s), cosH);
    diffuseScale = 1.0 - maxComponent(dielectric);
    return mix(dielectric, fresnelSchlick(s.baseColor, cosH), s.metallic);
}

// Non-delta part of the BSDF times cos(wi); pdf of sampleBsdf producing wi.
vec3 evalBsdf(Surface s, vec3 wo, vec3 wi, out float pdf) {
    pdf = 0.0;
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    float opaque = 1.0 - glassProbability(s);
    float alpha = ggxAlpha(s);
    float pSpecular = specularProbability(s, wo);
    vec3 h = normalize(wo + wi);
    float diffuseScale;
    vec3 fresnel = specularFresnel(s, dot(wo, h), diffuseScale);
    vec3 f = (1.0 - s.metallic) * diffuseScale * s.baseColor * INV_PI;
    pdf = (1.0 - pSpecular) * wi.z * INV_PI;
    if (alpha >= DELTA_ALPHA) {
        f += fresnel * ggxD(h, alpha) * smithG2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
        pdf += pSpecular * ggxReflectionPdf(wo, h, alpha);
    }
    pdf *= opaque;
    return opaque * f * wi.z;
}

vec3 cosineHemisphere(vec2 u) {
    float r = sqrt(u.x);
    float phi = TWO_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}

BsdfSample sampleGlass(Surface s, vec3 wo, bool entering, float u) {
    float eta = s.thinWalled ? s.ior : (entering ? s.ior : 1.0 / s.ior);
    float reflectance = fresnelDielectric(wo.z, eta);
    if (u < reflectance) return BsdfSample(vec3(-wo.xy, wo.z), s.specularColor, 0.0, true);
    if (s.thinWalled) return BsdfSample(-wo, s.baseColor, 0.0, true);
    vec3 wi = refract(-wo, vec3(0.0, 0.0, 1.0), 1.0 / eta);
    return BsdfSample(normalize(wi), s.baseColor, 0.0, true);
}

// `u` holds three uniforms: lobe choice, then two for the direction. `entering`: wo is outside the surface.
BsdfSample sampleBsdf(Surface s, vec3 wo, bool entering, vec3 u) {
    BsdfSample none = BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
    if (wo.z <= 0.0) return none;
    float pGlass = glassProbability(s);
    if (u.x < pGlass) return sampleGlass(s, wo, entering, u.y);
    float pSpecular = specularProbability(s, wo);
    float uLobe = (u.x - pGlass) / (1.0 - pGlass);
    float alpha = ggxAlpha(s);
    if (uLobe < pSpecular && alpha < DELTA_ALPHA) {
        float diffuseScale;
        vec3 fresnel = specularFresnel(s, wo.z, diffuseScale);
        return BsdfSample(vec3(-wo.xy, wo.z), fresnel / pSpecular, 0.0, true);
    }
    vec3 wi = uLobe < pSpecular ? reflect(-wo, sampleGgxVisibleNormal(wo, alpha, u.yz)) : cosineHemisphere(u.yz);
    float pdf;
    vec3 f = evalBsdf(s, wo, wi, pdf);
    if (pdf <= 0.0) return none;
    return BsdfSample(wi, f / pdf, pdf, false);
}
