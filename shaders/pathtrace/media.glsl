// The medium a path travels in (docs/MEDIA.md): vacuum, an absorbing volume (KHR_materials_volume
// alone), the scene's fog, or a scattering volume (GLINT_materials_volume_scatter). Only the
// HAS_MEDIA variant (fog on, or a scattering material) samples scattering; the others keep the
// closed-form Beer-Lambert absorption along each segment and draw no random numbers for it.
#ifdef HAS_MEDIA
#include "sampling/fog_density.glsl"
#include "sampling/phase.glsl"
uniform vec4 uFog;           // density (1/m; 0: no fog), height falloff (1/m), base height (m), 0
uniform vec3 uFogAlbedo;     // single-scattering albedo
uniform float uFogAnisotropy; // Henyey-Greenstein g
#endif

const int MEDIUM_ABSORBING = 0;  // sigmaT only (0: vacuum)
const int MEDIUM_FOG = 1;        // the scene's fog: grey extinction from uFog, falling with height
const int MEDIUM_SCATTERING = 2; // homogeneous, per-channel extinction, scattering `albedo` of it

struct Medium {
    int kind;
    vec3 sigmaT;  // extinction per metre (absorbing and scattering kinds)
    vec3 albedo;  // share of the extinction scattered (fog and scattering kinds)
    float g;      // Henyey-Greenstein anisotropy
};

// Where camera rays start, and where a path returns when it leaves a closed volume.
Medium sceneMedium() {
#ifdef HAS_MEDIA
    if (uFog.x > 0.0) return Medium(MEDIUM_FOG, vec3(0.0), uFogAlbedo, uFogAnisotropy);
#endif
    return Medium(MEDIUM_ABSORBING, vec3(0.0), vec3(0.0), 0.0);
}

// Inside a closed, non-thin-walled mesh or shape of `material`: the extinction is
// KHR_materials_volume's attenuation, of which material texel 6 scatters rgb with anisotropy w.
Medium interiorMedium(int material, SurfaceMaterial m) {
    vec3 sigmaT = attenuationCoefficient(m);
#ifdef HAS_MEDIA
    vec4 scatter = materialTexel(material, 6);
    if (maxComponent(scatter.rgb) > 0.0 && maxComponent(sigmaT) > 0.0) return Medium(MEDIUM_SCATTERING, sigmaT, scatter.rgb, scatter.w);
#endif
    return Medium(MEDIUM_ABSORBING, sigmaT, vec3(0.0), 0.0);
}

// The share of light that crosses distance t of the medium along `ray` unscattered.
vec3 mediumTransmittance(Medium m, Ray ray, float t) {
#ifdef HAS_MEDIA
    if (m.kind == MEDIUM_FOG) return vec3(exp(-fogOpticalDepth(uFog, ray.origin, ray.direction, t)));
#endif
    return exp(-m.sigmaT * t);
}

#ifdef HAS_INDEX_MATCHED
// Index-matched boundaries (renderer/gpu_scene/packed_scene.h indexMatched) neither bend nor
// reflect light: paths and shadow rays alike go straight through them, dimmed only by their tint (the
// base colour, as KHR_materials_transmission tints) and the medium behind. A crossing is not a path
// vertex: it takes no bounce and leaves the MIS state of the vertex before it, so next-event
// estimation across a boundary and the path through it are weighted against each other as in the
// open. Other surfaces block shadow rays.
const int MAX_SHADOW_CROSSINGS = 8;
const int MAX_PATH_CROSSINGS = 16;

bool indexMatchedBoundary(int material) { return materialTexel(material, 5).w == MATERIAL_INDEX_MATCHED; }

// Crosses the boundary `hit` found on `ray`: the medium behind it (a thin sheet keeps the medium),
// the ray moved just past it; returns the boundary's tint.
vec3 crossBoundary(Hit hit, INOUT(Ray) ray, INOUT(Medium) medium) {
    bool entering = dot(hit.geometricNormal, ray.direction) < 0.0;
    if (materialTexel(hit.material, 3).w > 0.0) // thickness: a closed volume
        medium = entering ? interiorMedium(hit.material, fetchSurfaceMaterial(hit.material)) : sceneMedium();
    ray.origin = bvhOffsetRayOrigin(ray.origin + hit.t * ray.direction, entering ? -hit.geometricNormal : hit.geometricNormal);
    return materialTexel(hit.material, 0).rgb;
}

// What arrives along a shadow ray of length `distance` that starts in `medium`: the transmittance of
// the media it crosses, through index-matched boundaries (a closed one switches the medium, as a
// path crossing it does), 0 where anything else is in the way or after MAX_SHADOW_CROSSINGS.
vec3 shadowTransmittance(Ray ray, float distance, Medium medium) {
    vec3 through = vec3(1.0);
    vec3 end = ray.origin + distance * ray.direction;
    for (int i = 0; i < MAX_SHADOW_CROSSINGS; ++i) {
        Hit hit = traceClosest(ray);
        if (hit.material < 0 || hit.t >= distance) return through * mediumTransmittance(medium, ray, distance);
        if (!indexMatchedBoundary(hit.material)) return vec3(0.0);
        through *= mediumTransmittance(medium, ray, hit.t);
        through *= crossBoundary(hit, ray, medium);
        distance = dot(end - ray.origin, ray.direction);
        if (!(distance > 0.0)) return through;
    }
    return vec3(0.0);
}
#endif

#ifdef HAS_MEDIA
// Whether a ray scatters in the medium before `tEnd` (the next surface, or RAY_MAX), and the weight
// of that outcome (the albedo is the scattering vertex's own weight, scatterSample). Free flights are
// sampled in proportion to transmittance x extinction, in closed form.
// - The fog's extinction is grey: the sampling is exact and the weight 1.
// - A volume's extinction differs per channel: the path samples every such distance with one
//   channel's extinction, its hero, chosen uniformly at its first volume event, and is weighted by
//   the balance heuristic over the three channels as whole-path strategies (pbrt-v4's spectral MIS):
//   weight = f / mean over channels of the path's pdf. `spectral` carries the path's per-channel pdfs
//   (up to a common factor) from event to event, so a channel that barely scatters never divides by
//   a small probability, however many events the path has.
struct MediumEvent {
    bool scattered;
    float t;
    vec3 weight;
};

struct SpectralPath {
    float hero;    // the channel distances are sampled with; -1 until the first volume event
    vec3 pdfs;     // the path's pdf under each channel's sampling, scaled to a maximum of 1
};

SpectralPath startSpectralPath() { return SpectralPath(-1.0, vec3(1.0)); }

MediumEvent sampleMediumEvent(Medium m, Ray ray, float tEnd, INOUT(Rng) rng, INOUT(SpectralPath) path) {
    if (m.kind == MEDIUM_ABSORBING) return MediumEvent(false, tEnd, exp(-m.sigmaT * tEnd));
    float u = rand1(rng);
    if (m.kind == MEDIUM_FOG) {
        float t = fogDistanceAtDepth(uFog, ray.origin, ray.direction, -log(1.0 - u), RAY_MAX);
        return MediumEvent(t < tEnd, t, vec3(1.0));
    }
    if (path.hero < 0.0) { // the first volume event draws the hero from the same number
        path.hero = min(floor(3.0 * u), 2.0);
        u = 3.0 * u - path.hero;
    }
    float sigma = path.hero == 0.0 ? m.sigmaT.r : (path.hero == 1.0 ? m.sigmaT.g : m.sigmaT.b);
    float t = sigma > 0.0 ? -log(1.0 - u) / sigma : RAY_MAX;
    bool scattered = t < tEnd;
    // Per channel, this outcome's pdf under that channel's sampling, which is also its transport
    // (extinction x transmittance for a scatter, transmittance for a pass).
    vec3 pdf = scattered ? m.sigmaT * exp(-m.sigmaT * t) : exp(-m.sigmaT * tEnd);
    float before = dot(path.pdfs, vec3(1.0 / 3.0));
    path.pdfs *= pdf;
    float after = dot(path.pdfs, vec3(1.0 / 3.0));
    vec3 weight = after > 0.0 ? pdf * (before / after) : vec3(0.0);
    if (after > 0.0) path.pdfs /= maxComponent(path.pdfs);
    return MediumEvent(scattered, scattered ? t : tEnd, weight);
}

// Equiangular sampling (Kulla and Fajardo 2012) of a distance along a ray in [0, tEnd]: density in
// proportion to 1 / (squared distance to a light at `center`), so that points near a light, whose
// direct light is large, are drawn as often as they matter. In angle about the centre's foot on the
// ray the density is uniform between thetaA and thetaB.
struct Equiangular {
    float along;  // the foot of the centre on the ray
    float offset; // the centre's distance from the ray
    float thetaA;
    float thetaB;
};

Equiangular equiangularAround(Ray ray, float tEnd, vec3 center) {
    float along = dot(center - ray.origin, ray.direction);
    float offset = max(length(center - ray.origin - along * ray.direction), 1e-4);
    return Equiangular(along, offset, atan(-along / offset), atan((min(tEnd, 1e30) - along) / offset));
}

float equiangularDistance(Equiangular e, float u) {
    return e.along + e.offset * tan(mix(e.thetaA, e.thetaB, u));
}

float equiangularPdf(Equiangular e, float t) {
    float r = t - e.along;
    return e.offset / ((e.thetaB - e.thetaA) * (e.offset * e.offset + r * r));
}

// Where in the segment to scatter, given that the fog's free flight scattered there (at
// `freeFlight`, probability 1 - T(tEnd)): one-sample MIS between that distance and an equiangular
// one around `center`, each chosen with probability 1/2 (`u`: the choice, then the equiangular
// draw). `weight`: extinction x transmittance at the distance / (1 - T(tEnd)) / the mixed pdf, at
// most 2; the analog free flight alone would have weight 1 but rarely lands next to a light.
float fogScatterDistance(Ray ray, float tEnd, float freeFlight, vec3 center, float u, OUT(float) weight) {
    weight = 1.0;
    Equiangular e = equiangularAround(ray, tEnd, center);
    if (!(e.thetaB > e.thetaA)) return freeFlight;
    float t = u < 0.5 ? clamp(equiangularDistance(e, 2.0 * u), 0.0, tEnd) : freeFlight;
    float depthToEnd = fogOpticalDepth(uFog, ray.origin, ray.direction, tEnd);
    float scatters = depthToEnd < 1e-4 ? depthToEnd * (1.0 - 0.5 * depthToEnd) : 1.0 - exp(-depthToEnd);
    float density = fogDensityAt(uFog, ray.origin.y + t * ray.direction.y) * exp(-fogOpticalDepth(uFog, ray.origin, ray.direction, t));
    float distancePdf = scatters > 0.0 ? density / scatters : 0.0;
    float mixed = 0.5 * distancePdf + 0.5 * equiangularPdf(e, t);
    weight = mixed > 0.0 ? distancePdf / mixed : 0.0;
    return t;
}
#endif
