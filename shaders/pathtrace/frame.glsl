// An orthonormal frame around a normal (Duff et al., "Building an Orthonormal Basis, Revisited").
struct Frame {
    vec3 tangent;
    vec3 bitangent;
    vec3 normal;
};

Frame frameAround(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return Frame(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

vec3 toLocal(Frame f, vec3 v) { return vec3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal)); }
vec3 toWorld(Frame f, vec3 v) { return v.x * f.tangent + v.y * f.bitangent + v.z * f.normal; }
