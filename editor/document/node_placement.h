#pragma once
// Where a node added from the menus goes, and how big and bright it is: a new user should see it
// at once in a scene of any size. Shapes land at the view's focus (its orbit centre), resting on the
// surface below it if there is one (spheres, boxes, cylinders), a quarter of the size of what is
// looked at, rounded to 1, 2 or 5 x 10^k metres, with a material of their own;
// point and spot lights hang above the focus (below the first surface over it, so not inside a
// room's ceiling) with the irradiance at the focus that Blender's new 1000 W light gives in its
// default scene; a new sun is Blender's (1 W/m^2) and shines down at an angle; a new area light
// (a 1 m square or disk, or a 0.1 m sphere, scaled as shapes are) hangs there facing down with the
// power in watts that gives the focus that same irradiance. Pure data, no Qt.
#include "scene/core/components.h"
#include "scene/core/transform.h"

#include <glm/glm.hpp>


namespace glint::editor {

struct ViewFocus {
    glm::dvec3 point{0.0};  // the view's orbit centre, world space
    double scale = 1.0;     // metres: the size of what is looked at (the scene, else the view's distance)
    double headroom = 1e30; // from `point` straight up to the first surface over it, metres
    double floor = 1e30;    // distance straight down from `point` to the first surface (1e30: none)
    // How far above `point` the free space starts: past the tops of objects around the focus itself
    // (a sphere just added there must not swallow the light added next); 0 when it is clear.
    double clearFrom = 0.0;
};

struct Placement {
    Transform worldFromNode; // for a node at the root; the caller makes it local to its parent
    Component component;
};

// `unit`: the component as the menu offers it (defaultShape, defaultLight: sized for 1 m).
Placement placeNewNode(const Component& unit, const ViewFocus& focus);

// A new portal pair: two square quads standing upright side by side across the focus, both facing
// +Z, each as large as a new quad (its 2 m edge scaled as shapes are), half an edge apart, their
// lower edges on the surface below the focus if there is one. Walking into one's front comes out
// of the other's front (portal.h).
struct PortalPairPlacement {
    Transform a, b; // world
    float edge = 2.0f;
};
PortalPairPlacement placePortalPair(const ViewFocus& focus);

// 1, 2 or 5 x 10^k nearest below `metres` (> 0), so sizes read as round numbers.
double roundSize(double metres);

// The candela of a point or spot light at `distance` metres from what it lights, and the lux of a
// sun, as Blender's new lights give after its glTF importer (1000 W; 1 W/m^2).
float newPointCandela(double distance);
inline constexpr float kNewSunLux = 683.0f;

// The irradiance (W/m^2) a new point light gives the focus: Blender's 1000 W light at 7.24 m.
double newLightIrradiance();
// The power (watts) of an area light (its shape and size as set) that gives a point `distance`
// metres straight below it (from its plane, or a sphere's centre) newLightIrradiance().
float newAreaLightWatts(const Light& light, double distance);

} // namespace glint::editor
