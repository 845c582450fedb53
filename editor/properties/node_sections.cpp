// Node, transform, shape, light and camera sections.
#include "sections.h"

#include "property_edits.h"

#include "editor/document/edit_operations.h"
#include "editor/document/keyed_transform.h"
#include "editor/outliner/node_names.h"

#include <QLineEdit>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace glint::editor {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

template <class T>
const T* componentOf(const Document& document, NodeId node) {
    const Node* n = document.scene().node(node);
    return n ? n->get<T>() : nullptr;
}

// Reads one float of a component (0 when the node or component is gone, e.g. mid-undo).
template <class T>
std::function<double()> readComponent(const Document& document, NodeId node, std::function<double(const T&)> read) {
    return [&document, node, read] {
        const T* c = componentOf<T>(document, node);
        return c ? read(*c) : 0.0;
    };
}

template <class T>
PropertyForm::FloatSetter writeComponent(Document& document, NodeId node, const Report& report,
                                         std::function<void(T&, double)> write) {
    return [&document, node, report, write](double v, std::uint64_t interaction) {
        const QString error = editComponent(
            document, node,
            [&](Component& c) {
                if (T* t = std::get_if<T>(&c)) write(*t, v);
            },
            interaction);
        if (!error.isEmpty()) report(error);
    };
}

// Adds a float field bound to one member of component T.
template <class T>
void addComponentFloat(PropertyForm* form, Document& document, NodeId node, const Report& report, const QString& label,
                       double min, double max, int decimals, float T::*member, double scale = 1.0) {
    form->addFloat(
        label, min, max, decimals, readComponent<T>(document, node, [member, scale](const T& c) { return c.*member * scale; }),
        writeComponent<T>(document, node, report,
                          [member, scale](T& c, double v) { c.*member = static_cast<float>(v / scale); }));
}

} // namespace

PropertyForm* makeNodeForm(Document& document, NodeId node, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Node"), parent);
    QLineEdit* name = form->addText(
        PropertyForm::tr("Name"),
        [&document, node] {
            const Node* n = document.scene().node(node);
            return n ? QString::fromStdString(n->name) : QString();
        },
        [&document, node, report](const QString& name) {
            if (name.trimmed().isEmpty() && !hasOwnName(document.scene(), node)) return; // stays unnamed
            const QString error = renameNode(document, node, name);
            if (!error.isEmpty()) report(error);
        });
    // A node the file gives no name shows the name the editor derives for it, greyed.
    name->setPlaceholderText(nodeDisplayName(document.scene(), node));
    form->addCheck(
        PropertyForm::tr("Visible"),
        [&document, node] {
            const Node* n = document.scene().node(node);
            return n && n->visible;
        },
        [&document, node, report](bool on) {
            const QString error = setVisible(document, node, on);
            if (!error.isEmpty()) report(error);
        });
    return form;
}

PropertyForm* makeTransformForm(Document& document, NodeId node, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Transform"), parent);
    auto local = [&document, node] { // a keyed node's pose at the current time
        return document.scene().node(node) ? shownTransform(document, node) : Transform{};
    };
    auto edit = [&document, node, report](std::function<void(Transform&)> change, std::uint64_t interaction) {
        const QString error = editTransform(document, node, change, interaction);
        if (!error.isEmpty()) report(error);
    };
    const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        form->addFloat(
            PropertyForm::tr("Position %1").arg(axes[axis]), -10.0, 10.0, 3,
            [local, axis] { return double(local().translation[axis]); },
            [edit, axis](double v, std::uint64_t i) { edit([&](Transform& t) { t.translation[axis] = float(v); }, i); });
    }
    for (int axis = 0; axis < 3; ++axis) {
        form->addFloat(
            PropertyForm::tr("Rotation %1 (degrees)").arg(axes[axis]), -180.0, 180.0, 2,
            [local, axis] { return glm::eulerAngles(local().rotation)[axis] * kDegrees; },
            [edit, axis](double v, std::uint64_t i) {
                edit(
                    [&](Transform& t) {
                        glm::vec3 euler = glm::eulerAngles(t.rotation);
                        euler[axis] = float(v / kDegrees);
                        t.rotation = glm::quat(euler);
                    },
                    i);
            });
    }
    for (int axis = 0; axis < 3; ++axis) {
        form->addFloat(
            PropertyForm::tr("Scale %1").arg(axes[axis]), 0.01, 10.0, 3, [local, axis] { return double(local().scale[axis]); },
            [edit, axis](double v, std::uint64_t i) { edit([&](Transform& t) { t.scale[axis] = float(v); }, i); });
    }
    return form;
}

PropertyForm* makeShapeForm(Document& document, NodeId node, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Shape"), parent);
    form->addChoice(
        PropertyForm::tr("Kind"),
        {PropertyForm::tr("Sphere"), PropertyForm::tr("Quad"), PropertyForm::tr("Disk"), PropertyForm::tr("Box"),
         PropertyForm::tr("Cylinder"), PropertyForm::tr("Ground plane")},
        [&document, node] {
            const Shape* s = componentOf<Shape>(document, node);
            return s ? static_cast<int>(s->kind) : 0;
        },
        [&document, node, report](int i) {
            const QString error = editComponent(
                document, node,
                [i](Component& c) {
                    if (auto* s = std::get_if<Shape>(&c)) s->kind = static_cast<ShapeKind>(i);
                },
                0);
            if (!error.isEmpty()) report(error);
        });
    // Only the fields the kind uses (the panel is rebuilt when the kind changes).
    const Shape* shape = componentOf<Shape>(document, node);
    const ShapeKind kind = shape ? shape->kind : ShapeKind::Sphere;
    const bool round = kind == ShapeKind::Sphere || kind == ShapeKind::Disk || kind == ShapeKind::Cylinder;
    if (round) addComponentFloat<Shape>(form, document, node, report, PropertyForm::tr("Radius (m)"), 0.01, 10.0, 3, &Shape::radius);
    if (kind == ShapeKind::Cylinder)
        addComponentFloat<Shape>(form, document, node, report, PropertyForm::tr("Height (m)"), 0.01, 10.0, 3, &Shape::height);
    const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        // A box has three sizes, a quad two (it lies in its XZ plane).
        if (kind != ShapeKind::Box && !(kind == ShapeKind::Quad && axis != 1)) continue;
        form->addFloat(PropertyForm::tr("Size %1 (m)").arg(axes[axis]), 0.01, 10.0, 3,
                       readComponent<Shape>(document, node, [axis](const Shape& s) { return double(s.size[axis]); }),
                       writeComponent<Shape>(document, node, report,
                                             [axis](Shape& s, double v) { s.size[axis] = float(v); }));
    }
    if (kind == ShapeKind::Quad) addPortalField(form, document, node, report);
    if (kind == ShapeKind::GroundPlane)
        form->addNote(PropertyForm::tr("An infinite plane: the node's y = 0, facing +Y; move and turn it with the transform. "
                                       "It has no size. In the glTF file other programs (Blender) get a 200 m square in "
                                       "its place."));
    return form;
}

namespace {

// An area light's shape, size and power. Power is in watts whatever the project's light-unit mode
// (as Blender gives area lights); the panel is rebuilt when the shape changes.
void addAreaLightFields(PropertyForm* form, Document& document, NodeId node, const Report& report, AreaShape shape) {
    form->addChoice(
        PropertyForm::tr("Shape"), {PropertyForm::tr("Rectangle"), PropertyForm::tr("Disk"), PropertyForm::tr("Sphere")},
        [&document, node] {
            const Light* l = componentOf<Light>(document, node);
            return l ? static_cast<int>(l->areaShape) : 0;
        },
        [&document, node, report](int i) {
            const QString error = editComponent(
                document, node,
                [i](Component& c) {
                    auto* l = std::get_if<Light>(&c);
                    if (!l) return;
                    l->areaShape = static_cast<AreaShape>(i);
                    // A sphere made from a rectangle or disk gets half its width as radius, and back.
                    if (l->areaShape == AreaShape::Sphere && !(l->radius > 0.0f)) l->radius = 0.5f * l->size.x;
                    if (l->areaShape != AreaShape::Sphere && !(l->size.x > 0.0f)) l->size = glm::vec2(2.0f * l->radius);
                },
                0);
            if (!error.isEmpty()) report(error);
        });
    addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Power (W)"), 0.0, 10000.0, 2, &Light::intensity);
    if (shape == AreaShape::Rectangle) {
        for (int axis = 0; axis < 2; ++axis)
            form->addFloat(axis == 0 ? PropertyForm::tr("Size X (m)") : PropertyForm::tr("Size Y (m)"), 0.001, 100.0, 3,
                           readComponent<Light>(document, node, [axis](const Light& l) { return double(l.size[axis]); }),
                           writeComponent<Light>(document, node, report, [axis](Light& l, double v) { l.size[axis] = float(v); }));
    } else if (shape == AreaShape::Disk) {
        form->addFloat(PropertyForm::tr("Diameter (m)"), 0.001, 100.0, 3,
                       readComponent<Light>(document, node, [](const Light& l) { return double(l.size.x); }),
                       writeComponent<Light>(document, node, report, [](Light& l, double v) { l.size = glm::vec2(float(v)); }));
    } else {
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Radius (m)"), 0.001, 50.0, 3, &Light::radius);
    }
    form->addNote(PropertyForm::tr("Emits its power evenly from the front face (the light's -Z) of the rectangle or disk, "
                                   "or the outside of the sphere; in the glTF file other programs get an emissive mesh."));
}

} // namespace

PropertyForm* makeLightForm(Document& document, NodeId node, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Light"), parent);
    const Light* light = componentOf<Light>(document, node);
    const bool sun = light && light->type == LightType::Sun;
    const bool area = light && light->type == LightType::Area;
    form->addChoice(
        PropertyForm::tr("Type"), {PropertyForm::tr("Sun"), PropertyForm::tr("Point"), PropertyForm::tr("Spot"), PropertyForm::tr("Area")},
        [&document, node] {
            const Light* l = componentOf<Light>(document, node);
            return l ? static_cast<int>(l->type) : 0;
        },
        [&document, node, report](int i) {
            const QString error = editComponent(
                document, node,
                [i](Component& c) {
                    auto* l = std::get_if<Light>(&c);
                    if (!l) return;
                    l->type = static_cast<LightType>(i);
                    if (l->type != LightType::Area) return;
                    // An area light has no range, cone or sun disk (GLINT_area_light keeps none):
                    // back to their defaults, so that what is saved is what the document holds.
                    const Light plain;
                    l->range = plain.range;
                    l->innerConeAngle = plain.innerConeAngle;
                    l->outerConeAngle = plain.outerConeAngle;
                    l->angularDiameter = plain.angularDiameter;
                },
                0);
            if (!error.isEmpty()) report(error);
        });
    form->addColor(
        PropertyForm::tr("Colour"),
        [&document, node] {
            const Light* l = componentOf<Light>(document, node);
            return l ? toQColor(l->color.x, l->color.y, l->color.z) : QColor();
        },
        [&document, node, report](const QColor& c) {
            const QString error = editComponent(
                document, node,
                [&](Component& comp) {
                    if (auto* l = std::get_if<Light>(&comp)) l->color = toLinear(c);
                },
                0);
            if (!error.isEmpty()) report(error);
        });
    if (area) {
        addAreaLightFields(form, document, node, report, light->areaShape);
        return form;
    }
    // The file stores photometric units (KHR_lights_punctual); the project's light-unit mode
    // decides how they become radiance, so the label names both.
    const bool blender = document.scene().settings.lightUnits == LightUnits::Blender;
    const QString units = sun ? PropertyForm::tr("lux") : PropertyForm::tr("cd");
    const QString mode = blender ? PropertyForm::tr("Blender units") : PropertyForm::tr("raw units");
    addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Intensity (%1, %2)").arg(units, mode), 0.0,
                             sun ? 20.0 : 1000.0, 3, &Light::intensity);
    // Only the fields the type uses (the panel is rebuilt when the type changes): a sun is
    // directional, with no range or cone, and the others have no angular diameter.
    const bool spot = light && light->type == LightType::Spot;
    if (!sun) {
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Range (m, 0 = infinite)"), 0.0, 100.0, 2,
                                 &Light::range);
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Radius (m)"), 0.0, 2.0, 3, &Light::radius);
    }
    if (spot) {
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Inner cone (degrees)"), 0.0, 90.0, 1,
                                 &Light::innerConeAngle, kDegrees);
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Outer cone (degrees)"), 0.0, 90.0, 1,
                                 &Light::outerConeAngle, kDegrees);
    }
    if (sun)
        addComponentFloat<Light>(form, document, node, report, PropertyForm::tr("Sun angular diameter (degrees)"), 0.0, 10.0,
                                 2, &Light::angularDiameter, kDegrees);
    return form;
}

PropertyForm* makeCameraForm(Document& document, NodeId node, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Camera"), parent);
    form->addChoice(
        PropertyForm::tr("Projection"), {PropertyForm::tr("Perspective"), PropertyForm::tr("Orthographic")},
        [&document, node] {
            const Camera* c = componentOf<Camera>(document, node);
            return c ? static_cast<int>(c->projection) : 0;
        },
        [&document, node, report](int i) {
            const QString error = editComponent(
                document, node,
                [i](Component& c) {
                    if (auto* cam = std::get_if<Camera>(&c)) cam->projection = static_cast<Projection>(i);
                },
                0);
            if (!error.isEmpty()) report(error);
        });
    const Camera* camera = componentOf<Camera>(document, node);
    if (camera && camera->projection == Projection::Orthographic)
        addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Half height (m)"), 0.01, 100.0, 3, &Camera::ymag);
    else
        addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Vertical field of view (degrees)"), 1.0,
                                  170.0, 2, &Camera::yfov, kDegrees);
    addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Lens radius (m)"), 0.0, 0.5, 4,
                              &Camera::lensRadius);
    addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Focus distance (m)"), 0.01, 100.0, 3,
                              &Camera::focusDistance);
    addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Exposure (EV)"), -10.0, 10.0, 2,
                              &Camera::exposure);
    addComponentFloat<Camera>(form, document, node, report, PropertyForm::tr("Near clip (m)"), 0.001, 10.0, 3,
                              &Camera::znear);
    form->addCheck(
        PropertyForm::tr("Active camera"), [&document, node] { return document.scene().settings.activeCamera == node; },
        [&document, node, report](bool on) {
            const QString error = editSettings(
                document, [&](ProjectSettings& s) { s.activeCamera = on ? node : NodeId{}; }, 0);
            if (!error.isEmpty()) report(error);
        });
    return form;
}

} // namespace glint::editor
