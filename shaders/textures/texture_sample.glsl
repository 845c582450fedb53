// Sampling one texture reference at a level of detail with its own sampler state. The arrays use
// GL_REPEAT and trilinear filtering for every texture, so clamp and mirrored-repeat wrapping and
// nearest filtering are done here: clamp keeps coordinates half a texel inside the edge (so the
// bilinear footprint never reaches the far side), mirrored repeat folds the coordinate and then
// clamps likewise (a mirrored edge repeats its own texel, which is what clamping gives), nearest
// reads one texel with texelFetch.
#include "textures/texture_arrays.glsl"
#include "textures/texture_refs.glsl"
#include "textures/ray_cone.glsl"

float mirrorCoord(float x) {
    float m = x - 2.0 * floor(0.5 * x); // [0, 2)
    return m > 1.0 ? 2.0 - m : m;
}

// Filtered coordinate for one axis at a level of `size` texels.
float wrapFiltered(float x, int mode, float size) {
    if (mode == WRAP_REPEAT) return x;
    float halfTexel = 0.5 / size;
    if (mode == WRAP_MIRROR) x = mirrorCoord(x);
    return clamp(x, halfTexel, 1.0 - halfTexel);
}

// Texel index for one axis (nearest), in [0, size).
int wrapNearest(float x, int mode, int size) {
    if (mode == WRAP_MIRROR) x = mirrorCoord(x);
    else if (mode == WRAP_REPEAT) x = x - floor(x);
    return clamp(int(floor(x * float(size))), 0, size - 1);
}

// `lod`: log2 of texels per footprint at level 0 (renderer ray cones). Below 0 the magnification
// filter applies, above it the minification filter (and mip levels only if the sampler has them).
vec4 sampleTextureRef(TextureRef r, vec2 uv, float lod) {
    ivec2 size = textureArraySize(r.bucket);
    int wrapS = r.flags % 3;
    int wrapT = (r.flags / 3) % 3;
    bool magnified = !(lod > 0.0); // also catches a NaN LOD
    bool nearest = magnified ? ((r.flags / 9) % 2 == 1) : ((r.flags / 18) % 2 == 1);
    int maxLevel = int(floor(log2(float(max(size.x, size.y)))));
    float level = (magnified || (r.flags / 36) % 2 == 0) ? 0.0 : min(lod, float(maxLevel));
    if (nearest) {
        int l = int(floor(level + 0.5));
        ivec2 s = max(size >> l, ivec2(1));
        return textureArrayFetch(r.bucket, ivec3(wrapNearest(uv.x, wrapS, s.x), wrapNearest(uv.y, wrapT, s.y), r.layer), l);
    }
    vec2 s = vec2(max(size >> int(level), ivec2(1)));
    return textureArrayLod(r.bucket, vec3(wrapFiltered(uv.x, wrapS, s.x), wrapFiltered(uv.y, wrapT, s.y), float(r.layer)), level);
}

// The LOD of one texture reference.
float textureRefLod(TextureRef r, float lambda) {
    ivec2 size = textureArraySize(r.bucket);
    return lambda + 0.5 * log2(float(size.x) * float(size.y)) + transformLodBias(r);
}
