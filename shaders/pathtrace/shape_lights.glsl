// Emissive analytic shapes and area lights (packed as shapes) as lights, in the one
// power-proportional distribution of area emitters they share with the emissive triangles
// (emissive_lights.glsl): shape s is chosen with probability power_s / (triangle power + shape
// power), power_s = luminance x world area (renderer/gpu_scene/packed_scene.cpp), and sampled by
// sampling/shape_emitter.glsl. Compiled in only for scenes that have one (HAS_EMISSIVE_SHAPES).
// Shape texel 5: power (0: not an emitter), cumulative power through this shape, 0, |det M|;
// texels 6..8: worldFromLocal's rows.
#ifdef HAS_EMISSIVE_SHAPES
ShapeEmitter shapeEmitter(int shape) {
    vec4 header = shapeTexel(shape, 0);
    vec4 params = shapeTexel(shape, 4);
    return ShapeEmitter(int(header.x), params.x, params.yzw, header.w, shapeTexel(shape, 1), shapeTexel(shape, 2),
                        shapeTexel(shape, 3), shapeTexel(shape, 6), shapeTexel(shape, 7), shapeTexel(shape, 8),
                        shapeTexel(shape, 5).w);
}

// The emissive shape whose share of the cumulative shape power holds x (0 <= x < uShapeEmitterPower)
// and where in its share x lies (0..1): a linear scan, shapes are few.
int findShapeEmitter(float x, OUT(float) within) {
    int found = -1;
    within = 0.0;
    for (int shape = 0; shape < uShapeCount; ++shape) {
        vec4 e = shapeTexel(shape, 5);
        if (!(e.x > 0.0)) continue;
        found = shape;
        within = clamp((x - (e.y - e.x)) / e.x, 0.0, 0.99999994);
        if (x < e.y) break;
    }
    return found;
}

// The solid-angle pdf with which light sampling picks shape `shape` and, on it, the point q with
// outward normal n, as seen from p (0: a shape that is not light-sampled). `areaPower`: the total
// power of the area emitters.
float shapeLightPdf(int shape, vec3 p, vec3 q, vec3 n, float areaPower) {
    float power = shapeTexel(shape, 5).x;
    if (!(power > 0.0) || !(areaPower > 0.0)) return 0.0;
    return power / areaPower * shapeEmitterPdf(shapeEmitter(shape), p, q, n);
}

// A point of an emissive shape for p, chosen by x in [0, uShapeEmitterPower) and uv. An area light
// seen from behind (its material's front-only flag) gives nothing.
bool sampleShapeLight(vec3 p, float x, vec2 uv, float areaPower, OUT(AreaLightSample) s) {
    s = AreaLightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0, vec3(0.0));
    float within;
    int shape = findShapeEmitter(x, within);
    if (shape < 0) return false;
    ShapePoint point;
    if (!sampleShapeEmitter(shapeEmitter(shape), p, vec3(within, uv.x, uv.y), point)) return false;
    vec3 offset = point.point - p;
    float distance = length(offset);
    if (!(distance > 0.0)) return false;
    vec3 direction = offset / distance;
    int material = int(shapeTexel(shape, 0).y);
    bool facesP = dot(point.normal, direction) < 0.0;
    if (materialTexel(material, 5).w == MATERIAL_FRONT_ONLY && !facesP) return false;
    float pdf = shapeTexel(shape, 5).x / areaPower * point.pdf;
    if (!(pdf > 0.0) || !isFiniteFloat(pdf)) return false;
    s = AreaLightSample(direction, distance, fetchEmission(material), pdf,
                        bvhOffsetRayOrigin(point.point, facesP ? point.normal : -point.normal));
    return true;
}
#endif
