// Paired portals (scene/core/portal.h; the HAS_PORTALS variant). A path that reaches a linked
// portal quad, from either side, continues out of its partner under the pair's map: the exit's
// worldFromLocal x half a turn about local Z x the entry's localFromWorld. Crossing is no bounce
// and draws no random number, so a view through a portal is the view from the mapped camera.
// Shadow rays stop at portals (they are shapes): light comes through a portal only along paths the
// BSDF sampled, which therefore take it with weight 1 (no light sample could have found it).

// The partner's shape index when `hit` is on a linked portal, else -1 (packed_scene.cpp linkPortals).
int portalExit(Hit hit) {
    if (hit.material < 0 || hit.onMesh || hit.triangle.y < 0) return -1;
    return int(shapeTexel(hit.triangle.y, 5).z) - 1;
}

vec3 portalToLocal(int shape, vec4 p) {
    return vec3(dot(shapeTexel(shape, 1), p), dot(shapeTexel(shape, 2), p), dot(shapeTexel(shape, 3), p));
}

vec3 portalToWorld(int shape, vec4 p) {
    return vec3(dot(shapeTexel(shape, 6), p), dot(shapeTexel(shape, 7), p), dot(shapeTexel(shape, 8), p));
}

// A world direction entering `entry` as it leaves `exit` (not normalized: the map may scale).
vec3 throughPortalDirection(int entry, int exit, vec3 direction) {
    vec3 local = portalToLocal(entry, vec4(direction, 0.0));
    return portalToWorld(exit, vec4(-local.x, -local.y, local.z, 0.0));
}

// The ray that continues `ray` beyond the portal it reached at distance t. It starts on the exit
// quad's plane (local y = 0 exactly), just off it on the side it leaves through.
Ray throughPortal(Ray ray, float t, int entry, int exit) {
    vec3 local = portalToLocal(entry, vec4(ray.origin + t * ray.direction, 1.0));
    vec3 position = portalToWorld(exit, vec4(-local.x, 0.0, local.z, 1.0));
    vec3 direction = normalize(throughPortalDirection(entry, exit, ray.direction));
    vec3 exitNormal = normalize(shapeTexel(exit, 2).xyz); // local +Y: normals map by localFromWorld's transpose
    return spawnRay(position, exitNormal, direction);
}
