#pragma once
// An export running on a worker thread with a headless GL context of its own (OfflineRenderer:
// EGL), so the editor's event loop and its viewport context are untouched. The job owns a copy of
// the scene taken when it starts, so editing meanwhile does not change what is exported.
#include "editor/export/export_settings.h"
#include "scene/core/scene.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <memory>

class QThread;

namespace glint::editor {

class ExportJob : public QObject {
    Q_OBJECT
public:
    ExportJob(Scene scene, ExportSettings settings);
    // From any thread: the frame in flight is discarded (nothing partial is written) and the job ends.
    void cancel() { cancelled_ = true; }
    bool cancelled() const { return cancelled_; }

public slots:
    void run(); // on the worker thread

signals:
    void progress(int done, int total);  // samples over the whole export
    void frameWritten(const QString& path);
    // error empty: every frame written (or cancelled, then `cancelled` is true).
    void finished(const QString& error, bool cancelled, const QStringList& files);

private:
    Scene scene_;
    ExportSettings settings_;
    std::atomic<bool> cancelled_{false};
};

// Runs one ExportJob on its own thread and reports back on the GUI thread. running(true) when it
// starts and running(false) when it ends: the viewport pauses meanwhile (two cores are not
// enough for both).
class ExportController : public QObject {
    Q_OBJECT
public:
    explicit ExportController(QObject* parent = nullptr);
    ~ExportController() override; // cancels and waits for a job still running

    // Throws what planExport throws (bad settings) before anything starts.
    void start(const Scene& scene, const ExportSettings& settings);
    void cancel();
    bool isRunning() const { return job_ != nullptr; }
    const QStringList& files() const { return files_; }
    const QString& error() const { return error_; }

signals:
    void running(bool on);
    void progress(int done, int total);
    void finished(const QString& error, bool cancelled);

private:
    void onFinished(const QString& error, bool cancelled, const QStringList& files);

    QThread* thread_ = nullptr;
    ExportJob* job_ = nullptr;
    QStringList files_;
    QString error_;
};

} // namespace glint::editor
