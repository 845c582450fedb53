#pragma once
// What the command line does for a scene that cannot render as stored, before render or bench
// plans anything, each step printed as a warning naming the file (so --strict refuses it):
// - no camera and no --camera: a default view of the whole scene (scene/core/default_view.h), since
//   most downloaded glTF assets have no camera;
// - --camera naming no camera: an error naming the file;
// - nothing that emits light (no light, emitter, --env or project environment): a warning that
//   the image will be black, since glTF assets rarely carry lights and the environment is black.
#include "common_options.h"
#include "scene/io/scene_io.h"

#include <string>

namespace glint::cli {

// `camera`: --camera (empty: none); `envGiven`: --env was passed; `size`: the output image's.
// Adds to `loaded.warnings`; throws FileError for a --camera that names no camera.
void completeForRender(LoadResult& loaded, const std::string& file, const std::string& camera, bool envGiven, Size size);

// The image size a render of `scene` has: --size, else the project's.
Size outputSize(const CommonRenderOptions& options, const Scene& scene);

} // namespace glint::cli
