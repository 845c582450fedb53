// Texture coordinates of the analytic shapes (HAS_TEXTURES): the same as their tessellation's
// (scene/geometry/shape_tessellation.cpp), which is what the glTF file carries for other viewers,
// so a texture lands where Blender shows it. Local space, from the hit point and local normal.
// Flat faces span +-u and +-v about a centre c, uv (0, 0) at the -u, +v corner; the sphere and the
// cylinder's side turn u once around +Y from +X (counter-clockwise seen from +Y) and run v from the
// top (0) to the bottom (1); the ground plane maps GROUND_UV_EXTENT metres to one UV unit.
const float GROUND_UV_EXTENT = 200.0;

struct ShapeFace {
    vec3 centre;
    vec3 u; // half extents, as vectors
    vec3 v;
};

// The flat face of `kind` with the (local) outward normal n; curved surfaces return none (u = 0).
ShapeFace flatShapeFace(int kind, vec3 n, vec4 params, float height) {
    float radius = params.x;
    vec3 h = 0.5 * params.yzw;
    vec3 X = vec3(1.0, 0.0, 0.0), Y = vec3(0.0, 1.0, 0.0), Z = vec3(0.0, 0.0, 1.0);
    if (kind == SHAPE_QUAD) return ShapeFace(vec3(0.0), h.x * X, -h.z * Z);
    if (kind == SHAPE_GROUND_PLANE) return ShapeFace(vec3(0.0), 0.5 * GROUND_UV_EXTENT * X, -0.5 * GROUND_UV_EXTENT * Z);
    if (kind == SHAPE_DISK) return ShapeFace(vec3(0.0), radius * X, -radius * Z);
    if (kind == SHAPE_CYLINDER) {
        if (abs(n.y) < 0.5) return ShapeFace(vec3(0.0), vec3(0.0), vec3(0.0)); // the side
        // Seen from below the rim runs the other way round, and v is mirrored so the texture is not.
        return ShapeFace(vec3(0.0, sign(n.y) * 0.5 * height, 0.0), radius * X, -sign(n.y) * radius * Z);
    }
    if (kind == SHAPE_BOX) {
        vec3 m = abs(n);
        if (m.x >= m.y && m.x >= m.z) return ShapeFace(sign(n.x) * h.x * X, -sign(n.x) * h.z * Z, h.y * Y);
        if (m.y >= m.z) return ShapeFace(sign(n.y) * h.y * Y, h.x * X, -sign(n.y) * h.z * Z);
        return ShapeFace(sign(n.z) * h.z * Z, sign(n.z) * h.x * X, h.y * Y);
    }
    return ShapeFace(vec3(0.0), vec3(0.0), vec3(0.0)); // the sphere
}

float turnAroundY(vec3 p) {
    float angle = atan(-p.z, p.x);
    return (angle < 0.0 ? angle + TWO_PI : angle) / TWO_PI;
}

vec2 shapeUv(int kind, vec3 p, vec3 n, vec4 params, float height) {
    ShapeFace f = flatShapeFace(kind, n, params, height);
    if (f.u != vec3(0.0)) {
        vec3 d = p - f.centre;
        return vec2(0.5 * (dot(d, f.u) / dot(f.u, f.u) + 1.0), 0.5 * (1.0 - dot(d, f.v) / dot(f.v, f.v)));
    }
    if (kind == SHAPE_SPHERE) return vec2(turnAroundY(p), acos(clamp(p.y / params.x, -1.0, 1.0)) / PI);
    return vec2(turnAroundY(p), 0.5 - p.y / height); // the cylinder's side
}
