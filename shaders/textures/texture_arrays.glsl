// Material textures in 2D texture arrays (renderer/gpu_scene/texture_arrays.h): one array per
// bucket of (colour space, size). TEXTURE_ARRAY_COUNT (0..3) of them are declared, never more than
// are bound: two sampler types on one texture unit would be an error at draw time. sRGB buckets
// are GL_SRGB8_ALPHA8, so every read below returns linear values.
#if TEXTURE_ARRAY_COUNT > 0
uniform sampler2DArray uTextureArray0;
uniform ivec2 uTextureArraySize0;
#endif
#if TEXTURE_ARRAY_COUNT > 1
uniform sampler2DArray uTextureArray1;
uniform ivec2 uTextureArraySize1;
#endif
#if TEXTURE_ARRAY_COUNT > 2
uniform sampler2DArray uTextureArray2;
uniform ivec2 uTextureArraySize2;
#endif

ivec2 textureArraySize(int bucket) {
#if TEXTURE_ARRAY_COUNT > 1
    if (bucket == 1) return uTextureArraySize1;
#endif
#if TEXTURE_ARRAY_COUNT > 2
    if (bucket == 2) return uTextureArraySize2;
#endif
#if TEXTURE_ARRAY_COUNT > 0
    return uTextureArraySize0;
#else
    return ivec2(1); // COLOR_0 alone: no texture is ever sampled
#endif
}

// Trilinear (GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT): callers have applied their own wrap mode.
vec4 textureArrayLod(int bucket, vec3 uvLayer, float lod) {
#if TEXTURE_ARRAY_COUNT > 1
    if (bucket == 1) return textureLod(uTextureArray1, uvLayer, lod);
#endif
#if TEXTURE_ARRAY_COUNT > 2
    if (bucket == 2) return textureLod(uTextureArray2, uvLayer, lod);
#endif
#if TEXTURE_ARRAY_COUNT > 0
    return textureLod(uTextureArray0, uvLayer, lod);
#else
    return vec4(1.0);
#endif
}

// One texel, no filtering (nearest sampling).
vec4 textureArrayFetch(int bucket, ivec3 texel, int level) {
#if TEXTURE_ARRAY_COUNT > 1
    if (bucket == 1) return texelFetch(uTextureArray1, texel, level);
#endif
#if TEXTURE_ARRAY_COUNT > 2
    if (bucket == 2) return texelFetch(uTextureArray2, texel, level);
#endif
#if TEXTURE_ARRAY_COUNT > 0
    return texelFetch(uTextureArray0, texel, level);
#else
    return vec4(1.0);
#endif
}
