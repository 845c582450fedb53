// Closest-hit and shadow queries over everything in the scene. Mesh traversal is compiled in only
// for scenes that have meshes (HAS_MESHES).
Hit traceClosest(Ray ray) {
    Hit hit = noHit();
    intersectShapes(ray, hit);
#ifdef HAS_MESHES
    intersectMeshes(ray, hit);
#endif
    return hit;
}

bool occluded(Ray ray, float distance) {
    if (occludedByShapes(ray, distance)) return true;
#ifdef HAS_MESHES
    if (occludedByMeshes(ray, distance)) return true;
#endif
    return false;
}
