// Point and spot lights with a radius (GLINT_light) as visible emitters: spheres of uniform radiance
// I / (pi r^2) that camera and BSDF-sampled rays hit and that block shadow rays. Compiled in only for
// scenes that have one (HAS_SPHERE_LAMPS); elsewhere these fold away and rays pass every light.
// Light buffer layout: lights.glsl. Suns are packed with radius 0, so radius > 0 marks a lamp.
#include "sampling/sphere_light.glsl"

float lampRadius(int light) { return lightTexel(light, 0).y; }

// Nearest lamp sphere along the ray within tMax, seen from outside; -1: none.
float closestLamp(vec3 origin, vec3 direction, float tMax, OUT(int) lamp) {
    lamp = -1;
#ifdef HAS_SPHERE_LAMPS
    for (int light = 0; light < uLightCount; ++light) {
        float radius = lampRadius(light);
        if (!(radius > 0.0)) continue;
        float t = hitSphereFromOutside(origin, direction, lightTexel(light, 2).xyz, radius, tMax);
        if (t > 0.0) {
            tMax = t;
            lamp = light;
        }
    }
#endif
    return lamp >= 0 ? tMax : -1.0;
}

bool occludedByLamps(vec3 origin, vec3 direction, float distance) {
    int lamp;
    return closestLamp(origin, direction, distance, lamp) > 0.0;
}
