// State of the ray being traced that the BVH's triangle filter (triangle_filter.glsl) reads: the
// traversal cannot carry the path's state, so the integrator sets it before each query. Scenes
// without the filter compile these to nothing that is read.
#include "textures/ray_cone.glsl"

bool gCullBackFaces = false;             // camera rays only
uvec4 gAlphaKey = uvec4(0u);             // random bits of this ray, for stochastic transparency
RayCone gFilterCone = RayCone(0.0, 0.0); // the ray's cone, for the alpha texture's LOD

void setTraceState(bool cullBackFaces, uvec4 alphaKey, RayCone cone) {
    gCullBackFaces = cullBackFaces;
    gAlphaKey = alphaKey;
    gFilterCone = cone;
}
