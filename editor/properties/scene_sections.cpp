// Environment, fog and render settings: the project file's sections, edited as one settings command.
#include "sections.h"

#include "configuration_names.h"
#include "property_edits.h"

#include "editor/outliner/node_names.h"
#include "scene/io/project/project_file.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <bit>

namespace glint::editor {
namespace {

using Edit = std::function<void(const std::function<void(ProjectSettings&)>&, std::uint64_t)>;

Edit settingsEditor(Document& document, const Report& report) {
    return [&document, report](const std::function<void(ProjectSettings&)>& change, std::uint64_t interaction) {
        const QString error = editSettings(document, change, interaction);
        if (!error.isEmpty()) report(error);
    };
}


// What keeps the project's environment image from being read, for the Scene tab; empty when none.
QString environmentProblem(const Document& document) {
    const std::string& file = document.scene().settings.environment.file;
    if (file.empty()) return {};
    const std::filesystem::path resolved = document.environmentPath();
    if (resolved.empty())
        return PropertyForm::tr("\"%1\" is relative, but the scene has no folder yet: choose the file with Browse, or save the scene first.")
            .arg(QString::fromStdString(file));
    const QFileInfo info(QString::fromStdString(resolved.string()));
    if (!info.isFile() || !info.isReadable())
        return PropertyForm::tr("Cannot read the environment image %1. Choose it again with Browse, or clear the field to use the colour below.")
            .arg(QDir::toNativeSeparators(info.absoluteFilePath()));
    return {};
}

QStringList configurationTitles() {
    QStringList titles;
    for (const QString& id : configurationIds()) titles << configurationTitle(id.toStdString());
    return titles;
}

} // namespace

PropertyForm* makeEnvironmentForm(Document& document, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Environment"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    // Paths resolve in the scene's folder. A file chosen there is stored relative to it; one chosen
    // elsewhere, or in an untitled scene, is stored absolute until a save copies it beside the scene.
    auto* row = new QWidget(form);
    auto* path = new QLineEdit(row);
    auto* browse = new QToolButton(row);
    browse->setText(PropertyForm::tr("Browse..."));
    browse->setAccessibleName(PropertyForm::tr("Choose an HDR environment file"));
    auto* status = new QLabel(row); // what is wrong with the file, where the user looks
    status->setWordWrap(true);
    status->setTextFormat(Qt::PlainText);
    status->setAccessibleName(PropertyForm::tr("Environment image status"));
    status->setForegroundRole(QPalette::BrightText);
    status->setAutoFillBackground(true);
    QPalette warning = status->palette();
    warning.setColor(QPalette::Window, QColor(0xb0, 0x2a, 0x1e));
    warning.setColor(QPalette::BrightText, Qt::white);
    status->setPalette(warning);
    status->setMargin(3);
    auto* pathRow = new QHBoxLayout;
    pathRow->setContentsMargins(0, 0, 0, 0);
    pathRow->addWidget(path, 1);
    pathRow->addWidget(browse);
    auto* rowLayout = new QVBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    rowLayout->addLayout(pathRow);
    rowLayout->addWidget(status);
    auto setFile = [edit](const QString& file) {
        edit([&](ProjectSettings& s) { s.environment.file = QDir::fromNativeSeparators(file).toStdString(); }, 0);
    };
    QObject::connect(path, &QLineEdit::editingFinished, row, [path, setFile] { setFile(path->text().trimmed()); });
    QObject::connect(browse, &QToolButton::clicked, row, [&document, row, setFile] {
        const QString sceneFolder = document.filePath().isEmpty() ? QString() : QFileInfo(document.filePath()).absolutePath();
        const std::filesystem::path current = document.environmentPath();
        const QString start = !current.empty() ? QString::fromStdString(current.parent_path().string())
                              : !sceneFolder.isEmpty() ? sceneFolder
                                                       : QDir::homePath();
        const QString file = QFileDialog::getOpenFileName(row, PropertyForm::tr("Environment map"), start,
                                                          PropertyForm::tr("HDR images (*.hdr *.exr);;All files (*)"));
        if (file.isEmpty()) return;
        const QString absolute = QFileInfo(file).absoluteFilePath();
        const QString relative = sceneFolder.isEmpty() ? QString() : QDir(sceneFolder).relativeFilePath(absolute);
        const bool inside = !relative.isEmpty() && !relative.startsWith(QLatin1String("../")) && QFileInfo(relative).isRelative();
        setFile(inside ? relative : absolute);
    });
    form->addWidget(PropertyForm::tr("HDR file"), row, [&document, &scene, path, status] {
        if (!path->hasFocus()) path->setText(QString::fromStdString(scene.settings.environment.file));
        const QString problem = environmentProblem(document);
        status->setText(problem);
        status->setVisible(!problem.isEmpty());
    });
    form->addColor(
        PropertyForm::tr("Colour (no file)"),
        [&scene] {
            const glm::vec3& c = scene.settings.environment.color;
            return toQColor(c.x, c.y, c.z);
        },
        [edit](const QColor& c) {
            edit([&](ProjectSettings& s) { s.environment.color = toLinear(c); }, 0);
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

PropertyForm* makeFogForm(Document& document, const Report& report, QWidget* parent) {
    // The project's fog (docs/MEDIA.md). Typing may go past a slider's range, so each value is
    // held to what the project file accepts: a saved scene always opens again.
    auto* form = new PropertyForm(document, PropertyForm::tr("Fog"), parent);
    const Edit edit = settingsEditor(document, report);
    const Fog& fog = document.scene().settings.fog;
    form->addFloat(
        PropertyForm::tr("Density (1/m)"), 0.0, 1.0, 4, [&fog] { return double(fog.density); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.fog.density = float(std::max(v, 0.0)); }, i); });
    form->addColor(
        PropertyForm::tr("Colour"), [&fog] { return toQColor(fog.color.x, fog.color.y, fog.color.z); },
        [edit](const QColor& c) { edit([&](ProjectSettings& s) { s.fog.color = toLinear(c); }, 0); });
    const double g = kMaxFogAnisotropy;
    form->addFloat(
        PropertyForm::tr("Anisotropy"), -g, g, 2, [&fog] { return double(fog.anisotropy); },
        [edit, g](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.fog.anisotropy = float(std::clamp(v, -g, g)); }, i); });
    form->addFloat(
        PropertyForm::tr("Height falloff (1/m)"), 0.0, 2.0, 3, [&fog] { return double(fog.heightFalloff); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.fog.heightFalloff = float(std::max(v, 0.0)); }, i); });
    form->addFloat(
        PropertyForm::tr("Base height (m)"), -10.0, 10.0, 2, [&fog] { return double(fog.baseHeight); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.fog.baseHeight = float(v); }, i); });
    return form;
}

PropertyForm* makeRenderForm(Document& document, const Report& report, QWidget* parent) {
    auto* form = new PropertyForm(document, PropertyForm::tr("Render settings"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    form->addChoice(
        PropertyForm::tr("Configuration"), configurationTitles(),
        [&scene] { return std::max(0, static_cast<int>(configurationIds().indexOf(QString::fromStdString(scene.settings.render.configuration)))); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.configuration = configurationIds()[i].toStdString(); }, 0); });
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
        {PropertyForm::tr("None"), PropertyForm::tr("ACES (fitted)"), PropertyForm::tr("Khronos PBR Neutral"), PropertyForm::tr("AgX"),
         PropertyForm::tr("Reinhard (extended)"), PropertyForm::tr("Hable (Uncharted 2)")},
        [&scene] { return static_cast<int>(scene.settings.render.tonemapper); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.tonemapper = static_cast<Tonemapper>(i); }, 0); });
    form->addFloat(
        PropertyForm::tr("Radiance clamp (0 = off)"), 0.0, 100.0, 2, [&scene] { return double(scene.settings.render.clamp); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.clamp = float(v); }, i); });
    form->addFloat(
        PropertyForm::tr("Noise threshold (adaptive sampling, 0 = off)"), 0.0, 1.0, 4,
        [&scene] { return double(scene.settings.render.adaptive.threshold); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.adaptive.threshold = float(v); }, i); });
    form->addInt(
        PropertyForm::tr("Adaptive minimum samples (0 = automatic)"), 0, 1 << 20,
        [&scene] { return scene.settings.render.adaptive.minSamples; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.adaptive.minSamples = v; }, 0); });
    form->addChoice(
        PropertyForm::tr("Adaptive goal"), {PropertyForm::tr("Even noise (as Cycles)"), PropertyForm::tr("Least mean error")},
        [&scene] { return static_cast<int>(scene.settings.render.adaptive.goal); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.adaptive.goal = static_cast<AdaptiveGoal>(i); }, 0); });
    // Index i of the choice is a block of 2^i pixels per side (RenderSettings::sampleBlock).
    form->addChoice(
        PropertyForm::tr("Sample blocks (pixels sharing a sequence)"),
        {PropertyForm::tr("Off"), QStringLiteral("2 x 2"), QStringLiteral("4 x 4"), QStringLiteral("8 x 8")},
        [&scene] { return std::countr_zero(static_cast<unsigned>(scene.settings.render.sampleBlock)); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.sampleBlock = 1 << i; }, 0); });
    form->addFloat(
        PropertyForm::tr("Motion blur shutter (frames, 0 = off)"), 0.0, 1.0, 2, [&scene] { return double(scene.settings.render.shutter); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.shutter = float(v); }, i); });
    form->addFloat(
        PropertyForm::tr("Bloom strength (0 = off)"), 0.0, 1.0, 3, [&scene] { return double(scene.settings.render.bloom.strength); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.bloom.strength = float(v); }, i); });
    form->addFloat(
        PropertyForm::tr("Bloom radius (of the height)"), 0.001, 1.0, 3, [&scene] { return double(scene.settings.render.bloom.radius); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.bloom.radius = float(v); }, i); });
    form->addChoice(
        PropertyForm::tr("Light units"), {PropertyForm::tr("Blender (W = lm / 683)"), PropertyForm::tr("Raw")},
        [&scene] { return static_cast<int>(scene.settings.lightUnits); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.lightUnits = static_cast<LightUnits>(i); }, 0); });
    return form;
}

PropertyForm* makeViewportForm(Document& document, const ViewportControls& controls, QWidget* parent) {
    // Not undoable: like the preferences dialog's field it is the editor's setting, kept across
    // scenes; a render's samples are the Render settings' field above.
    auto* form = new PropertyForm(document, PropertyForm::tr("Viewport"), parent);
    QSpinBox* samples = form->addInt(PropertyForm::tr("Viewport samples"), 0, 1 << 20, controls.sampleCap, controls.setSampleCap);
    samples->setSpecialValueText(PropertyForm::tr("No limit"));
    samples->setToolTip(PropertyForm::tr("The viewport stops adding samples per pixel here; renders use the samples per pixel above"));
    if (controls.pause) {
        auto* pause = new QToolButton(form);
        pause->setDefaultAction(controls.pause);
        pause->setToolButtonStyle(Qt::ToolButtonTextOnly);
        form->addWidget(PropertyForm::tr("Rendering"), pause, [] {});
    }
    return form;
}

PropertyForm* makeProjectForm(Document& document, const Report& report, QWidget* parent) {
    // What `glint render` and the exports take from the project besides the render settings.
    auto* form = new PropertyForm(document, PropertyForm::tr("Camera and timeline"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    auto* camera = newFormComboBox(form);
    QObject::connect(camera, &QComboBox::activated, form, [edit, camera](int i) {
        edit([&](ProjectSettings& s) { s.activeCamera = NodeId{camera->itemData(i).toUInt()}; }, 0);
    });
    // Filled on every refresh: cameras come and go with the document (renames too).
    form->addWidget(PropertyForm::tr("Active camera"), camera, [&scene, camera] {
        QSignalBlocker block(camera);
        camera->clear();
        camera->addItem(PropertyForm::tr("(the first camera)"), 0u);
        for (const NodeId id : scene.depthFirst())
            if (scene.at(id).get<Camera>()) camera->addItem(nodeDisplayName(scene, id), id.value);
        camera->setCurrentIndex(std::max(0, camera->findData(scene.settings.activeCamera.value)));
    });
    form->addFloat(
        PropertyForm::tr("Timeline start (s)"), 0.0, 60.0, 3, [&scene] { return scene.settings.timeline.start; },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.timeline.start = std::max(0.0, v); }, i); });
    form->addFloat(
        PropertyForm::tr("Timeline end (s, 0 = the animation's)"), 0.0, 60.0, 3, [&scene] { return scene.settings.timeline.end; },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.timeline.end = std::max(0.0, v); }, i); });
    form->addText(
        PropertyForm::tr("Frames per second"),
        [&scene] {
            const Timeline& t = scene.settings.timeline;
            return t.fpsDenominator == 1 ? QString::number(t.fpsNumerator)
                                         : QStringLiteral("%1/%2").arg(t.fpsNumerator).arg(t.fpsDenominator);
        },
        [edit, report](const QString& text) {
            // "24" or a rational rate such as "24000/1001" (docs/CLI.md).
            const QStringList parts = text.trimmed().split('/');
            bool okN = false, okD = parts.size() == 1;
            const int numerator = parts.value(0).toInt(&okN);
            const int denominator = parts.size() == 2 ? parts[1].toInt(&okD) : 1;
            if (!okN || !okD || parts.size() > 2 || numerator <= 0 || denominator <= 0) {
                report(PropertyForm::tr("Frames per second must be a positive number or a ratio such as 24000/1001, not \"%1\".").arg(text));
                return;
            }
            edit(
                [&](ProjectSettings& s) {
                    s.timeline.fpsNumerator = numerator;
                    s.timeline.fpsDenominator = denominator;
                },
                0);
        });
    return form;
}

PropertyForm* makeReconstructionForm(Document& document, const Report& report, QWidget* parent) {
    // Used by the configurations with history (baseline to heavy) and saved in the project, so
    // exports and `glint render` filter the same way (docs/DENOISING.md says what each one does).
    auto* form = new PropertyForm(document, PropertyForm::tr("Real-time reconstruction"), parent);
    const Edit edit = settingsEditor(document, report);
    const Scene& scene = document.scene();
    const TaaParameters& taa = scene.settings.render.taa;
    const SvgfParameters& svgf = scene.settings.render.svgf;
    form->addFloat(
        PropertyForm::tr("TAA blend (current frame)"), 0.01, 1.0, 3, [&taa] { return double(taa.blend); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.taa.blend = float(std::clamp(v, 0.01, 1.0)); }, i); });
    form->addChoice(
        PropertyForm::tr("TAA history clipping"),
        {PropertyForm::tr("Variance clip (YCoCg)"), PropertyForm::tr("Min/max clamp"), PropertyForm::tr("None (ghosts)")},
        [&taa] { return static_cast<int>(taa.clip); },
        [edit](int i) { edit([&](ProjectSettings& s) { s.render.taa.clip = static_cast<TaaClip>(i); }, 0); });
    form->addFloat(
        PropertyForm::tr("TAA clip box (std. deviations)"), 0.25, 4.0, 2, [&taa] { return double(taa.clipGamma); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.taa.clipGamma = float(std::clamp(v, 0.05, 16.0)); }, i); });
    form->addCheck(
        PropertyForm::tr("TAA perceptual blend"), [&taa] { return taa.perceptualBlend; },
        [edit](bool on) { edit([&](ProjectSettings& s) { s.render.taa.perceptualBlend = on; }, 0); });
    form->addInt(
        PropertyForm::tr("SVGF a-trous iterations"), 1, 10, [&svgf] { return svgf.iterations; },
        [edit](int v) { edit([&](ProjectSettings& s) { s.render.svgf.iterations = v; }, 0); });
    form->addFloat(
        PropertyForm::tr("SVGF temporal alpha"), 0.01, 1.0, 3, [&svgf] { return double(svgf.alpha); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.alpha = float(std::clamp(v, 0.01, 1.0)); }, i); });
    form->addFloat(
        PropertyForm::tr("SVGF moments alpha"), 0.01, 1.0, 3, [&svgf] { return double(svgf.momentsAlpha); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.momentsAlpha = float(std::clamp(v, 0.01, 1.0)); }, i); });
    form->addFloat(
        PropertyForm::tr("SVGF luminance sigma"), 0.1, 32.0, 2, [&svgf] { return double(svgf.sigmaLuminance); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.sigmaLuminance = float(std::max(v, 0.01)); }, i); });
    form->addFloat(
        PropertyForm::tr("SVGF normal sigma (exponent)"), 0.0, 512.0, 1, [&svgf] { return double(svgf.sigmaNormal); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.sigmaNormal = float(std::max(v, 0.0)); }, i); });
    form->addFloat(
        PropertyForm::tr("SVGF depth sigma"), 0.05, 16.0, 2, [&svgf] { return double(svgf.sigmaDepth); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.sigmaDepth = float(std::max(v, 0.01)); }, i); });
    form->addFloat(
        PropertyForm::tr("SVGF firefly ratio"), 1.0, 64.0, 1, [&svgf] { return double(svgf.fireflyRatio); },
        [edit](double v, std::uint64_t i) { edit([&](ProjectSettings& s) { s.render.svgf.fireflyRatio = float(std::max(v, 1.0)); }, i); });
    return form;
}

} // namespace glint::editor
