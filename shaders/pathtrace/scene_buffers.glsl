// The scene as texture buffers; layouts written by renderer/gpu_scene/scene_packing.cpp.
uniform samplerBuffer uShapes;    // SHAPE_TEXELS per shape
uniform int uShapeCount;
uniform samplerBuffer uMaterials; // MATERIAL_TEXELS per material
uniform samplerBuffer uLights;    // LIGHT_TEXELS per light
uniform int uLightCount;

const int SHAPE_TEXELS = 9; // packed_scene.h shapeTexels
const int MATERIAL_TEXELS = 31; // packed_scene.h materialTexels: 7 factor texels + 8 texture references (textures/texture_refs.glsl)
const int LIGHT_TEXELS = 4;

vec4 shapeTexel(int shape, int texel) { return texelFetch(uShapes, shape * SHAPE_TEXELS + texel); }
vec4 materialTexel(int material, int texel) { return texelFetch(uMaterials, material * MATERIAL_TEXELS + texel); }
vec4 lightTexel(int light, int texel) { return texelFetch(uLights, light * LIGHT_TEXELS + texel); }
