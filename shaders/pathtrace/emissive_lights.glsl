// Emissive mesh triangles as lights (renderer/gpu_scene/emissive_triangles.h): one triangle chosen
// in proportion to its power, a uniform point on it. Triangles share one distribution with the
// emissive shapes and area lights (shape_lights.glsl): every area emitter is chosen in proportion
// to its power, luminance x area, out of areaEmitterPower(). So the pdf per unit area of any
// triangle point is luminance / areaEmitterPower(), which lets BSDF-sampled hits compute their MIS
// weight from the material alone. A single-sided material emits
// from its front face only (emissionSeen), so a point behind it gets no sample; the triangle's
// texels hold its vertices counter-clockwise seen from the front and, in the emission's w, 1 for a
// double-sided emitter. An emissive-textured triangle is chosen by its material's mean emission
// (the luminance its hits carry in SurfaceShading.sampledEmission) and its sample carries the
// texel's emission at the sampled point: unbiased whatever the texture's layout.
#ifdef HAS_MESHES
const int EMISSIVE_TRIANGLE_TEXELS = 5; // emissive_triangles.h
uniform samplerBuffer uEmissiveTriangles; // p0, p1, p2, emission, texturing
uniform samplerBuffer uEmissiveCdf;       // uEmissiveCount + 1 ascending values
uniform int uEmissiveCount;
uniform float uEmissivePower;
#endif
#ifdef HAS_EMISSIVE_SHAPES
uniform float uShapeEmitterPower; // the sum of the emissive shapes' powers (shape_lights.glsl)
#endif

// The power of the light-sampled emissive triangles (0: none).
float emissiveTrianglePower() {
#ifdef HAS_MESHES
    return uEmissiveCount > 0 ? uEmissivePower : 0.0;
#else
    return 0.0;
#endif
}

// The power of every light-sampled area emitter: triangles and emissive shapes.
float areaEmitterPower() {
#ifdef HAS_EMISSIVE_SHAPES
    return emissiveTrianglePower() + uShapeEmitterPower;
#else
    return emissiveTrianglePower();
#endif
}

struct AreaLightSample {
    vec3 direction;
    float distance;
    vec3 radiance;
    float pdf;     // per solid angle at the shading point
    vec3 target;   // where the shadow ray ends: the sampled point, moved off the emitter towards p
};

// Solid-angle pdf of light sampling for a point of emission `emission` seen at distance t under cos.
float emissiveLightPdf(vec3 emission, float t, float cosAtLight) {
#ifdef HAS_MESHES
    if (uEmissiveCount == 0 || cosAtLight <= 0.0) return 0.0;
    return luminance(emission) / areaEmitterPower() * t * t / cosAtLight;
#else
    return 0.0;
#endif
}

bool hasEmissiveTriangles() {
#ifdef HAS_MESHES
    return uEmissiveCount > 0;
#else
    return false;
#endif
}

#ifdef HAS_MESHES
int findEmissiveTriangle(float u) {
    int lo = 0;
    int hi = uEmissiveCount;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (texelFetch(uEmissiveCdf, mid).x <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}
#endif

#if defined(HAS_MESHES) && defined(HAS_TEXTURES)
// The emission at a point of an emissive-textured triangle: its texturing texel (slot / 65536,
// slot % 65536, 1, 1 if p1 and p2 were swapped) and the point's weights of the stored p1 and p2.
vec3 texturedTriangleEmission(vec4 texturing, vec2 storedWeights) {
    int slot = int(texturing.x) * 65536 + int(texturing.y);
    vec2 barycentric = texturing.w > 0.0 ? storedWeights.yx : storedWeights;
    int material = int(bvhTriangleVertices(slot).w);
    TextureRef r = fetchTextureRef(material, TEXREF_EMISSIVE);
    return fetchEmission(material) * sampleSurfaceTexture(meshPointSurface(slot, barycentric), r).rgb;
}
#endif

bool sampleEmissiveTriangle(vec3 p, vec3 u, OUT(AreaLightSample) s) {
    s = AreaLightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0, vec3(0.0));
#ifdef HAS_MESHES
    if (uEmissiveCount == 0) return false;
    int i = findEmissiveTriangle(u.x);
    int first = EMISSIVE_TRIANGLE_TEXELS * i;
    vec3 p0 = texelFetch(uEmissiveTriangles, first).xyz;
    vec3 p1 = texelFetch(uEmissiveTriangles, first + 1).xyz;
    vec3 p2 = texelFetch(uEmissiveTriangles, first + 2).xyz;
    vec4 emission = texelFetch(uEmissiveTriangles, first + 3);
    float su = sqrt(u.y);
    vec3 q = (1.0 - su) * p0 + (u.z * su) * p1 + (su - u.z * su) * p2;
    vec3 offset = q - p;
    float distance = length(offset);
    if (!(distance > 0.0)) return false;
    vec3 direction = offset / distance;
    vec3 normal = normalize(cross(p1 - p0, p2 - p0));
    float cosAtLight = -dot(normal, direction); // > 0: q's front faces p
    vec3 towardsP = cosAtLight >= 0.0 ? normal : -normal;
    if (emission.w > 0.0) cosAtLight = abs(cosAtLight);
    float pdf = emissiveLightPdf(emission.rgb, distance, cosAtLight);
    if (!(pdf > 0.0) || !isFiniteFloat(pdf)) return false;
    vec3 radiance = emission.rgb;
#ifdef HAS_TEXTURES
    vec4 texturing = texelFetch(uEmissiveTriangles, first + 4);
    if (texturing.z > 0.0) radiance = texturedTriangleEmission(texturing, vec2(u.z * su, su - u.z * su));
#endif
    s = AreaLightSample(direction, distance, radiance, pdf, bvhOffsetRayOrigin(q, towardsP));
    return true;
#else
    return false;
#endif
}
