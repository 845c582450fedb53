// Baseline's ambient term (the AMBIENT_TERM variant: only configurations that cut paths short,
// configuration.h `ao`; a configuration that converges never compiles it). It stands in for the
// light that the missing bounces would bring: one cosine-weighted ray of length uAmbientDistance
// from the first hit; unoccluded, it adds the diffuse albedo times the environment's radiance in
// that direction. Its mean is the diffuse albedo times the environment's cosine-weighted average
// radiance over the directions that are open within that distance (without a map: the project's
// environment colour times the ambient-occlusion term). docs/DENOISING.md says where it helps.
uniform float uAmbientDistance; // metres: FrameSettings::aoDistance

vec3 ambientTerm(Vertex v, INOUT(Rng) rng) {
    vec3 albedo = bsdfAlbedo(v.material, v.wo).diffuse;
    vec2 u = rand2(rng);
    if (!(maxComponent(albedo) > 0.0)) return vec3(0.0);
    vec3 n = v.wo.z >= 0.0 ? v.frame.normal : -v.frame.normal;
    vec3 wi = worldFromLocal(frameFromNormal(n), cosineHemisphere(u));
    setTraceState(false, alphaKey(rng, 3u), v.cone);
    if (occluded(spawnRay(v.position, v.faceNormal, wi), uAmbientDistance)) return vec3(0.0);
    return albedo * environmentRadiance(wi);
}
