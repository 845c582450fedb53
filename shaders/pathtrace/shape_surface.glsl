// What texturing needs at an analytic shape's hit (HAS_TEXTURES): its UV (shape_uv.glsl, carried in
// Hit.barycentric), the tangent dp/du and the ray-cone LOD from dp/du and dp/dv in world space. The
// handedness is the one the tessellation's tangents get (glTF's: cross(n, dp/du) x sign points to
// -v, "up" in the image, MikkTSpace's sign negated since glTF's v runs down the image).
#include "textured_surface.glsl"

// dp/du and dp/dv in local space at `uv` of the face with local normal n.
void shapeDerivatives(int kind, vec3 n, vec2 uv, vec4 params, float height, out vec3 dpdu, out vec3 dpdv) {
    ShapeFace f = flatShapeFace(kind, n, params, height);
    if (f.u != vec3(0.0)) {
        dpdu = 2.0 * f.u;
        dpdv = -2.0 * f.v;
        return;
    }
    float phi = TWO_PI * uv.x;
    vec3 around = vec3(-sin(phi), 0.0, -cos(phi)); // d(cos phi, 0, -sin phi) / dphi
    if (kind == SHAPE_SPHERE) {
        float theta = PI * uv.y;
        float r = params.x;
        dpdu = TWO_PI * r * sin(theta) * around;
        dpdv = PI * r * vec3(cos(theta) * cos(phi), -sin(theta), -cos(theta) * sin(phi));
        return;
    }
    dpdu = TWO_PI * params.x * around; // the cylinder's side
    dpdv = vec3(0.0, -height, 0.0);
}

TexturedSurface shapeSurface(int shape, vec2 uv, vec3 rayDirection, vec3 geometricNormal, float coneWidth) {
    vec4 header = shapeTexel(shape, 0);
    vec4 params = shapeTexel(shape, 4);
    mat3 worldRows = mat3(shapeTexel(shape, 6).xyz, shapeTexel(shape, 7).xyz, shapeTexel(shape, 8).xyz); // W^T
    int kind = int(header.x);
    vec3 localNormal = normalize(worldRows * geometricNormal); // normals map back by W^T
    vec3 dpdu, dpdv;
    shapeDerivatives(kind, localNormal, uv, params, header.w, dpdu, dpdv);
    mat3 worldFromLocal = transpose(worldRows);
    vec3 tangent = worldFromLocal * dpdu;
    vec3 bitangent = worldFromLocal * dpdv;
    float worldArea = length(cross(tangent, bitangent)); // per unit UV area
    float lambda = coneLod(coneWidth, dot(rayDirection, geometricNormal), 1.0, worldArea);
    float handedness = dot(cross(geometricNormal, tangent), bitangent) < 0.0 ? 1.0 : -1.0;
    float scale = pow(max(shapeTexel(shape, 5).w, 1e-30), 1.0 / 3.0); // |det W|: the mean scale
    float curvature = kind == SHAPE_SPHERE || (kind == SHAPE_CYLINDER && abs(localNormal.y) < 0.5)
                          ? 1.0 / max(params.x * scale, 1e-12)
                          : 0.0;
    return TexturedSurface(uv, uv, vec4(1.0), tangent, handedness, lambda, lambda, curvature);
}
