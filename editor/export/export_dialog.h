#pragma once
// Export still / export animation: size, samples, configuration, output file (the format follows
// its extension: .exr with AOVs, .png, .jpg, .tif), AOV layers, frame range. The export runs in
// the background (ExportController) with a progress dialog and cancel; the viewport passed in is
// paused meanwhile. It opens with the project's output block (path, EXR layers) where it fits the
// kind, and with what the last export of the same scene and kind used (the user's settings).
#include "editor/export/export_job.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QProgressDialog;
class QSpinBox;

namespace glint::editor {

class Document;
class Viewport;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Still, Animation };
    ExportDialog(Document& document, Kind kind, Viewport* viewport = nullptr, QWidget* parent = nullptr);

    ExportSettings settings() const;      // from the fields
    void setSettings(const ExportSettings& settings);
    ExportController& controller() { return controller_; }

public slots:
    void startExport(); // validates, starts, shows progress; reports errors in a message box

private:
    void buildForm(Kind kind);
    void applyProjectOutput(Kind kind);
    void restoreLast();
    void rememberLast() const;
    QString settingsGroup() const; // "export/still" or "export/animation"

    void onFinished(const QString& error, bool cancelled);

    Document& document_;
    Viewport* viewport_;
    ExportController controller_;
    QLineEdit* out_ = nullptr;
    QSpinBox* width_ = nullptr;
    QSpinBox* height_ = nullptr;
    QSpinBox* spp_ = nullptr;
    QSpinBox* seed_ = nullptr;
    QComboBox* configuration_ = nullptr;
    QLineEdit* aovs_ = nullptr;
    QLineEdit* passes_ = nullptr;
    QCheckBox* animation_ = nullptr;
    QSpinBox* first_ = nullptr;
    QSpinBox* last_ = nullptr;
    QLineEdit* video_ = nullptr;
    QProgressDialog* progress_ = nullptr;
    Kind kind_;
};

} // namespace glint::editor
