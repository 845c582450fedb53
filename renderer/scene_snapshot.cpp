#include "renderer/scene_snapshot.h"

#include "scene/anim/scene_at_time.h"

namespace glint::renderer {

SceneSnapshot snapshotOf(Scene document, double seconds) {
    SceneSnapshot snapshot;
    snapshot.document = std::make_shared<const Scene>(std::move(document));
    return retimed(std::move(snapshot), seconds);
}

SceneSnapshot retimed(SceneSnapshot snapshot, double seconds) {
    snapshot.time = seconds;
    Scene storage;
    const Scene& posed = glint::posedAt(*snapshot.document, seconds, storage); // the scene's one posing function
    snapshot.posed = &posed == snapshot.document.get() ? snapshot.document : std::make_shared<const Scene>(std::move(storage));
    return snapshot;
}

} // namespace glint::renderer
