// Environment and render settings: the project file's sections, edited as one settings command.
#include "sections.h"

#include "property_edits.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QToolButton>

namespace glint::editor {
namespace {

using Edit = std::function<void(const std::function<void(ProjectSettings&)>&, std::uint64_t)>;

Edit settingsEditor(Document& document, const Report& report) {
    return [&document, report](const std::function<void(ProjectSettings&)>& change, std::uint64_t interaction) {
        const QString error = editSettings(document, change, interaction);
        if (!error.isEmpty()) report(error);
    };
}

const QStringList kConfigurations{"baseline", "realistic", "full", "heavy", "accumulate", "reference"};

} // namespace

PropertyForm* makeEnvironmentForm(Document& document, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Environment"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    // The file is stored relative to the project folder (the scene file's folder once saved).
    auto* row = new QWidget(form);
    auto* path = new QLineEdit(row);
    auto* browse = new QToolButton(row);
    browse->setText(PropertyForm::tr("Browse..."));
    browse->setAccessibleName(PropertyForm::tr("Choose an HDR environment file"));
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    rowLayout->addWidget(path, 1);
    rowLayout->addWidget(browse);
    auto setFile = [edit](const QString& file) {
        edit([&](ProjectSettings& s) { s.environment.file = file.toStdString(); }, 0);
    };
    QObject::connect(path, &QLineEdit::editingFinished, row, [path, setFile] { setFile(path->text()); });
    QObject::connect(browse, &QToolButton::clicked, row, [&document, row, setFile] {
        const QString folder = document.filePath().isEmpty() ? QDir::currentPath() : QFileInfo(document.filePath()).absolutePath();
        const QString file = QFileDialog::getOpenFileName(row, PropertyForm::tr("Environment map"), folder,
                                                          PropertyForm::tr("HDR images (*.hdr *.exr);;All files (*)"));
        if (!file.isEmpty()) setFile(QDir(folder).relativeFilePath(file));
    });
    form->addWidget(PropertyForm::tr("HDR file"), row, [&scene, path] {
        if (!path->hasFocus()) path->setText(QString::fromStdString(scene.settings.environment.file));
    });
    form->addColor(
        PropertyForm::tr("Colour (no file)"),
        [&scene] {
            const glm::vec3& c = scene.settings.environment.color;
            return toQColor(c.x, c.y, c.z);
        },
        [edit](const QColor& c) {
            edit([&](ProjectSettings& s) { s.environment.color = {c.redF(), c.greenF(), c.blueF()}; }, 0);
        });
    form->addFloat(
        PropertyForm::tr("Intensity"), 0.0, 10.0, 3, [&scene] { return double(scene.settings.environment.intensity); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.environment.intensity = float(v); }, i); });
    form->addFloat(
        PropertyForm::tr("Rotation (degrees)"), -180.0, 180.0, 1,
        [&scene] { return double(scene.settings.environment.rotationDegrees); },
        [edit](double v, std::uint64_t i) {
            edit([&](ProjectSettings& s) { s.environment.rotationDegrees = float(v); }, i);
        });
    return form;
}

PropertyForm* makeRenderForm(Document& document, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Render settings"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    form->addChoice(
        PropertyForm::tr("Configuration"), kConfigurations,
        [&scene] { return std::max(0, static_cast<int>(kConfigurations.indexOf(QString::fromStdString(scene.settings.render.configuration)))); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.configuration = kConfigurations[i].toStdString(); }, 0); });
    form->addInt(
        PropertyForm::tr("Width (px)"), 1, 16384, [&scene] { return scene.settings.render.width; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.width = v; }, 0); });
    form->addInt(
        PropertyForm::tr("Height (px)"), 1, 16384, [&scene] { return scene.settings.render.height; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.height = v; }, 0); });
    form->addInt(
        PropertyForm::tr("Samples per pixel"), 1, 65536, [&scene] { return scene.settings.render.spp; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.spp = v; }, 0); });
    form->addInt(
        PropertyForm::tr("Bounces"), 0, 64, [&scene] { return scene.settings.render.bounces; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.bounces = v; }, 0); });
    form->addInt(
        PropertyForm::tr("Seed"), 0, 1 << 30, [&scene] { return static_cast<int>(scene.settings.render.seed); },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.seed = static_cast<std::uint32_t>(v); }, 0); });
    form->addFloat(
        PropertyForm::tr("Exposure (EV)"), -10.0, 10.0, 2, [&scene] { return double(scene.settings.render.exposure); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.exposure = float(v); }, i); });
    form->addChoice(
        PropertyForm::tr("Tonemapper"),
        {PropertyForm::tr("None"), PropertyForm::tr("ACES (fitted)"), PropertyForm::tr("Khronos PBR Neutral")},
        [&scene] { return static_cast<int>(scene.settings.render.tonemapper); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.tonemapper = static_cast<Tonemapper>(i); }, 0); });
    form->addFloat(
        PropertyForm::tr("Radiance clamp (0 = off)"), 0.0, 100.0, 2, [&scene] { return double(scene.settings.render.clamp); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.clamp = float(v); }, i); });
    form->addChoice(
        PropertyForm::tr("Light units"), {PropertyForm::tr("Blender (W = lm / 683)"), PropertyForm::tr("Raw")},
        [&scene] { return static_cast<int>(scene.settings.lightUnits); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.lightUnits = static_cast<LightUnits>(i); }, 0); });
    return form;
}

} // namespace glint::editor
