#pragma once
// What the renderer draws: the document a host handed over, and that document posed at one time
// (node animations sampled). The editable document stays with its host (the editor's Document, the
// command line's loaded scene); a snapshot is immutable and shared, and cheap to make: copying a
// Scene copies no vertex or image data (scene/core/shared_array.h), and a scene that does not
// animate is its own posed scene. Posing is the scene library's posedAt (scene/anim/scene_at_time.h).
#include "scene/core/scene.h"

#include <memory>

namespace glint::renderer {

struct SceneSnapshot {
    std::shared_ptr<const Scene> document;
    std::shared_ptr<const Scene> posed; // the document itself when nothing animates
    double time = 0.0;
};

SceneSnapshot snapshotOf(Scene document, double seconds);
// The same document at another time.
SceneSnapshot retimed(SceneSnapshot snapshot, double seconds);

} // namespace glint::renderer
