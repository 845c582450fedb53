#pragma once
// Whether anything can light a scene: a light, a visible emissive surface, or an environment
// that is not black. Without one the image is black, which the command line and the editor say,
// since most glTF assets carry no lights and the project's environment is black by default
// (docs/UNITS.md); so do they where only emissive textures give light.
#include "scene/core/scene.h"

namespace glint {

// What lights a scene, from nothing to enough to see it by.
enum class SceneLighting {
    None,                 // the image is black
    EmissiveTexturesOnly, // only emission through textures at glTF's default strength: glowing
                          // details such as a helmet's lamps or a label, which leave most of the
                          // image dark (many glTF assets are made to be seen under an environment)
    Lit,                  // a light, an emissive surface without a texture (or one whose strength
                          // is raised above 1), or an environment that is not black
};

bool environmentEmits(const Environment& environment);
SceneLighting sceneLighting(const Scene& scene);

} // namespace glint
