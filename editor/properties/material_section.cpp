// The material editor: every glTF material feature Glint renders, colour pickers, sliders and
// texture slots with thumbnails.
#include "sections.h"

#include "property_edits.h"

#include "editor/materials/material_operations.h"
#include "editor/preferences/retranslate.h"
#include "scene/history/asset_commands.h"

#include <QComboBox>
#include <QFileDialog>
#include <QToolButton>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QSignalBlocker>

#include <algorithm>

namespace glint::editor {
namespace {

using FloatMember = float Material::*;
using RefMember = TextureRef Material::*;

struct MaterialBinding {
    Document& document;
    MaterialId id;
    Report report;

    const Material* get() const { return document.scene().materials.find(id); }
    void edit(const std::function<void(Material&)>& change, std::uint64_t interaction) const {
        const QString error = editMaterial(document, id, change, interaction);
        if (!error.isEmpty()) report(error);
    }
};

void addFloat(PropertyForm* form, const MaterialBinding& m, const QString& label, double min, double max, FloatMember member) {
    form->addFloat(
        label, min, max, 3, [m, member] { return m.get() ? double(m.get()->*member) : 0.0; },
        [m, member](double v, std::uint64_t i) { m.edit([&](Material& mat) { mat.*member = float(v); }, i); });
}

// GLINT_materials_volume_scatter's g, held to the range the glTF reader accepts (typing may go
// past the slider's), so a saved material reads back without a clamp.
constexpr double kMaxScatterAnisotropy = 0.99;

void addScatterAnisotropy(PropertyForm* form, const MaterialBinding& m) {
    form->addFloat(
        PropertyForm::tr("Scatter anisotropy"), -kMaxScatterAnisotropy, kMaxScatterAnisotropy, 2,
        [m] { return m.get() ? double(m.get()->scatterAnisotropy) : 0.0; },
        [m](double v, std::uint64_t i) {
            m.edit([&](Material& mat) { mat.scatterAnisotropy = float(std::clamp(v, -kMaxScatterAnisotropy, kMaxScatterAnisotropy)); }, i);
        });
}

template <class Vec>
void addColor(PropertyForm* form, const MaterialBinding& m, const QString& label, Vec Material::*member) {
    form->addColor(
        label,
        [m, member] {
            const Material* mat = m.get();
            return mat ? toQColor((mat->*member).x, (mat->*member).y, (mat->*member).z) : QColor();
        },
        [m, member](const QColor& c) {
            const glm::vec3 linear = toLinear(c);
            m.edit(
                [&](Material& mat) {
                    (mat.*member).x = linear.x;
                    (mat.*member).y = linear.y;
                    (mat.*member).z = linear.z;
                },
                0);
        });
}

// A 48 px preview of the texture's image, decoded from the bytes the file holds.
QPixmap thumbnail(const Scene& scene, TextureId texture) {
    const Texture* t = scene.textures.find(texture);
    const Image* image = t ? scene.images.find(t->image) : nullptr;
    if (!image || image->encoded.empty()) return {};
    QImage decoded;
    decoded.loadFromData(image->encoded.data(), static_cast<int>(image->encoded.size()));
    if (decoded.isNull()) return {};
    return QPixmap::fromImage(decoded.scaled(48, 48, Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

QString textureName(const Scene& scene, TextureId id, const Texture& texture) {
    if (!texture.name.empty()) return QString::fromStdString(texture.name);
    const Image* image = scene.images.find(texture.image);
    if (image && !image->name.empty()) return QString::fromStdString(image->name);
    if (image && !image->uri.empty()) return QString::fromStdString(image->uri);
    return PropertyForm::tr("Texture %1").arg(id.value);
}

// The texture a slot of the material reads, or null.
const Texture* slotTexture(const MaterialBinding& m, RefMember member) {
    const Material* mat = m.get();
    return mat ? m.document.scene().textures.find((mat->*member).texture) : nullptr;
}

// Edits the sampler of the slot's texture; a texture without one gets its own first (one step).
void editSampler(const MaterialBinding& m, RefMember member, const std::function<void(Sampler&)>& change) {
    const Material* mat = m.get();
    if (!mat) return;
    const TextureId textureId = (mat->*member).texture;
    const Texture* texture = m.document.scene().textures.find(textureId);
    if (!texture) return;
    try {
        if (const Sampler* sampler = m.document.scene().samplers.find(texture->sampler)) {
            Sampler changed = *sampler;
            change(changed);
            if (!(changed == *sampler)) m.document.push(std::make_unique<SetAsset<Sampler>>(texture->sampler, std::move(changed)));
            return;
        }
        Sampler fresh;
        change(fresh);
        m.document.beginMacro(PropertyForm::tr("Edit sampler"));
        auto add = std::make_unique<AddAsset<Sampler>>(std::move(fresh));
        AddAsset<Sampler>* raw = add.get();
        try {
            m.document.push(std::move(add));
            Texture withSampler = *m.document.scene().textures.find(textureId);
            withSampler.sampler = raw->id();
            m.document.push(std::make_unique<SetAsset<Texture>>(textureId, std::move(withSampler)));
        } catch (...) {
            m.document.endMacro();
            throw;
        }
        m.document.endMacro();
    } catch (const std::exception& e) {
        m.report(QString::fromStdString(e.what()));
    }
}

// Asks for an image file (not modal to the event loop: tests answer the dialog) and loads it.
void chooseTextureFile(QWidget* parent, const MaterialBinding& m, const TextureSlot& slot) {
    auto* dialog = new QFileDialog(parent, PropertyForm::tr("Load texture"));
    dialog->setObjectName("materials.textureFileDialog");
    dialog->setFileMode(QFileDialog::ExistingFile);
    dialog->setNameFilter(PropertyForm::tr("Images (*.png *.jpg *.jpeg *.exr *.hdr *.tif *.tiff)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QFileDialog::fileSelected, parent, [m, &slot](const QString& file) {
        const QString error = loadTextureFile(m.document, m.id, slot, file);
        if (!error.isEmpty()) m.report(error);
    });
    dialog->open();
}

// A texture slot: a thumbnail, a list of the scene's textures (or none) and Load to read a file;
// with a texture, its UV set, sampler and KHR_texture_transform.
void addTextureSlot(PropertyForm* form, const MaterialBinding& m, const TextureSlot& textureSlot) {
    const QString label = PropertyForm::tr(textureSlot.title);
    const RefMember member = textureSlot.member;
    auto* slot = new QWidget(form);
    auto* preview = new QLabel(slot);
    preview->setFixedSize(48, 48);
    preview->setFrameShape(QFrame::Box);
    preview->setAccessibleName(PropertyForm::tr("%1 thumbnail").arg(label));
    auto* choice = newFormComboBox(slot);
    auto* load = new QToolButton(slot);
    load->setText(PropertyForm::tr("Load…"));
    load->setObjectName(QStringLiteral("texture.load.%1").arg(QLatin1String(textureSlot.id)));
    load->setToolTip(PropertyForm::tr("Load an image file (PNG, JPEG, EXR, HDR, TIFF) into this slot"));
    load->setAccessibleName(PropertyForm::tr("Load %1").arg(label));
    auto* layout = new QHBoxLayout(slot);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(preview);
    layout->addWidget(choice, 1);
    layout->addWidget(load);
    QObject::connect(choice, &QComboBox::activated, slot, [m, member, choice](int index) {
        const TextureId id{choice->itemData(index).toUInt()};
        m.edit([&](Material& mat) { (mat.*member).texture = id; }, 0);
    });
    QObject::connect(load, &QToolButton::clicked, slot, [slot, m, &textureSlot] { chooseTextureFile(slot, m, textureSlot); });
    form->addWidget(label, slot, [m, member, choice, preview] {
        const Scene& scene = m.document.scene();
        const Material* mat = m.get();
        const TextureId current = mat ? (mat->*member).texture : TextureId{};
        QSignalBlocker block(choice);
        choice->clear();
        choice->addItem(PropertyForm::tr("(none)"), 0u);
        for (const auto& [id, texture] : scene.textures) choice->addItem(textureName(scene, id, texture), id.value);
        choice->setCurrentIndex(std::max(0, choice->findData(current.value)));
        preview->setPixmap(thumbnail(scene, current));
    });
    if (!slotTexture(m, member)) return; // the panel is rebuilt when a slot gains a texture
    const QString indent = QStringLiteral("    ");
    form->addChoice(
        indent + PropertyForm::tr("UV set"), {QStringLiteral("TEXCOORD_0"), QStringLiteral("TEXCOORD_1")},
        [m, member] { return m.get() ? std::clamp((m.get()->*member).texCoord, 0, 1) : 0; },
        [m, member](int i) { m.edit([&](Material& mat) { (mat.*member).texCoord = i; }, 0); });
    const QStringList wraps{PropertyForm::tr("Repeat"), PropertyForm::tr("Clamp to edge"), PropertyForm::tr("Mirrored repeat")};
    const Wrap wrapValues[] = {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat};
    auto wrapIndex = [wrapValues](Wrap w) {
        for (int i = 0; i < 3; ++i)
            if (wrapValues[i] == w) return i;
        return 0;
    };
    auto sampler = [m, member]() -> Sampler {
        const Texture* t = slotTexture(m, member);
        const Sampler* s = t ? m.document.scene().samplers.find(t->sampler) : nullptr;
        return s ? *s : Sampler{};
    };
    form->addChoice(indent + PropertyForm::tr("Wrap U"), wraps, [sampler, wrapIndex] { return wrapIndex(sampler().wrapS); },
                    [m, member, wrapValues](int i) { editSampler(m, member, [&](Sampler& s) { s.wrapS = wrapValues[i]; }); });
    form->addChoice(indent + PropertyForm::tr("Wrap V"), wraps, [sampler, wrapIndex] { return wrapIndex(sampler().wrapT); },
                    [m, member, wrapValues](int i) { editSampler(m, member, [&](Sampler& s) { s.wrapT = wrapValues[i]; }); });
    form->addChoice(
        indent + PropertyForm::tr("Filter"), {PropertyForm::tr("Linear"), PropertyForm::tr("Nearest")},
        [sampler] { return sampler().magFilter == Filter::Nearest ? 1 : 0; },
        [m, member](int i) {
            editSampler(m, member, [&](Sampler& s) {
                s.magFilter = i == 1 ? Filter::Nearest : Filter::Linear;
                s.minFilter = i == 1 ? Filter::NearestMipmapNearest : Filter::LinearMipmapLinear;
            });
        });
    auto transformFloat = [&](const QString& name, double min, double max, double scale, auto access) {
        form->addFloat(
            indent + name, min, max, 3, [m, member, access, scale] {
                if (!m.get()) return 0.0;
                TextureTransform t = (m.get()->*member).transform;
                return double(access(t)) * scale;
            },
            [m, member, access, scale](double v, std::uint64_t i) {
                m.edit([&](Material& mat) { access((mat.*member).transform) = float(v / scale); }, i);
            });
    };
    transformFloat(PropertyForm::tr("Offset U"), -10.0, 10.0, 1.0, [](TextureTransform& t) -> float& { return t.offset.x; });
    transformFloat(PropertyForm::tr("Offset V"), -10.0, 10.0, 1.0, [](TextureTransform& t) -> float& { return t.offset.y; });
    transformFloat(PropertyForm::tr("Rotation (degrees)"), -180.0, 180.0, 180.0 / 3.14159265358979323846,
                   [](TextureTransform& t) -> float& { return t.rotation; });
    transformFloat(PropertyForm::tr("Scale U"), 0.01, 100.0, 1.0, [](TextureTransform& t) -> float& { return t.scale.x; });
    transformFloat(PropertyForm::tr("Scale V"), 0.01, 100.0, 1.0, [](TextureTransform& t) -> float& { return t.scale.y; });
}

const TextureSlot& slotOf(RefMember member) {
    for (const TextureSlot& slot : textureSlots())
        if (slot.member == member) return slot;
    return textureSlots().front();
}

} // namespace

PropertyForm* makeMaterialForm(Document& document, MaterialId material, const Report& report, QWidget* parent) {
    const Material* mat = document.scene().materials.find(material);
    const QString name = mat && !mat->name.empty() ? QString::fromStdString(mat->name) : PropertyForm::tr("unnamed");
    auto* form = new PropertyForm(document, PropertyForm::tr("Material: %1").arg(name), parent);
    const MaterialBinding m{document, material, report};

    addColor<glm::vec4>(form, m, PropertyForm::tr("Base colour"), &Material::baseColorFactor);
    form->addFloat(
        PropertyForm::tr("Opacity"), 0.0, 1.0, 3, [m] { return m.get() ? double(m.get()->baseColorFactor.w) : 1.0; },
        [m](double v, std::uint64_t i) { m.edit([&](Material& mat) { mat.baseColorFactor.w = float(v); }, i); });
    addTextureSlot(form, m, slotOf(&Material::baseColorTexture));
    addFloat(form, m, PropertyForm::tr("Metallic"), 0.0, 1.0, &Material::metallicFactor);
    addFloat(form, m, PropertyForm::tr("Roughness"), 0.0, 1.0, &Material::roughnessFactor);
    addTextureSlot(form, m, slotOf(&Material::metallicRoughnessTexture));
    addTextureSlot(form, m, slotOf(&Material::normalTexture));
    addTextureSlot(form, m, slotOf(&Material::occlusionTexture));
    addColor<glm::vec3>(form, m, PropertyForm::tr("Emission"), &Material::emissiveFactor);
    addFloat(form, m, PropertyForm::tr("Emission strength"), 0.0, 100.0, &Material::emissiveStrength);
    addTextureSlot(form, m, slotOf(&Material::emissiveTexture));
    addFloat(form, m, PropertyForm::tr("Specular"), 0.0, 1.0, &Material::specularFactor);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Specular colour"), &Material::specularColorFactor);
    addTextureSlot(form, m, slotOf(&Material::specularTexture));
    addTextureSlot(form, m, slotOf(&Material::specularColorTexture));
    addFloat(form, m, PropertyForm::tr("Transmission"), 0.0, 1.0, &Material::transmissionFactor);
    addTextureSlot(form, m, slotOf(&Material::transmissionTexture));
    addFloat(form, m, PropertyForm::tr("Index of refraction"), 1.0, 3.0, &Material::ior);
    addFloat(form, m, PropertyForm::tr("Thickness"), 0.0, 10.0, &Material::thicknessFactor);
    addTextureSlot(form, m, slotOf(&Material::thicknessTexture));
    addFloat(form, m, PropertyForm::tr("Attenuation distance (m)"), 0.01, 100.0, &Material::attenuationDistance);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Attenuation colour"), &Material::attenuationColor);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Scatter colour"), &Material::scatterColor);
    addScatterAnisotropy(form, m);
    form->addChoice(
        PropertyForm::tr("Alpha mode"), {PropertyForm::tr("Opaque"), PropertyForm::tr("Mask"), PropertyForm::tr("Blend")},
        [m] { return m.get() ? static_cast<int>(m.get()->alphaMode) : 0; },
        [m](int i) { m.edit([&](Material& mat) { mat.alphaMode = static_cast<AlphaMode>(i); }, 0); });
    addFloat(form, m, PropertyForm::tr("Alpha cutoff"), 0.0, 1.0, &Material::alphaCutoff);
    form->addCheck(
        PropertyForm::tr("Double sided"), [m] { return m.get() && m.get()->doubleSided; },
        [m](bool on) { m.edit([&](Material& mat) { mat.doubleSided = on; }, 0); });
    return form;
}

} // namespace glint::editor

namespace glint::editor {

std::uint32_t texturedSlots(const Scene& scene, MaterialId material) {
    const Material* m = scene.materials.find(material);
    std::uint32_t mask = 0;
    if (!m) return mask;
    int bit = 0;
    for (const TextureSlot& slot : textureSlots()) {
        if (scene.textures.contains((m->*slot.member).texture)) mask |= 1u << bit;
        ++bit;
    }
    return mask;
}

MaterialId nodeMaterial(const Scene& scene, NodeId node, std::size_t primitive) {
    const Node* n = scene.node(node);
    if (!n) return {};
    if (const auto* shape = n->get<Shape>()) return shape->material;
    if (const auto* instance = n->get<MeshInstance>()) {
        const Mesh* mesh = scene.meshes.find(instance->mesh);
        if (mesh && !mesh->primitives.empty()) return mesh->primitives[std::min(primitive, mesh->primitives.size() - 1)].material;
    }
    return {};
}

PropertyForm* makeMaterialSlotsForm(Document& document, NodeId node, std::size_t shownPrimitive,
                                    const std::function<void(std::size_t)>& showPrimitive, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Materials"), parent);
    const Node* n = document.scene().node(node);
    const auto* instance = n ? n->get<MeshInstance>() : nullptr;
    const Mesh* mesh = instance ? document.scene().meshes.find(instance->mesh) : nullptr;
    const MeshId meshId = instance ? instance->mesh : MeshId{};
    const std::size_t count = mesh ? mesh->primitives.size() : 1;
    // Each row: the material of the shape, or of one primitive of the mesh; Edit shows it below.
    for (std::size_t p = 0; p < count; ++p) {
        auto* row = new QWidget(form);
        auto* choice = newFormComboBox(row);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(choice, 1);
        if (mesh && count > 1) {
            auto* edit = new QToolButton(row);
            edit->setText(PropertyForm::tr("Edit"));
            edit->setCheckable(true);
            edit->setChecked(p == shownPrimitive);
            edit->setObjectName(QStringLiteral("primitive.edit.%1").arg(p));
            edit->setToolTip(PropertyForm::tr("Show this primitive's material below"));
            QObject::connect(edit, &QToolButton::clicked, row, [showPrimitive, p] { showPrimitive(p); });
            layout->addWidget(edit);
        }
        QObject::connect(choice, &QComboBox::activated, row, [&document, node, meshId, p, choice, report](int index) {
            const MaterialId material{choice->itemData(index).toUInt()};
            const QString error = meshId ? assignPrimitiveMaterial(document, meshId, p, material)
                                         : assignMaterial(document, material, {node});
            if (!error.isEmpty()) report(error);
        });
        const QString label = mesh ? countText("glint::editor::PropertyForm",
                                               QT_TRANSLATE_N_NOOP("glint::editor::PropertyForm", "Primitive %1 (%n triangles)"),
                                               "Primitive %1 (%n triangle)", int(mesh->primitives[p].triangleCount()))
                                         .arg(p + 1)
                                   : PropertyForm::tr("Material");
        form->addWidget(label, row, [&document, node, p, choice] {
            const Scene& scene = document.scene();
            const MaterialId current = nodeMaterial(scene, node, p);
            QSignalBlocker block(choice);
            choice->clear();
            choice->addItem(PropertyForm::tr("(default)"), 0u);
            for (const auto& [id, material] : scene.materials)
                choice->addItem(material.name.empty() ? PropertyForm::tr("Material %1").arg(id.value) : QString::fromStdString(material.name), id.value);
            choice->setCurrentIndex(std::max(0, choice->findData(current.value)));
        });
    }
    return form;
}

} // namespace glint::editor
