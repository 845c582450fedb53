// The path integrator: next-event estimation at every vertex (punctual lights; one area emitter (an
// emissive triangle, emissive shape or area light) and the environment map with multiple importance
// sampling), BSDF sampling to continue, Russian roulette, and a bounce
// limit as docs/CLI.md defines it: bounces = 0 renders emitters and direct light only; each
// further bounce adds one indirect vertex. Shading frames use the surface's outward normal: the
// shared BSDF reads the side of wo (wo.z < 0: inside).
uniform int uMaxBounces;
uniform float uClamp; // 0: off (unbiased)
// Light sampling reaches every emitter a ray can meet: no environment light, no portal, no emitter
// left to BSDF sampling (lightSamplingReachesEveryEmitter), and the strategies include it.
uniform bool uEveryEmitterLightSampled;

// Which strategies find the light of area emitters (renderer/gpu_scene SceneFeatures): 0 both, with
// MIS; 1 light sampling alone; 2 BSDF sampling alone (the tests' debug variants).
#ifndef AREA_LIGHT_STRATEGY
#define AREA_LIGHT_STRATEGY 0
#endif

const int ROULETTE_START = 3;
const int HARD_PATH_LIMIT = 64; // a guard, not a setting: uMaxBounces is clamped below it

struct PathResult {
    vec3 radiance;
    vec3 albedo;    // first hit's base colour (or the environment's radiance)
    vec3 normal;    // first hit's shading normal facing the camera, world space
    float depth;    // along the camera's view axis; -1: nothing hit
    float objectId; // node id of the first hit; 0: nothing
    vec4 lobes;     // first hit's metallic, roughness, transmission, specular factor (misses: 0, 1, 0, 0)
};

struct Vertex {
    vec3 position;
    vec3 faceNormal; // geometric, outward
    Frame frame;     // around the outward shading normal
    vec3 wo;         // towards where the ray came from, local
    SurfaceMaterial material;
    RayCone cone;    // the arriving ray's cone, its width taken at this vertex
    bool inMedium;   // a scattering point in a medium (mediumVertex): the phase function replaces the BSDF
    vec3 albedo;     // ... the medium's single-scattering albedo there
    float g;         // ... and its Henyey-Greenstein anisotropy
};

// Whether the path ends at this vertex with its light samples weighted 1. At the bounce limit the
// BSDF-sampled ray would serve only to find emitters, for MIS; where light sampling reaches them all
// and the vertex has no narrow lobe (which light samples would seldom meet), light samples alone
// have the same expectation and about the same variance, without that ray's walk (5 to 10 % of a
// sample's time at 4 bounces on llvmpipe: docs/PERFORMANCE.md, "The last bounce's BSDF ray").
bool endsAtLightSamples(Vertex v, int depth, int maxBounces) {
    return depth == maxBounces && uEveryEmitterLightSampled && !v.inMedium &&
           v.material.roughness >= 0.5 && v.material.transmission <= 0.0;
}

// A scattering point at distance t along `ray` in medium m. Its frame's normal is the direction
// of travel and wo is -Z, so a direction's local z is the cosine of its scattering angle; it has no
// surface, so shadow rays and the next ray start at the point itself (spawnRay with a zero normal).
Vertex mediumVertex(Ray ray, float t, Medium m, RayCone cone) {
    Vertex v;
    v.position = ray.origin + t * ray.direction;
    v.faceNormal = vec3(0.0);
    v.frame = frameFromNormal(ray.direction);
    v.wo = vec3(0.0, 0.0, -1.0);
    v.material = defaultSurfaceMaterial();
    v.cone = RayCone(coneWidthAt(cone, t), cone.spread);
    v.inMedium = true;
    v.albedo = m.albedo;
    v.g = m.g;
    return v;
}

// What scatters light from world `direction` towards wo: the BSDF (f cos) at a surface, albedo x
// phase in a medium; `pdf`: the density the vertex samples that direction with.
vec3 scatterEval(Vertex v, vec3 direction, OUT(float) pdf) {
#ifdef HAS_MEDIA
    if (v.inMedium) {
        pdf = henyeyGreenstein(localFromWorld(v.frame, direction).z, v.g);
        return v.albedo * pdf;
    }
#endif
    return bsdfEval(v.material, v.wo, localFromWorld(v.frame, direction), pdf);
}

// The next direction from a vertex (local frame): BSDF sampling at a surface; in a medium, the
// phase function sampled exactly, weight = albedo (a diffuse-like lobe: MIS and denoising treat it so).
bool scatterSample(Vertex v, vec3 u, OUT(BsdfSample) bs) {
#ifdef HAS_MEDIA
    if (v.inMedium) {
        float cosTheta = sampleHenyeyGreensteinCos(v.g, u.x);
        float sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
        float phi = TWO_PI * u.y;
        bs = BsdfSample(vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta), v.albedo,
                        henyeyGreenstein(cosTheta, v.g), LOBE_DIFFUSE, 1.0);
        return true;
    }
#endif
    return bsdfSample(v.material, v.wo, u, bs);
}

// Random bits for the triangle filter's stochastic transparency, from dimensions no sampling
// routine draws (so alpha-free scenes keep their random streams).
uvec4 alphaKey(Rng rng, uint salt) { return rngBits(rng.key, 0x80000000u + salt * 0x10000u + rng.dimension); }

#ifdef AMBIENT_TERM
#include "ambient_term.glsl"
#endif

// A light sample waiting for its shadow ray: unoccluded, it adds `contribution`.
struct ShadowCandidate {
    vec3 direction;
    float distance;
    vec3 contribution; // f * Le * MIS weight / pdf
    vec4 target;       // w = 1: the shadow ray goes to the point xyz; w = 0: along `direction`, `distance` far
};

ShadowCandidate noCandidate() { return ShadowCandidate(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), vec4(0.0)); }

// The shadow ray of a candidate. A ray to a point on an emitter starts where spawnRay puts it (a
// few ULPs off the surface, 1.5e-5 m near the origin) and ends at the candidate's target, itself
// moved off the emitter towards the shading point: both ends clear their surfaces at any distance.
// (Shortening the ray by a fraction of the distance instead, with the direction kept from the
// shading point, let the moved origin's ray reach the emitter's surface first wherever the emitter
// was nearer than about 7e4 offsets: near-field light was lost.) False: nothing to trace.
bool shadowRay(Vertex v, ShadowCandidate c, OUT(Ray) ray, OUT(float) distance) {
    ray = spawnRay(v.position, v.faceNormal, c.direction);
    distance = c.distance;
    if (c.target.w == 0.0) return true;
    vec3 toTarget = c.target.xyz - ray.origin;
    distance = length(toTarget);
    if (!(distance > 0.0) || dot(toTarget, c.direction) <= 0.0) return false; // the offsets crossed
    ray.direction = toTarget / distance;
    return true;
}

// `alone`: no BSDF-sampled ray follows (endsAtLightSamples), so light samples take weight 1.
ShadowCandidate punctualCandidate(Vertex v, int light, bool alone, INOUT(Rng) rng) {
    LightSample ls = sampleLight(light, v.position, rand2(rng));
    float pdf;
    vec3 f = scatterEval(v, ls.direction, pdf);
    float misWeight = ls.pdf > 0.0 && !alone ? powerHeuristic(ls.pdf, pdf) : 1.0; // sun disks: BSDF rays see them too
    return ShadowCandidate(ls.direction, ls.distance, f * ls.irradiance * misWeight, ls.target);
}

// One area emitter (an emissive triangle, or an emissive shape or area light where the scene has
// them) chosen in proportion to its power, weighted against BSDF sampling by the power heuristic.
// The shadow ray ends just off the emitter (shadowRay), so that it does not find the emitter itself.
bool sampleAreaEmitter(vec3 p, vec3 u, OUT(AreaLightSample) ls) {
#ifdef HAS_EMISSIVE_SHAPES
    float triangles = emissiveTrianglePower();
    float total = triangles + uShapeEmitterPower;
    float x = u.x * total;
    return x < triangles ? sampleEmissiveTriangle(p, vec3(x / triangles, u.y, u.z), ls)
                         : sampleShapeLight(p, x - triangles, vec2(u.y, u.z), total, ls);
#else
    return sampleEmissiveTriangle(p, u, ls);
#endif
}

ShadowCandidate areaCandidate(Vertex v, bool alone, INOUT(Rng) rng) {
    vec3 u = rand3(rng);
#if AREA_LIGHT_STRATEGY == 2
    return noCandidate();
#endif
    AreaLightSample ls;
    if (!sampleAreaEmitter(v.position, u, ls)) return noCandidate();
    float bsdfPdf;
    vec3 f = scatterEval(v, ls.direction, bsdfPdf);
#if AREA_LIGHT_STRATEGY == 1
    float weight = 1.0;
#else
    float weight = alone ? 1.0 : powerHeuristic(ls.pdf, bsdfPdf);
#endif
    return ShadowCandidate(ls.direction, ls.distance, f * ls.radiance * (weight / ls.pdf), vec4(ls.target, 1.0));
}

// One environment sample, weighted against BSDF sampling by the power heuristic.
ShadowCandidate environmentCandidate(Vertex v, INOUT(Rng) rng) {
    vec2 u = rand2(rng);
    if (!environmentIsSampled()) return noCandidate();
    float lightPdf;
    vec3 direction = sampleEnvironment(u, lightPdf);
    if (lightPdf <= 0.0) return noCandidate();
    float bsdfPdf;
    vec3 f = scatterEval(v, direction, bsdfPdf);
    return ShadowCandidate(direction, RAY_MAX, f * environmentRadiance(direction) * (powerHeuristic(lightPdf, bsdfPdf) / lightPdf), vec4(0.0));
}

// Candidate k of next-event estimation: punctual lights 0 .. uLightCount - 1, then the area emitter,
// then the environment. Each kind is compiled in only where the scene has it (llvmpipe runs every
// branch and every loop pass, so a kind with nothing to sample would cost a full pass).
ShadowCandidate lightCandidate(Vertex v, int k, bool alone, INOUT(Rng) rng) {
#ifdef HAS_PUNCTUAL_LIGHTS
    if (k < uLightCount) return punctualCandidate(v, k, alone, rng);
#endif
#ifdef HAS_AREA_EMITTERS
    if (k == uLightCount) return areaCandidate(v, alone, rng);
#endif
    return environmentCandidate(v, rng);
}

// Next-event estimation: every punctual light, one emissive triangle and one environment sample.
// All shadow rays go through one call site: GLSL inlines every call, and each traversal copy costs
// compile time (seconds on llvmpipe for the BVH variant).
// `diffuse`: the part of the sum the diffuse lobe carried, where `split` (the first hit) asks for it.
// `alone`: no BSDF-sampled ray follows (endsAtLightSamples), so every sample takes weight 1.
// Shadow rays cross the medium on their side of the surface: `arrived` on the side of wo (and
// everywhere around a medium vertex), `across` on the other; in the HAS_INDEX_MATCHED variant they
// also cross index-matched boundaries and the media behind them (media.glsl).
vec3 directLight(Vertex v, Medium arrived, Medium across, bool split, bool alone, INOUT(Rng) rng, OUT(vec3) diffuse) {
    vec3 sum = vec3(0.0);
    diffuse = vec3(0.0);
    // Only the kinds the scene has take a pass of the loop: llvmpipe runs every branch of a pass, so
    // an empty one costs as much as a full one. Candidate k draws dimension first + k whichever kinds
    // the variant has, so every variant of a scene draws the same numbers.
#ifdef HAS_AREA_EMITTERS
    const int areaCandidates = 1;
#else
    const int areaCandidates = 0;
#endif
#ifdef HAS_ENV_MAP
    const int environmentCandidates = 1;
#else
    const int environmentCandidates = 0;
#endif
    uint first = rng.dimension;
    for (int i = 0; i < uLightCount + areaCandidates + environmentCandidates; ++i) {
        int k = i < uLightCount ? i : i + 1 - areaCandidates;
        rng.dimension = first + uint(k);
        ShadowCandidate c = lightCandidate(v, k, alone, rng);
        if (!(maxComponent(c.contribution) > 0.0)) continue;
        setTraceState(false, alphaKey(rng, 1u), v.cone);
        Ray ray;
        float distance;
        if (!shadowRay(v, c, ray, distance)) continue;
        bool sameSide = v.inMedium || (localFromWorld(v.frame, c.direction).z > 0.0) == (v.wo.z > 0.0);
#ifdef HAS_INDEX_MATCHED
        vec3 transmittance = shadowTransmittance(ray, distance, sameSide ? arrived : across);
        if (!(maxComponent(transmittance) > 0.0)) continue;
#else
        if (occluded(ray, distance)) continue;
        vec3 transmittance = mediumTransmittance(sameSide ? arrived : across, ray, distance);
#endif
        vec3 contribution = c.contribution * transmittance;
        sum += contribution;
        if (split) diffuse += v.inMedium ? contribution : diffusePart(v.material, v.wo, localFromWorld(v.frame, c.direction), contribution);
    }
    rng.dimension = first + uint(uLightCount) + 2u; // later draws keep their dimensions
    return sum;
}

// Weight of emission found by BSDF sampling along `ray`, which left the vertex `from` (light
// sampling there would have used that point, not the ray's offset origin): emissive triangles,
// emissive shapes and area lights are light-sampled too (bsdfPdf 0, camera rays and delta lobes:
// weight 1).
float emissionMisWeight(Hit hit, vec3 emission, Ray ray, vec3 from, float bsdfPdf) {
    if (bsdfPdf <= 0.0) return 1.0;
    float lightPdf = 0.0;
    if (hit.onMesh) {
        if (!hasEmissiveTriangles()) return 1.0;
        lightPdf = emissiveLightPdf(emission, hit.t, abs(dot(hit.geometricNormal, ray.direction)));
    }
#ifdef HAS_EMISSIVE_SHAPES
    else if (hit.triangle.y >= 0) {
        lightPdf = shapeLightPdf(hit.triangle.y, from, ray.origin + hit.t * ray.direction, hit.geometricNormal,
                                 areaEmitterPower());
    }
#endif
#if AREA_LIGHT_STRATEGY == 1
    return lightPdf > 0.0 ? 0.0 : 1.0;
#elif AREA_LIGHT_STRATEGY == 2
    return 1.0;
#else
    return powerHeuristic(bsdfPdf, lightPdf);
#endif
}

// Weight of an environment contribution found by BSDF sampling (pdf 0: a delta lobe, weight 1).
float environmentMisWeight(vec3 direction, float bsdfPdf) {
    if (!environmentIsSampled() || bsdfPdf <= 0.0) return 1.0;
    return powerHeuristic(bsdfPdf, environmentPdf(direction));
}

#ifdef HAS_MEDIA
// A light for fog scattering to concentrate around (fogScatterDistance): a point or spot light, or a
// point on an area emitter, chosen uniformly among them; false for a sun, or where the area sample
// fails (the free flight alone then decides: each choice is unbiased on its own).
bool fogLightCenter(vec3 from, INOUT(Rng) rng, OUT(vec3) center) {
    float pick = rand1(rng) * float(uLightCount + (areaEmitterPower() > 0.0 ? 1 : 0));
    vec3 u = rand3(rng);
    int light = int(pick);
    center = vec3(0.0);
    if (light < uLightCount) {
        center = lightTexel(light, 2).xyz;
        return int(lightTexel(light, 0).x) != LIGHT_SUN;
    }
    AreaLightSample ls;
    if (!sampleAreaEmitter(from, u, ls)) return false;
    center = ls.target;
    return true;
}
#endif

// `lobes`: the radiance split by the first hit's lobe that carried it (lobe_radiance.glsl).
// Each vertex is a surface hit or, in the HAS_MEDIA variant, a point where the ray scattered in a
// medium before reaching the surface (media.glsl); both go through the one next-event estimation
// and the one scatter-sampling call below.
PathResult tracePath(Ray ray, vec3 viewAxis, INOUT(Rng) rng, OUT(LobeRadiance) lobes) {
    PathResult result = PathResult(vec3(0.0), vec3(0.0), vec3(0.0), -1.0, 0.0, vec4(0.0, 1.0, 0.0, 0.0));
    lobes = noLobeRadiance();
    bool specularPath = false; // the first bounce left by a specular lobe (reflection or transmission)
    bool reflectedPath = false; // ... and stayed on the side it came from
    vec3 throughput = vec3(1.0);
    Medium medium = sceneMedium(); // the medium the ray travels in
#ifdef HAS_MEDIA
    SpectralPath spectral = startSpectralPath();
#endif
    float lastBsdfPdf = 0.0;       // of the sampled direction; 0 for camera rays and delta lobes
    vec3 lastPosition = ray.origin; // the vertex the ray left (MIS evaluates light sampling there)
    int maxBounces = min(uMaxBounces, HARD_PATH_LIMIT - 1);
#ifdef HAS_INDEX_MATCHED
    int crossings = 0; // of index-matched boundaries (media.glsl), which are not bounces
#endif
    // The guide buffers' depth of a camera ray that went through portals: along the unfolded ray.
    float travelled = 0.0; // before this segment
    float viewCos = dot(ray.direction, viewAxis);
#ifdef HAS_PORTALS
    int portalCrossings = 0; // a chain of portals ends at the bounce limit + 1: that quad is a surface
#endif
    RayCone cone = cameraCone();
    for (int depth = 0; depth <= maxBounces + 1; ++depth) {
        setTraceState(depth == 0, alphaKey(rng, 2u), cone);
        Hit hit = traceClosest(ray);
        float lampT, lampId;
        vec3 lamp = sphereLampEmission(ray, hit.t, lastBsdfPdf, lampT, lampId); // a sphere lamp in front ends the path
        bool scattered = false;
        float segment = hit.t; // to this vertex
#ifdef HAS_MEDIA
        MediumEvent event = sampleMediumEvent(medium, ray, min(hit.t, lampT), rng, spectral);
        throughput *= event.weight;
        scattered = event.scattered;
        if (scattered) segment = event.t;
        vec3 center;
        if (scattered && medium.kind == MEDIUM_FOG && fogLightCenter(ray.origin, rng, center)) {
            float weight;
            segment = fogScatterDistance(ray, min(hit.t, lampT), segment, center, rand1(rng), weight);
            throughput *= weight;
        }
#endif
#ifdef HAS_INDEX_MATCHED
        if (!scattered && hit.material >= 0 && hit.t < lampT && crossings < MAX_PATH_CROSSINGS && indexMatchedBoundary(hit.material)) {
            ++crossings;
            cone = RayCone(coneWidthAt(cone, hit.t), cone.spread);
            travelled += hit.t;
            throughput *= crossBoundary(hit, ray, medium);
            --depth; // not a bounce
            continue;
        }
#endif
#ifdef HAS_PORTALS
        int portalExitShape = scattered || hit.t >= lampT ? -1 : portalExit(hit);
        if (portalExitShape >= 0 && portalCrossings <= maxBounces) {
            ++portalCrossings;
#ifndef HAS_MEDIA
            throughput *= exp(-medium.sigmaT * hit.t);
#endif
            cone = RayCone(coneWidthAt(cone, hit.t), cone.spread);
            travelled += hit.t;
            ray = throughPortal(ray, hit.t, hit.triangle.y, portalExitShape);
            lastBsdfPdf = 0.0;
            lastPosition = ray.origin;
            --depth; // not a bounce
            continue;
        }
#endif
        if (depth == 1 && reflectedPath) lobes.reflectionDistance = min(min(segment, lampT), REFLECTION_AT_INFINITY);
        Vertex v;
        Medium across = medium; // the medium on the far side of the vertex's surface
        float curvature = 0.0;
        if (scattered) {
            v = mediumVertex(ray, segment, medium, cone);
            // The guide buffers describe what the camera ray meets behind the fog, not the random
            // scatter point: the denoisers' reprojection and edge stops need the same surface from
            // sample to sample. Its albedo is the fog's (the light this sample carries is the fog's).
            if (depth == 0) {
                result.albedo = medium.albedo;
                if (hit.material >= 0 && hit.t < lampT) {
                    result.normal = dot(hit.geometricNormal, ray.direction) < 0.0 ? hit.geometricNormal : -hit.geometricNormal;
                    result.depth = (travelled + hit.t) * viewCos;
                    result.objectId = hit.objectId;
                }
            }
        } else {
            if (lampT < hit.t) {
                addRadiance(result.radiance, lobes, throughput * lamp, specularPath);
                PASS_FOUND(depth, throughput * lamp, specularPath, false);
                if (depth == 0) {
                    result.albedo = lamp;
                    result.depth = (travelled + lampT) * viewCos;
                    result.objectId = lampId;
                }
                break;
            }
            if (hit.material < 0) {
                vec3 environment = environmentRadiance(ray.direction);
                vec3 found = throughput * (environment * environmentMisWeight(ray.direction, lastBsdfPdf) +
                                           sunDiskRadiance(ray.direction, lastBsdfPdf));
                addRadiance(result.radiance, lobes, found, specularPath);
                PASS_FOUND(depth, found, specularPath, true);
                if (depth == 0) result.albedo = environment;
                break;
            }
#ifndef HAS_MEDIA
            throughput *= exp(-medium.sigmaT * hit.t);
#endif
            v.position = ray.origin + hit.t * ray.direction;
            v.faceNormal = hit.geometricNormal;
            v.cone = RayCone(coneWidthAt(cone, hit.t), cone.spread);
            SurfaceShading shading = shadeSurface(hit, ray.direction, v.cone.width);
            v.frame = frameFromNormal(shading.normal);
            v.wo = localFromWorld(v.frame, -ray.direction);
            v.material = shading.material;
            v.inMedium = false;
            curvature = shading.curvature;
            // A closed volume's boundary: entering, its interior; leaving, the scene's medium.
            if (!v.material.thinWalled) across = v.wo.z > 0.0 ? interiorMedium(hit.material, v.material) : sceneMedium();
            if (depth == 0) {
                result.albedo = v.material.baseColor;
                result.normal = v.wo.z >= 0.0 ? shading.normal : -shading.normal;
                result.depth = (travelled + hit.t) * viewCos;
                result.objectId = hit.objectId;
                result.lobes = vec4(v.material.metallic, v.material.roughness, v.material.transmission, v.material.specularFactor);
            }
            vec3 emitted = throughput * shading.emission * emissionMisWeight(hit, shading.sampledEmission, ray, lastPosition, lastBsdfPdf);
            addRadiance(result.radiance, lobes, emitted, specularPath);
            PASS_FOUND(depth, emitted, specularPath, false);
        }
        if (depth > maxBounces) break;

        vec3 diffuseDirect;
        bool ends = endsAtLightSamples(v, depth, maxBounces);
        vec3 direct = throughput * directLight(v, medium, across, depth == 0, ends, rng, diffuseDirect);
        if (depth == 0) addSplitRadiance(result.radiance, lobes, direct, throughput * diffuseDirect);
        else addRadiance(result.radiance, lobes, direct, specularPath);
        PASS_LIGHT_SAMPLED(depth, direct, throughput * diffuseDirect, specularPath);
#ifdef AMBIENT_TERM
        if (depth == 0 && !scattered) {
            vec3 ambient = ambientTerm(v, rng);
            addRadiance(result.radiance, lobes, ambient, false); // diffuse: it is albedo x light
            PASS_LIGHT_SAMPLED(1, ambient, ambient, false);      // it stands for indirect diffuse light
        }
#endif

        if (ends) break;
        BsdfSample bs;
        if (!scatterSample(v, rand3(rng), bs) || maxComponent(bs.weight) <= 0.0) break;
        // Russian roulette on this bounce's weight (its albedo), not on the whole throughput: a
        // surviving path keeps its throughput, which keeps the estimator's tail short.
        if (depth >= ROULETTE_START) {
            float survive = min(maxComponent(bs.weight), 0.95);
            if (rand1(rng) >= survive) break;
            bs.weight /= survive;
        }
        throughput *= bs.weight;
        if (depth == 0) specularPath = (bs.lobe & LOBE_DIFFUSE) == 0u;
        if (depth == 0) reflectedPath = specularPath && (bs.wi.z > 0.0) == (v.wo.z > 0.0);
        lastBsdfPdf = (bs.lobe & LOBE_SPECULAR) != 0u ? 0.0 : bs.pdf;
        bool crosses = !scattered && (bs.wi.z > 0.0) != (v.wo.z > 0.0);
        if (crosses) medium = across;
        vec3 wi = worldFromLocal(v.frame, bs.wi);
        float lobeRoughness = (bs.lobe & LOBE_SPECULAR) != 0u ? 0.0 : ((bs.lobe & LOBE_DIFFUSE) != 0u ? 1.0 : v.material.roughness);
        cone = bounceCone(cone, segment, curvature, lobeRoughness);
        ray = spawnRay(v.position, v.faceNormal, wi);
        lastPosition = v.position;
    }
    if (uClamp > 0.0) clampRadiance(result.radiance, lobes, uClamp);
    return result;
}

// Debug view (the DEBUG_VIEW_AO variant): the fraction of a cosine-weighted hemisphere unoccluded
// within uAoDistance. Misses are black, so a convex object (unoccluded all over) still shows.
uniform float uAoDistance;

PathResult ambientOcclusion(Ray ray, vec3 viewAxis, INOUT(Rng) rng) {
    PathResult result = PathResult(vec3(0.0), vec3(1.0), vec3(0.0), -1.0, 0.0, vec4(0.0, 1.0, 0.0, 0.0));
    setTraceState(true, alphaKey(rng, 2u), cameraCone());
    Hit hit = traceClosest(ray);
    if (hit.material < 0) return result;
    vec3 p = ray.origin + hit.t * ray.direction;
    vec3 n = dot(ray.direction, hit.shadingNormal) < 0.0 ? hit.shadingNormal : -hit.shadingNormal;
    vec3 wi = worldFromLocal(frameFromNormal(n), cosineHemisphere(rand2(rng)));
    setTraceState(false, alphaKey(rng, 1u), cameraCone());
    float visible = occluded(spawnRay(p, hit.geometricNormal, wi), uAoDistance) ? 0.0 : 1.0;
    return PathResult(vec3(visible), vec3(1.0), n, hit.t * dot(ray.direction, viewAxis), hit.objectId, vec4(0.0, 1.0, 0.0, 0.0));
}
