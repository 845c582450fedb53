// Triangle meshes through the two-level BVH; compiled only when the scene has meshes.
#ifdef HAS_MESHES
#error "mesh traversal is not wired into the path tracer yet"
#endif
