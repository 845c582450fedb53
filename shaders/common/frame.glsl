// An orthonormal basis around a unit normal without a branch on a threshold (Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited"). BSDFs work in the local frame where the normal is +Z.
#ifdef __cplusplus
#pragma once
#endif
#include "common/compat.glsl"

struct Frame {
    vec3 tangent;
    vec3 bitangent;
    vec3 normal;
};

Frame frameFromNormal(vec3 n) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    return Frame(vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

vec3 localFromWorld(Frame f, vec3 v) { return vec3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal)); }

vec3 worldFromLocal(Frame f, vec3 v) { return v.x * f.tangent + v.y * f.bitangent + v.z * f.normal; }
