#pragma once
// Whether anything can light a scene: a light, a visible emissive surface, or an environment
// that is not black. Without one the image is black, which the command line says, since most
// glTF assets carry no lights and the project's environment is black by default
// (docs/UNITS.md).
#include "scene/core/scene.h"

namespace glint {

bool environmentEmits(const Environment& environment);
bool hasLightSource(const Scene& scene); // lights, emissive surfaces and the project's environment

} // namespace glint
