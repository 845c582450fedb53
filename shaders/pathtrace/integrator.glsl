// The path integrator: next-event estimation at every vertex, BSDF sampling to continue, Russian
// roulette, and a bounce limit with CONTRACTS.md semantics: bounces = 0 renders emitters and
// direct light only; each further bounce adds one indirect vertex.
uniform int uMaxBounces;
uniform float uClamp; // 0: off (unbiased)

const int ROULETTE_START = 3;
const int HARD_PATH_LIMIT = 64; // a guard, not a setting: uMaxBounces is clamped below it

struct PathResult {
    vec3 radiance;
    vec3 albedo;    // first hit's base colour (or the environment's radiance)
    vec3 normal;    // first hit's shading normal, world space
    float depth;    // along the camera's view axis; -1: nothing hit
    float objectId; // node id of the first hit; 0: nothing
};

// Direct light from every punctual light, unoccluded, times the BSDF.
vec3 directLight(vec3 p, vec3 faceNormal, Frame frame, Surface s, vec3 wo, INOUT(Rng) rng) {
    vec3 sum = vec3(0.0);
    for (int light = 0; light < uLightCount; ++light) {
        LightSample ls = sampleLight(light, p, rand2(rng));
        vec3 wi = localFromWorld(frame, ls.direction);
        float pdf;
        vec3 f = evalBsdf(s, wo, wi, pdf);
        if (maxComponent(f) <= 0.0) continue;
        if (!occluded(spawnRay(p, faceNormal, ls.direction), ls.distance)) sum += f * ls.irradiance;
    }
    return sum;
}

PathResult tracePath(Ray ray, vec3 viewAxis, INOUT(Rng) rng) {
    PathResult result = PathResult(vec3(0.0), vec3(0.0), vec3(0.0), -1.0, 0.0);
    vec3 throughput = vec3(1.0);
    vec3 attenuation = vec3(0.0); // Beer-Lambert sigma of the medium the ray travels in
    int maxBounces = min(uMaxBounces, HARD_PATH_LIMIT - 1);
    for (int vertex = 0; vertex <= maxBounces + 1; ++vertex) {
        Hit hit = traceClosest(ray);
        if (hit.material < 0) {
            vec3 environment = environmentRadiance(ray.direction);
            result.radiance += throughput * environment;
            if (vertex == 0) result.albedo = environment;
            break;
        }
        throughput *= exp(-attenuation * hit.t);
        Surface s = fetchSurface(hit.material);
        vec3 p = ray.origin + hit.t * ray.direction;
        bool entering = dot(ray.direction, hit.geometricNormal) < 0.0;
        vec3 n = entering ? hit.shadingNormal : -hit.shadingNormal;
        if (vertex == 0) {
            result.albedo = s.baseColor;
            result.normal = n;
            result.depth = hit.t * dot(ray.direction, viewAxis);
            result.objectId = hit.objectId;
        }
        result.radiance += throughput * s.emission;
        if (vertex > maxBounces) break;

        Frame frame = frameFromNormal(n);
        vec3 wo = localFromWorld(frame, -ray.direction);
        result.radiance += throughput * directLight(p, hit.geometricNormal, frame, s, wo, rng);

        BsdfSample bs = sampleBsdf(s, wo, entering, rand3(rng));
        if (maxComponent(bs.weight) <= 0.0) break;
        // Russian roulette on this bounce's weight (its albedo), not on the whole throughput: a
        // surviving path keeps its throughput, which keeps the estimator's tail short.
        if (vertex >= ROULETTE_START) {
            float survive = min(maxComponent(bs.weight), 0.95);
            if (rand1(rng) >= survive) break;
            bs.weight /= survive;
        }
        throughput *= bs.weight;
        vec3 wi = worldFromLocal(frame, bs.wi);
        if (bs.wi.z < 0.0 && !s.thinWalled) attenuation = entering ? s.attenuationCoefficient : vec3(0.0);
        ray = spawnRay(p, hit.geometricNormal, wi);
    }
    if (uClamp > 0.0) result.radiance = min(result.radiance, vec3(uClamp));
    return result;
}

// Debug view: the fraction of a cosine-weighted hemisphere unoccluded within uAoDistance.
uniform float uAoDistance;

PathResult ambientOcclusion(Ray ray, vec3 viewAxis, INOUT(Rng) rng) {
    PathResult result = PathResult(vec3(1.0), vec3(1.0), vec3(0.0), -1.0, 0.0);
    Hit hit = traceClosest(ray);
    if (hit.material < 0) return result;
    vec3 p = ray.origin + hit.t * ray.direction;
    vec3 n = dot(ray.direction, hit.shadingNormal) < 0.0 ? hit.shadingNormal : -hit.shadingNormal;
    vec3 wi = worldFromLocal(frameFromNormal(n), cosineHemisphere(rand2(rng)));
    float visible = occluded(spawnRay(p, hit.geometricNormal, wi), uAoDistance) ? 0.0 : 1.0;
    return PathResult(vec3(visible), vec3(1.0), n, hit.t * dot(ray.direction, viewAxis), hit.objectId);
}
