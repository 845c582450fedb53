// Emissive analytic shapes (and area lights, which the renderer packs as shapes) as lights: a point
// of a shape sampled as seen from a shading point, and the density of that sampling, for
// next-event estimation and for the MIS weight of BSDF-sampled rays that hit the shape.
//
// A shape lives in its local space (scene/core/components.h) under an affine map M = worldFromLocal
// (any rotation, scale or shear; L = M^-1 = localFromWorld). It is sampled in local space, where it
// is canonical, by the best cheap method for its kind, and the local density per unit area is
// carried to the world by the surface's Jacobian,
//     dA_world / dA_local = |det M| |L^T n_local|     (n_local: the unit local normal),
// then to solid angle at the shading point p: pdf = density_world * d^2 / |cos at the shape|.
// Under a similarity (rotation, uniform scale) the local solid-angle methods stay uniform in solid
// angle; under other maps they stay exact densities, only no longer uniform.
// - sphere: uniform over the cone of directions it subtends from p (its visible cap); from inside,
//   or on the surface (within SPHERE_SURFACE_MARGIN: a point of the sphere itself, a hair outside
//   in float, would find only itself in its cone), uniform over its area;
// - quad: the spherical rectangle (Urena, Fajardo and King 2013, as pbrt-v4 writes it), uniform in
//   solid angle, where it subtends between SPHERICAL_RECT_MIN and SPHERICAL_RECT_MAX steradians;
//   by area otherwise (far away the two agree; nearly edge-on the warp loses its float digits);
// - disk: by area (concentric map);
// - box: by area over the faces p sees (the planes p is outside of; all six from inside);
// - cylinder: by area over the parts p sees: a cap whose outside p is on, and the strip of the side
//   facing p (azimuths within acos(r / rho) of p's, rho its distance from the axis); all from inside.
// Points that p cannot see (the far side of a box, a cylinder's back) are never sampled, so no
// shadow ray is spent on them; points hidden by other geometry are the shadow ray's business.
#ifdef __cplusplus
#pragma once
#endif
#include "common/frame.glsl"
#include "common/math.glsl"
#include "sampling/sphere_light.glsl"
#include "sampling/warp.glsl"

// ShapeKind's values (scene/core/components.h); ground planes are infinite and never sampled.
const int EMITTER_SPHERE = 0;
const int EMITTER_QUAD = 1;
const int EMITTER_DISK = 2;
const int EMITTER_BOX = 3;
const int EMITTER_CYLINDER = 4;

const float SPHERICAL_RECT_MIN = 1e-2f;
const float SPHERICAL_RECT_MAX = 6.2f;
// Points with |p|^2 <= r^2 (1 + margin) sample a sphere by area (as from inside): a point on the
// surface, rounded a few ULPs outside, is inside in this sense. Area sampling is unbiased from
// anywhere (what p cannot see gets no light through the shadow ray); the cone is only better.
const float SPHERE_SURFACE_MARGIN = 1e-3f;

struct ShapeEmitter {
    int kind;
    float radius;  // sphere, disk, cylinder
    vec3 size;     // box: full extents; quad: size.x by size.z in the XZ plane (normal +Y)
    float height;  // cylinder, along +Y
    vec4 local0;   // rows of localFromWorld (3 x 4)
    vec4 local1;
    vec4 local2;
    vec4 world0;   // rows of worldFromLocal (3 x 4)
    vec4 world1;
    vec4 world2;
    float absDet;  // |det| of worldFromLocal's 3 x 3 part
};

struct ShapePoint {
    vec3 point;  // world
    vec3 normal; // world, unit, the shape's outward normal there
    float pdf;   // per unit solid angle at the shading point
};

vec3 rowsTimesPoint(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(r0.x * p.x + r0.y * p.y + r0.z * p.z + r0.w, r1.x * p.x + r1.y * p.y + r1.z * p.z + r1.w,
                r2.x * p.x + r2.y * p.y + r2.z * p.z + r2.w);
}

// (rows)^T v: a local normal through L^T, or a world normal back through M^T.
vec3 rowsTransposeTimes(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(r0.x * v.x + r1.x * v.y + r2.x * v.z, r0.y * v.x + r1.y * v.y + r2.y * v.z,
                r0.z * v.x + r1.z * v.y + r2.z * v.z);
}

// Directions within the cone of 1 - cos(half angle) = oneMinusCos around +Z, uniform; written with
// 1 - cos so that far, small cones keep their digits (1 - 1e-9 is 1 in float).
vec3 uniformConeOneMinusCos(vec2 u, float oneMinusCos) {
    float t = u.x * oneMinusCos; // 1 - cos(theta)
    float sinTheta = safeSqrt(t * (2.0f - t));
    float phi = TWO_PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), 1.0f - t);
}

// ---- Sphere ----

bool sphereSampledByArea(float radius, float centre2) { return centre2 <= radius * radius * (1.0f + SPHERE_SURFACE_MARGIN); }

float sphereLocalDensity(float radius, vec3 p, vec3 q, vec3 n) {
    float centre2 = dot(p, p);
    if (sphereSampledByArea(radius, centre2)) return 1.0f / (2.0f * TWO_PI * radius * radius);
    vec3 toP = p - q;
    float d2 = dot(toP, toP);
    float cosAt = dot(n, toP) * inversesqrt(d2);
    if (!(cosAt > 0.0f)) return 0.0f;
    return conePdfFromOneMinusCos(sphereConeOneMinusCos(radius, centre2)) * cosAt / d2;
}

void sampleSphereLocal(float radius, vec3 p, vec2 u, OUT(vec3) q, OUT(vec3) n) {
    float centre2 = dot(p, p);
    if (sphereSampledByArea(radius, centre2)) {
        n = uniformSphere(u);
        q = radius * n;
        return;
    }
    vec3 offset = -p; // towards the centre
    vec3 axis = offset * inversesqrt(centre2);
    vec3 direction = worldFromLocal(frameFromNormal(axis), uniformConeOneMinusCos(u, sphereConeOneMinusCos(radius, centre2)));
    float along = dot(direction, offset);
    vec3 perpendicular = offset - along * direction; // no cancellation of d^2 - along^2 far away
    float t = along - safeSqrt(radius * radius - dot(perpendicular, perpendicular));
    q = p + t * direction;
    n = normalize(q);
}

// ---- Quad: the rectangle |x| <= size.x / 2, |z| <= size.z / 2 of the plane y = 0 ----

// Solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom and Strackee 1983).
float triangleSolidAngle(vec3 a, vec3 b, vec3 c) {
    float la = length(a);
    float lb = length(b);
    float lc = length(c);
    float numerator = abs(dot(a, cross(b, c)));
    float denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return 2.0f * atan(numerator, denominator);
}

float quadSolidAngle(vec3 size, vec3 p) {
    float x0 = -0.5f * size.x - p.x;
    float x1 = 0.5f * size.x - p.x;
    float z0 = -0.5f * size.z - p.z;
    float z1 = 0.5f * size.z - p.z;
    vec3 v00 = vec3(x0, -p.y, z0);
    vec3 v10 = vec3(x1, -p.y, z0);
    vec3 v11 = vec3(x1, -p.y, z1);
    vec3 v01 = vec3(x0, -p.y, z1);
    return triangleSolidAngle(v00, v10, v11) + triangleSolidAngle(v00, v11, v01);
}

bool quadUsesSolidAngle(float solidAngle) { return solidAngle > SPHERICAL_RECT_MIN && solidAngle < SPHERICAL_RECT_MAX; }

float quadLocalDensity(vec3 size, vec3 p, vec3 q) {
    float solidAngle = quadSolidAngle(size, p);
    if (!quadUsesSolidAngle(solidAngle)) return 1.0f / (size.x * size.z);
    vec3 toP = p - q;
    float d2 = dot(toP, toP);
    return abs(toP.y) * inversesqrt(d2) / (d2 * solidAngle);
}

// The angle between two unit vectors, without acos's loss near 0 and pi.
float angleBetweenUnit(vec3 a, vec3 b) {
    if (dot(a, b) < 0.0f) return PI - 2.0f * asin(min(length(a + b) * 0.5f, 1.0f));
    return 2.0f * asin(min(length(b - a) * 0.5f, 1.0f));
}

// pbrt-v4's SampleSphericalRectangle for the quad: in a frame with x along the quad's X, y along its
// Z and z from p's side towards the plane (z0 = -|p.y|).
vec3 sampleSphericalQuad(vec3 size, vec3 p, vec2 u) {
    float x0 = -0.5f * size.x - p.x;
    float y0 = -0.5f * size.z - p.z;
    float z0 = -abs(p.y);
    float x1 = x0 + size.x;
    float y1 = y0 + size.z;
    vec3 v00 = vec3(x0, y0, z0);
    vec3 v01 = vec3(x0, y1, z0);
    vec3 v10 = vec3(x1, y0, z0);
    vec3 v11 = vec3(x1, y1, z0);
    vec3 n0 = normalize(cross(v00, v10));
    vec3 n1 = normalize(cross(v10, v11));
    vec3 n2 = normalize(cross(v11, v01));
    vec3 n3 = normalize(cross(v01, v00));
    float g0 = angleBetweenUnit(-n0, n1);
    float g1 = angleBetweenUnit(-n1, n2);
    float g2 = angleBetweenUnit(-n2, n3);
    float g3 = angleBetweenUnit(-n3, n0);
    float b0 = n0.z;
    float b1 = n2.z;
    float au = u.x * (g0 + g1 - TWO_PI) + (u.x - 1.0f) * (g2 + g3);
    float fu = (cos(au) * b0 - b1) / sin(au);
    float cu = (fu >= 0.0f ? 1.0f : -1.0f) / sqrt(fu * fu + b0 * b0);
    cu = clamp(cu, -0.99999994f, 0.99999994f);
    float xu = clamp(-(cu * z0) / safeSqrt(1.0f - cu * cu), x0, x1);
    float dd = sqrt(xu * xu + z0 * z0);
    float h0 = y0 / sqrt(dd * dd + y0 * y0);
    float h1 = y1 / sqrt(dd * dd + y1 * y1);
    float hv = h0 + u.y * (h1 - h0);
    float yv = hv * hv < 1.0f - 1e-6f ? hv * dd / sqrt(1.0f - hv * hv) : y1;
    return vec3(p.x + xu, 0.0f, p.z + clamp(yv, y0, y1));
}

void sampleQuadLocal(vec3 size, vec3 p, vec2 u, OUT(vec3) q, OUT(vec3) n) {
    n = vec3(0.0f, 1.0f, 0.0f);
    if (quadUsesSolidAngle(quadSolidAngle(size, p))) q = sampleSphericalQuad(size, p, u);
    else q = vec3((u.x - 0.5f) * size.x, 0.0f, (u.y - 0.5f) * size.z);
}

// ---- Disk: radius r in the plane y = 0 ----

float diskLocalDensity(float radius) { return 1.0f / (PI * radius * radius); }

void sampleDiskLocal(float radius, vec2 u, OUT(vec3) q, OUT(vec3) n) {
    vec2 d = concentricDisk(u);
    q = vec3(radius * d.x, 0.0f, radius * d.y);
    n = vec3(0.0f, 1.0f, 0.0f);
}

// ---- Box: full extents `size`, centred on the origin ----

// Face f: axis f / 2 (0 x, 1 y, 2 z), outward sign + for even f.
float boxFaceArea(vec3 size, int axis) { return axis == 0 ? size.y * size.z : (axis == 1 ? size.x * size.z : size.x * size.y); }

bool boxInside(vec3 size, vec3 p) { return abs(p.x) <= 0.5f * size.x && abs(p.y) <= 0.5f * size.y && abs(p.z) <= 0.5f * size.z; }

float axisValue(vec3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

// Whether p sees face f from outside (the whole face: the box is convex); from inside every face.
bool boxFaceSeen(vec3 size, vec3 p, int face, bool inside) {
    if (inside) return true;
    int axis = face / 2;
    float halfExtent = 0.5f * axisValue(size, axis);
    return face % 2 == 0 ? axisValue(p, axis) > halfExtent : axisValue(p, axis) < -halfExtent;
}

float boxSeenArea(vec3 size, vec3 p) {
    bool inside = boxInside(size, p);
    float area = 0.0f;
    for (int face = 0; face < 6; ++face)
        if (boxFaceSeen(size, p, face, inside)) area += boxFaceArea(size, face / 2);
    return area;
}

// The face an outward local normal belongs to.
int boxFaceOf(vec3 n) {
    vec3 a = abs(n);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (axisValue(n, axis) >= 0.0f ? 0 : 1);
}

float boxLocalDensity(vec3 size, vec3 p, vec3 n) {
    if (!boxFaceSeen(size, p, boxFaceOf(n), boxInside(size, p))) return 0.0f;
    float area = boxSeenArea(size, p);
    return area > 0.0f ? 1.0f / area : 0.0f;
}

bool sampleBoxLocal(vec3 size, vec3 p, vec3 u, OUT(vec3) q, OUT(vec3) n) {
    bool inside = boxInside(size, p);
    float area = boxSeenArea(size, p);
    q = vec3(0.0f);
    n = vec3(0.0f, 1.0f, 0.0f);
    if (!(area > 0.0f)) return false;
    float x = u.x * area;
    int chosen = -1;
    for (int face = 0; face < 6; ++face) {
        if (!boxFaceSeen(size, p, face, inside)) continue;
        chosen = face;
        float faceArea = boxFaceArea(size, face / 2);
        if (x < faceArea) break;
        x -= faceArea;
    }
    int axis = chosen / 2;
    float side = chosen % 2 == 0 ? 1.0f : -1.0f;
    float a = u.y - 0.5f;
    float b = u.z - 0.5f;
    if (axis == 0) {
        q = vec3(side * 0.5f * size.x, a * size.y, b * size.z);
        n = vec3(side, 0.0f, 0.0f);
    } else if (axis == 1) {
        q = vec3(a * size.x, side * 0.5f * size.y, b * size.z);
        n = vec3(0.0f, side, 0.0f);
    } else {
        q = vec3(a * size.x, b * size.y, side * 0.5f * size.z);
        n = vec3(0.0f, 0.0f, side);
    }
    return true;
}

// ---- Cylinder: radius r, height h along +Y, centred on the origin; closed by two caps ----

bool cylinderInside(float radius, float height, vec3 p) {
    return p.x * p.x + p.z * p.z <= radius * radius && abs(p.y) <= 0.5f * height;
}

// Half the azimuth range of the side that p sees (0: none; pi: all of it, from inside).
float cylinderSeenHalfArc(float radius, vec3 p, bool inside) {
    if (inside) return PI;
    float rho2 = p.x * p.x + p.z * p.z;
    if (rho2 <= radius * radius) return 0.0f;
    return acos(clamp(radius * inversesqrt(rho2), 0.0f, 1.0f));
}

// Seen areas: x the top cap, y the bottom cap, z the side.
vec3 cylinderSeenAreas(float radius, float height, vec3 p) {
    bool inside = cylinderInside(radius, height, p);
    float cap = PI * radius * radius;
    return vec3(inside || p.y > 0.5f * height ? cap : 0.0f, inside || p.y < -0.5f * height ? cap : 0.0f,
                2.0f * cylinderSeenHalfArc(radius, p, inside) * radius * height);
}

float cylinderLocalDensity(float radius, float height, vec3 p, vec3 q, vec3 n) {
    vec3 areas = cylinderSeenAreas(radius, height, p);
    float total = areas.x + areas.y + areas.z;
    if (!(total > 0.0f)) return 0.0f;
    bool seen;
    if (abs(n.y) > 0.5f) {
        seen = n.y > 0.0f ? areas.x > 0.0f : areas.y > 0.0f;
    } else {
        // On the side: within the seen arc, cos(phi_q - phi_p) >= r / rho, i.e. q.p >= r^2 in XZ.
        seen = areas.z > 0.0f && (cylinderInside(radius, height, p) || q.x * p.x + q.z * p.z >= radius * radius);
    }
    return seen ? 1.0f / total : 0.0f;
}

bool sampleCylinderLocal(float radius, float height, vec3 p, vec3 u, OUT(vec3) q, OUT(vec3) n) {
    vec3 areas = cylinderSeenAreas(radius, height, p);
    float total = areas.x + areas.y + areas.z;
    q = vec3(0.0f);
    n = vec3(0.0f, 1.0f, 0.0f);
    if (!(total > 0.0f)) return false;
    float x = u.x * total;
    if (x < areas.x + areas.y) {
        bool top = x < areas.x;
        sampleDiskLocal(radius, vec2(u.y, u.z), q, n);
        q.y = top ? 0.5f * height : -0.5f * height;
        n = vec3(0.0f, top ? 1.0f : -1.0f, 0.0f);
        return true;
    }
    float halfArc = cylinderSeenHalfArc(radius, p, cylinderInside(radius, height, p));
    float phi = atan(p.z, p.x) + (2.0f * u.y - 1.0f) * halfArc;
    n = vec3(cos(phi), 0.0f, sin(phi));
    q = vec3(radius * n.x, (u.z - 0.5f) * height, radius * n.z);
    return true;
}

// ---- Any shape ----

// Density per unit local area with which p (local) samples the point q (local, outward normal n).
float shapeLocalDensity(ShapeEmitter e, vec3 p, vec3 q, vec3 n) {
    if (e.kind == EMITTER_SPHERE) return sphereLocalDensity(e.radius, p, q, n);
    if (e.kind == EMITTER_QUAD) return quadLocalDensity(e.size, p, q);
    if (e.kind == EMITTER_DISK) return diskLocalDensity(e.radius);
    if (e.kind == EMITTER_BOX) return boxLocalDensity(e.size, p, n);
    if (e.kind == EMITTER_CYLINDER) return cylinderLocalDensity(e.radius, e.height, p, q, n);
    return 0.0f;
}

// Solid-angle pdf at world point p of a world point q with local normal nLocal, from the local
// density; also the world normal.
float shapeWorldPdf(ShapeEmitter e, float localDensity, vec3 p, vec3 q, vec3 nLocal, OUT(vec3) nWorld) {
    vec3 m = rowsTransposeTimes(e.local0, e.local1, e.local2, nLocal); // L^T n: |m| |det M| = area ratio
    float lm = length(m);
    nWorld = m / lm;
    vec3 toQ = q - p;
    float d2 = dot(toQ, toQ);
    float cosAt = abs(dot(nWorld, toQ)) * inversesqrt(d2);
    if (!(cosAt > 0.0f) || !(lm > 0.0f)) return 0.0f;
    return localDensity * d2 / (cosAt * e.absDet * lm);
}

// A point of the shape sampled from world point p with the 3D number u (u.x picks a box's face or a
// cylinder's part, (u.y, u.z) the point). False: p sees nothing of the shape to sample.
bool sampleShapeEmitter(ShapeEmitter e, vec3 p, vec3 u, OUT(ShapePoint) s) {
    s = ShapePoint(vec3(0.0f), vec3(0.0f, 1.0f, 0.0f), 0.0f);
    vec3 pLocal = rowsTimesPoint(e.local0, e.local1, e.local2, p);
    vec3 q = vec3(0.0f);
    vec3 n = vec3(0.0f, 1.0f, 0.0f);
    vec2 uv = vec2(u.y, u.z);
    if (e.kind == EMITTER_SPHERE) {
        sampleSphereLocal(e.radius, pLocal, uv, q, n);
    } else if (e.kind == EMITTER_QUAD) {
        if (pLocal.y == 0.0f) return false; // edge-on
        sampleQuadLocal(e.size, pLocal, uv, q, n);
    } else if (e.kind == EMITTER_DISK) {
        if (pLocal.y == 0.0f) return false;
        sampleDiskLocal(e.radius, uv, q, n);
    } else if (e.kind == EMITTER_BOX) {
        if (!sampleBoxLocal(e.size, pLocal, u, q, n)) return false;
    } else if (e.kind == EMITTER_CYLINDER) {
        if (!sampleCylinderLocal(e.radius, e.height, pLocal, u, q, n)) return false;
    } else {
        return false;
    }
    float density = shapeLocalDensity(e, pLocal, q, n);
    vec3 qWorld = rowsTimesPoint(e.world0, e.world1, e.world2, q);
    vec3 nWorld;
    float pdf = shapeWorldPdf(e, density, p, qWorld, n, nWorld);
    if (!(pdf > 0.0f) || !isFiniteFloat(pdf)) return false;
    s = ShapePoint(qWorld, nWorld, pdf);
    return true;
}

// The solid-angle pdf with which sampleShapeEmitter, from world point p, gives the world point q of
// the shape, whose outward world normal is nWorld (a BSDF-sampled ray's hit).
float shapeEmitterPdf(ShapeEmitter e, vec3 p, vec3 q, vec3 nWorld) {
    vec3 pLocal = rowsTimesPoint(e.local0, e.local1, e.local2, p);
    vec3 qLocal = rowsTimesPoint(e.local0, e.local1, e.local2, q);
    vec3 nLocal = normalize(rowsTransposeTimes(e.world0, e.world1, e.world2, nWorld)); // M^T n
    if ((e.kind == EMITTER_QUAD || e.kind == EMITTER_DISK) && pLocal.y == 0.0f) return 0.0f;
    vec3 unused;
    return shapeWorldPdf(e, shapeLocalDensity(e, pLocal, qLocal, nLocal), p, q, nLocal, unused);
}
