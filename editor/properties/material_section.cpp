// The material editor: every glTF material feature Glint renders, colour pickers, sliders and
// texture slots with thumbnails.
#include "sections.h"

#include "property_edits.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QSignalBlocker>

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

// A texture slot: a thumbnail and a list of the scene's textures (or none).
void addTextureSlot(PropertyForm* form, const MaterialBinding& m, const QString& label, RefMember member) {
    auto* slot = new QWidget(form);
    auto* preview = new QLabel(slot);
    preview->setFixedSize(48, 48);
    preview->setFrameShape(QFrame::Box);
    preview->setAccessibleName(PropertyForm::tr("%1 thumbnail").arg(label));
    auto* choice = new QComboBox(slot);
    auto* layout = new QHBoxLayout(slot);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(preview);
    layout->addWidget(choice, 1);
    QObject::connect(choice, &QComboBox::activated, slot, [m, member, choice](int index) {
        const TextureId id{choice->itemData(index).toUInt()};
        m.edit([&](Material& mat) { (mat.*member).texture = id; }, 0);
    });
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
    addTextureSlot(form, m, PropertyForm::tr("Base colour texture"), &Material::baseColorTexture);
    addFloat(form, m, PropertyForm::tr("Metallic"), 0.0, 1.0, &Material::metallicFactor);
    addFloat(form, m, PropertyForm::tr("Roughness"), 0.0, 1.0, &Material::roughnessFactor);
    addTextureSlot(form, m, PropertyForm::tr("Metallic-roughness texture"), &Material::metallicRoughnessTexture);
    addTextureSlot(form, m, PropertyForm::tr("Normal texture"), &Material::normalTexture);
    addTextureSlot(form, m, PropertyForm::tr("Occlusion texture"), &Material::occlusionTexture);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Emission"), &Material::emissiveFactor);
    addFloat(form, m, PropertyForm::tr("Emission strength"), 0.0, 100.0, &Material::emissiveStrength);
    addTextureSlot(form, m, PropertyForm::tr("Emission texture"), &Material::emissiveTexture);
    addFloat(form, m, PropertyForm::tr("Specular"), 0.0, 1.0, &Material::specularFactor);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Specular colour"), &Material::specularColorFactor);
    addTextureSlot(form, m, PropertyForm::tr("Specular texture"), &Material::specularTexture);
    addTextureSlot(form, m, PropertyForm::tr("Specular colour texture"), &Material::specularColorTexture);
    addFloat(form, m, PropertyForm::tr("Transmission"), 0.0, 1.0, &Material::transmissionFactor);
    addTextureSlot(form, m, PropertyForm::tr("Transmission texture"), &Material::transmissionTexture);
    addFloat(form, m, PropertyForm::tr("Index of refraction"), 1.0, 3.0, &Material::ior);
    addFloat(form, m, PropertyForm::tr("Thickness"), 0.0, 10.0, &Material::thicknessFactor);
    addTextureSlot(form, m, PropertyForm::tr("Thickness texture"), &Material::thicknessTexture);
    addFloat(form, m, PropertyForm::tr("Attenuation distance (m)"), 0.01, 100.0, &Material::attenuationDistance);
    addColor<glm::vec3>(form, m, PropertyForm::tr("Attenuation colour"), &Material::attenuationColor);
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
