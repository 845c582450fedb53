#include "editor/export/export_dialog.h"

#include "editor/document/document.h"
#include "editor/preferences/retranslate.h"
#include "editor/properties/configuration_names.h"
#include "editor/viewport/viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

#include <cmath>

namespace glint::editor {

namespace {

QSpinBox* spin(QWidget* parent, int lo, int hi, int value, const QString& name) {
    auto* box = new QSpinBox(parent);
    box->setRange(lo, hi);
    box->setValue(value);
    box->setAccessibleName(name);
    return box;
}

// The last frame of the project's animation at its fps (0 when there is none).
int defaultLastFrame(const Scene& scene) {
    const Timeline& t = scene.settings.timeline;
    double end = t.end;
    if (end <= t.start)
        for (const auto& [id, node] : scene.nodes())
            if (const auto* camera = node.get<Camera>(); camera && !camera->path.empty()) end = std::max(end, camera->path.keys.back().time);
    const double fps = double(t.fpsNumerator) / std::max(1, t.fpsDenominator);
    return std::max(0, int(std::floor((end - t.start) * fps + 1e-6)));
}

// A form row's label whose text follows the language (retranslate.h): the dialog may be open
// while the language changes.
QLabel* rowLabel(QWidget* parent, const char* text) {
    auto* label = new QLabel(parent);
    keepTranslated(label, TextRole::Text, ExportDialog::staticMetaObject.className(), text);
    return label;
}

} // namespace

ExportDialog::ExportDialog(Document& document, Kind kind, Viewport* viewport, QWidget* parent)
    : QDialog(parent), document_(document), viewport_(viewport), kind_(kind) {
    keepTranslated(this, TextRole::Title, staticMetaObject.className(), kind == Kind::Still ? QT_TR_NOOP("Export image") : QT_TR_NOOP("Export animation"));
    buildForm(kind);
    applyProjectOutput(kind);
    restoreLast();
    connect(&controller_, &ExportController::finished, this, &ExportDialog::onFinished);
    if (viewport_) connect(&controller_, &ExportController::running, viewport_, &Viewport::setPaused);
}

void ExportDialog::buildForm(Kind kind) {
    const Scene& scene = document_.scene();
    const RenderSettings& r = scene.settings.render;
    auto* form = new QFormLayout;
    const QString base = document_.filePath().isEmpty() ? QStringLiteral("render") : QFileInfo(document_.filePath()).completeBaseName();
    const QString folder = document_.filePath().isEmpty() ? QString() : QFileInfo(document_.filePath()).absolutePath() + "/";
    out_ = new QLineEdit(folder + base + (kind == Kind::Still ? ".exr" : "_####.exr"), this);
    keepTranslated(out_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Output file"));
    auto* browse = new QPushButton(this);
    keepTranslated(browse, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Browse..."));
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getSaveFileName(this, tr("Output file"), out_->text(), tr("Images (*.exr *.png *.jpg *.tif)"));
        if (!file.isEmpty()) out_->setText(file);
    });
    auto* outRow = new QHBoxLayout;
    outRow->addWidget(out_);
    outRow->addWidget(browse);
    form->addRow(rowLabel(this, QT_TR_NOOP("Output")), outRow);
    width_ = spin(this, 1, 16384, r.width, tr("Width"));
    height_ = spin(this, 1, 16384, r.height, tr("Height"));
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(width_);
    sizeRow->addWidget(height_);
    form->addRow(rowLabel(this, QT_TR_NOOP("Size")), sizeRow);
    configuration_ = new QComboBox(this);
    keepTranslated(configuration_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Configuration"));
    // Shown as words ("Full"), kept as the identifiers the renderer and the files use ("full").
    for (const QString& id : configurationIds()) configuration_->addItem(configurationTitle(id.toStdString()), id);
    configuration_->setCurrentIndex(std::max(0, configuration_->findData(QString::fromStdString(r.configuration))));
    form->addRow(rowLabel(this, QT_TR_NOOP("Configuration")), configuration_);
    spp_ = spin(this, 1, 1 << 20, r.spp, tr("Samples per pixel"));
    form->addRow(rowLabel(this, QT_TR_NOOP("Samples per pixel")), spp_);
    seed_ = spin(this, 0, 1 << 30, int(r.seed), tr("Seed"));
    form->addRow(rowLabel(this, QT_TR_NOOP("Seed")), seed_);
    aovs_ = new QLineEdit(QStringLiteral("all"), this);
    keepTranslated(aovs_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("EXR layers"));
    keepTranslated(aovs_, TextRole::ToolTip, staticMetaObject.className(), QT_TR_NOOP("all, none, or a list of albedo, normal, depth, id, variance"));
    form->addRow(rowLabel(this, QT_TR_NOOP("EXR layers")), aovs_);
    passes_ = new QLineEdit(this);
    keepTranslated(passes_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Render passes"));
    keepTranslated(passes_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("EXR only, Accumulate and Reference: none, all, light, or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector"));
    keepTranslated(passes_, TextRole::Placeholder, staticMetaObject.className(), QT_TR_NOOP("none"));
    form->addRow(rowLabel(this, QT_TR_NOOP("Render passes")), passes_);
    animation_ = new QCheckBox(tr("Animation"), this);
    animation_->setChecked(kind == Kind::Animation);
    animation_->setVisible(false);
    first_ = spin(this, 0, 1 << 24, 0, tr("First frame"));
    last_ = spin(this, 0, 1 << 24, defaultLastFrame(scene), tr("Last frame"));
    if (kind == Kind::Animation) {
        auto* range = new QHBoxLayout;
        range->addWidget(first_);
        range->addWidget(last_);
        form->addRow(rowLabel(this, QT_TR_NOOP("Frames")), range);
        video_ = new QLineEdit(this);
        keepTranslated(video_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Video file"));
        keepTranslated(video_, TextRole::Placeholder, staticMetaObject.className(), QT_TR_NOOP("optional: .mp4 (H.264), .mov (ProRes), .mkv (FFV1)"));
        form->addRow(rowLabel(this, QT_TR_NOOP("Video")), video_);
    } else {
        first_->hide();
        last_->hide();
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    // A render can take minutes: Enter after typing a file name or a number must not start one, so
    // Export is no default button (an accept button would be made one), and no button of the
    // dialog becomes one by default (Browse would open a file dialog); only a click starts it.
    QPushButton* exportButton = buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    keepTranslated(exportButton, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Export"));
    for (QPushButton* button : findChildren<QPushButton*>()) {
        button->setAutoDefault(false);
        button->setDefault(false);
    }
    connect(exportButton, &QPushButton::clicked, this, &ExportDialog::startExport);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

ExportSettings ExportDialog::settings() const {
    const Scene& scene = document_.scene();
    ExportSettings s;
    s.sceneFile = document_.filePath().toStdString();
    s.out = out_->text().toStdString();
    s.width = width_->value();
    s.height = height_->value();
    s.spp = spp_->value();
    s.seed = std::uint32_t(seed_->value());
    s.configuration = configuration_->currentData().toString().toStdString();
    s.aovs = aovs_->text().trimmed().toStdString();
    s.passes = passes_->text().trimmed().toStdString();
    s.animation = animation_->isChecked();
    s.firstFrame = first_->value();
    s.lastFrame = last_->value();
    s.fpsNumerator = scene.settings.timeline.fpsNumerator;
    s.fpsDenominator = scene.settings.timeline.fpsDenominator;
    if (!s.animation && document_.currentTime() != 0.0) s.time = document_.currentTime();
    if (video_ && !video_->text().trimmed().isEmpty()) {
        s.video = video_->text().trimmed().toStdString();
        s.encoder = QCoreApplication::applicationFilePath().toStdString(); // the glint executable
    }
    return s;
}

void ExportDialog::setSettings(const ExportSettings& s) {
    out_->setText(QString::fromStdString(s.out.string()));
    width_->setValue(s.width);
    height_->setValue(s.height);
    spp_->setValue(s.spp);
    seed_->setValue(int(s.seed));
    configuration_->setCurrentIndex(std::max(0, configuration_->findData(QString::fromStdString(s.configuration))));
    aovs_->setText(QString::fromStdString(s.aovs));
    passes_->setText(QString::fromStdString(s.passes));
    first_->setValue(s.firstFrame);
    last_->setValue(s.lastFrame);
}

// The project's output block (what `glint render SCENE` writes without --out): its path, relative
// to the scene's folder, where it is a still's (no '#') or an animation's pattern as the dialog is.
void ExportDialog::applyProjectOutput(Kind kind) {
    const OutputSettings& output = document_.scene().settings.output;
    if (!output.aovs.empty()) aovs_->setText(QString::fromStdString(output.aovs));
    passes_->setText(QString::fromStdString(output.passes));
    const QString path = QString::fromStdString(output.path);
    if (path.isEmpty() || path.contains('#') != (kind == Kind::Animation)) return;
    const QString folder = document_.filePath().isEmpty() ? QString() : QFileInfo(document_.filePath()).absolutePath();
    out_->setText(QFileInfo(path).isAbsolute() || folder.isEmpty() ? path : folder + "/" + path);
}

QString ExportDialog::settingsGroup() const {
    return kind_ == Kind::Still ? QStringLiteral("export/still") : QStringLiteral("export/animation");
}

// The last export of this scene file and kind, restored field by field.
void ExportDialog::restoreLast() {
    QSettings settings;
    settings.beginGroup(settingsGroup());
    if (document_.filePath().isEmpty() || settings.value("scene").toString() != document_.filePath()) return;
    out_->setText(settings.value("out", out_->text()).toString());
    width_->setValue(settings.value("width", width_->value()).toInt());
    height_->setValue(settings.value("height", height_->value()).toInt());
    spp_->setValue(settings.value("spp", spp_->value()).toInt());
    seed_->setValue(settings.value("seed", seed_->value()).toInt());
    configuration_->setCurrentIndex(std::max(0, configuration_->findData(settings.value("configuration", configuration_->currentData()))));
    aovs_->setText(settings.value("aovs", aovs_->text()).toString());
    passes_->setText(settings.value("passes", passes_->text()).toString());
    first_->setValue(settings.value("first", first_->value()).toInt());
    last_->setValue(settings.value("last", last_->value()).toInt());
    if (video_) video_->setText(settings.value("video", video_->text()).toString());
}

void ExportDialog::rememberLast() const {
    QSettings settings;
    settings.beginGroup(settingsGroup());
    settings.setValue("scene", document_.filePath());
    settings.setValue("out", out_->text());
    settings.setValue("width", width_->value());
    settings.setValue("height", height_->value());
    settings.setValue("spp", spp_->value());
    settings.setValue("seed", seed_->value());
    settings.setValue("configuration", configuration_->currentData());
    settings.setValue("aovs", aovs_->text());
    settings.setValue("passes", passes_->text());
    settings.setValue("first", first_->value());
    settings.setValue("last", last_->value());
    if (video_) settings.setValue("video", video_->text());
}

void ExportDialog::startExport() {
    rememberLast();
    try {
        controller_.start(document_.scene(), settings());
    } catch (const std::exception& e) {
        QMessageBox::warning(this, windowTitle(), QString::fromStdString(e.what()));
        return;
    }
    progress_ = new QProgressDialog(tr("Rendering..."), tr("Cancel"), 0, 100, this);
    progress_->setWindowModality(Qt::WindowModal);
    progress_->setMinimumDuration(0);
    progress_->setAutoReset(false);
    progress_->setAutoClose(false);
    connect(&controller_, &ExportController::progress, progress_, [this](int done, int total) {
        progress_->setMaximum(total);
        progress_->setValue(done);
    });
    connect(progress_, &QProgressDialog::canceled, &controller_, &ExportController::cancel);
    progress_->show();
}

void ExportDialog::onFinished(const QString& error, bool cancelled) {
    if (progress_) {
        progress_->deleteLater();
        progress_ = nullptr;
    }
    if (!error.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), error);
        return;
    }
    if (!cancelled) accept();
}

} // namespace glint::editor
