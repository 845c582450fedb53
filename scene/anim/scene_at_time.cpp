#include "scene/anim/scene_at_time.h"

#include "scene/anim/camera_path_sampling.h"
#include "scene/anim/node_animation.h"

namespace glint {

namespace {

void placeOnPath(Scene& scene, NodeId id, double t) {
    Camera camera = *scene.at(id).get<Camera>();
    const CameraKey key = sampleCameraPath(camera.path, t);
    const NodeId parent = scene.at(id).parent;
    const glm::mat4 worldFromParent = parent ? scene.worldFromNode(parent) : glm::mat4(1.0f);
    Transform worldPose;
    worldPose.translation = glm::vec3(key.position);
    worldPose.rotation = glm::quat(key.orientation);
    scene.setLocal(id, fromMatrix(glm::inverse(worldFromParent) * toMatrix(worldPose)));
    camera.yfov = key.yfov;
    camera.focusDistance = key.focusDistance;
    camera.lensRadius = key.lensRadius;
    scene.setComponent(id, camera);
}

} // namespace

void poseSceneAt(Scene& scene, double t) {
    for (const auto& [id, local] : sampleAnimatedTransforms(scene, t)) scene.setLocal(id, local);
    // After the node animations, so a path camera under an animated parent still lands on its path.
    for (NodeId id : scene.depthFirst()) {
        const Camera* camera = scene.at(id).get<Camera>();
        if (camera && !camera->path.empty()) placeOnPath(scene, id, t);
    }
}

Scene sceneAt(const Scene& scene, double t) {
    Scene posed = scene;
    poseSceneAt(posed, t);
    return posed;
}

bool sceneAnimates(const Scene& scene) {
    const auto [start, end] = sceneAnimationTimeSpan(scene);
    return end > start || !scene.animations.empty();
}

const Scene& posedAt(const Scene& scene, double t, Scene& storage) {
    if (!sceneAnimates(scene)) return scene;
    storage = sceneAt(scene, t);
    return storage;
}

} // namespace glint
