// What texturing needs at a mesh hit (HAS_TEXTURES): interpolated UV sets, COLOR_0, the MikkTSpace
// tangent in world space, the ray-cone LOD per UV set, and a curvature estimate for the cone's
// next spread. Vertex texels (gpu_meshes.cpp): normal, (uv0, uv1), tangent, colour.
#include "textured_surface.glsl"

mat3 meshLocalFromWorld(int instance) {
    return transpose(mat3(bvhInstanceRow(instance, 0).xyz, bvhInstanceRow(instance, 1).xyz, bvhInstanceRow(instance, 2).xyz));
}

float uvArea(vec2 a, vec2 b, vec2 c) {
    vec2 e1 = b - a;
    vec2 e2 = c - a;
    return abs(e1.x * e2.y - e1.y * e2.x);
}

float edgeCurvature(vec3 n0, vec3 n1, vec3 p0, vec3 p1) {
    return length(n1 - n0) / max(length(p1 - p0), 1e-12);
}

// The UV sets at a point of a slot's triangle (weights of vertices 1 and 2) seen by no ray: a light
// sample, which reads the textures' base level.
TexturedSurface meshPointSurface(int slot, vec2 barycentric) {
    uvec4 v = bvhTriangleVertices(slot);
    vec3 w = vec3(1.0 - barycentric.x - barycentric.y, barycentric.x, barycentric.y);
    vec4 uv = w.x * vertexTexel(v.x, 1) + w.y * vertexTexel(v.y, 1) + w.z * vertexTexel(v.z, 1);
    return TexturedSurface(uv.xy, uv.zw, vec4(1.0), vec3(0.0), 1.0, -64.0, -64.0, 0.0);
}

TexturedSurface meshSurface(int slot, int instance, vec2 barycentric, vec3 rayDirection, vec3 geometricNormal, float coneWidth) {
    uvec4 v = bvhTriangleVertices(slot);
    vec3 w = vec3(1.0 - barycentric.x - barycentric.y, barycentric.x, barycentric.y);
    vec4 t0 = vertexTexel(v.x, 1), t1 = vertexTexel(v.y, 1), t2 = vertexTexel(v.z, 1);
    vec4 tangent = w.x * vertexTexel(v.x, 2) + w.y * vertexTexel(v.y, 2) + w.z * vertexTexel(v.z, 2);
    vec4 color = w.x * vertexTexel(v.x, 3) + w.y * vertexTexel(v.y, 3) + w.z * vertexTexel(v.z, 3);
    mat3 worldFromLocal = inverse(meshLocalFromWorld(instance));
    vec3 p0 = bvhTrianglePosition(slot, 0), p1 = bvhTrianglePosition(slot, 1), p2 = bvhTrianglePosition(slot, 2);
    float worldArea = length(cross(worldFromLocal * (p1 - p0), worldFromLocal * (p2 - p0)));
    float cosine = dot(rayDirection, geometricNormal);
    vec3 n0 = vertexTexel(v.x, 0).xyz, n1 = vertexTexel(v.y, 0).xyz, n2 = vertexTexel(v.z, 0).xyz;
    float curvature = max(edgeCurvature(n0, n1, p0, p1), max(edgeCurvature(n1, n2, p1, p2), edgeCurvature(n2, n0, p2, p0)));
    float mirrored = (bvhInstanceInfo(instance).w & BVH_INSTANCE_MIRRORED) != 0u ? -1.0 : 1.0;
    return TexturedSurface(w.x * t0.xy + w.y * t1.xy + w.z * t2.xy, w.x * t0.zw + w.y * t1.zw + w.z * t2.zw, color,
                       worldFromLocal * tangent.xyz, (tangent.w < 0.0 ? -1.0 : 1.0) * mirrored,
                       coneLod(coneWidth, cosine, uvArea(t0.xy, t1.xy, t2.xy), worldArea),
                       coneLod(coneWidth, cosine, uvArea(t0.zw, t1.zw, t2.zw), worldArea),
                       isFiniteFloat(curvature) ? curvature : 0.0);
}
