#include "editor/export/export_plan.h"

#include "editor/export/export_job.h"

#include "scene/anim/scene_at_time.h"

#include <QProcess>
#include <QThread>

#include <stdexcept>

namespace glint::editor {

namespace {

// Thrown from the progress callback to leave a render that was cancelled.
struct Cancelled {};

constexpr const char* kVersion = GLINT_VERSION;
constexpr int kEncodeTimeoutMs = 10 * 60 * 1000;

// The frames into a video, as `glint render --animation --video` does: through `glint encode`.
void encodeVideo(const ExportSettings& s) {
    QProcess encode;
    encode.start(QString::fromStdString(s.encoder.string()),
                 {"encode", QString::fromStdString(s.out.string()), QString::fromStdString(s.video.string()), "--frames",
                  QString("%1-%2").arg(s.firstFrame).arg(s.lastFrame), "--fps", QString("%1/%2").arg(s.fpsNumerator).arg(s.fpsDenominator)});
    if (!encode.waitForFinished(kEncodeTimeoutMs) || encode.exitStatus() != QProcess::NormalExit || encode.exitCode() != 0)
        throw std::runtime_error("encoding the video failed: " + encode.readAllStandardError().trimmed().toStdString());
}

} // namespace

ExportJob::ExportJob(Scene scene, ExportSettings settings) : scene_(std::move(scene)), settings_(std::move(settings)) {}

void ExportJob::run() {
    QStringList files;
    try {
        std::vector<ExportFrame> frames = planExport(scene_, settings_);
        renderer::prepareOutputFolder(frames.front().out);
        renderer::OfflineRenderer gpu;
        const int total = int(frames.size()) * std::max(1, settings_.spp);
        int before = 0;
        for (ExportFrame& frame : frames) {
            if (cancelled_) throw Cancelled{};
            const Scene posed = frame.time ? sceneAt(scene_, *frame.time) : scene_;
            frame.request.time = frame.time.value_or(0.0);
            frame.request.progress = [&](int done, int) {
                if (cancelled_) throw Cancelled{};
                emit progress(before + done, total);
            };
            const renderer::RenderOutput image = gpu.render(posed, frame.request);
            renderer::ImageMetadata metadata = frame.metadata;
            metadata["version"] = kVersion;
            metadata["renderTimeMs"] = formatNumber(image.timings.setupMs + image.timings.renderMs);
            renderer::ExrLayers layers = renderer::parseAovList(settings_.aovs);
            if (renderer::imageFormatFor(frame.out) == renderer::ImageFormat::Exr) layers.passes = renderer::parsePassList(settings_.passes);
            renderer::writeRenderImage(frame.out, image, layers, metadata);
            files << QString::fromStdString(frame.out.string());
            emit frameWritten(files.back());
            before += std::max(1, settings_.spp);
        }
        if (settings_.animation && !settings_.video.empty()) {
            encodeVideo(settings_);
            files << QString::fromStdString(settings_.video.string());
        }
        emit finished({}, false, files);
    } catch (const Cancelled&) {
        emit finished({}, true, files);
    } catch (const std::exception& e) {
        emit finished(QString::fromStdString(e.what()), false, files);
    }
}

ExportController::ExportController(QObject* parent) : QObject(parent) {}

ExportController::~ExportController() {
    if (!thread_) return;
    if (job_) job_->cancel();
    thread_->quit();
    thread_->wait();
}

void ExportController::start(const Scene& scene, const ExportSettings& settings) {
    if (job_) throw std::logic_error("an export is already running");
    planExport(scene, settings); // refuse bad settings here, on the caller's thread
    files_.clear();
    error_.clear();
    if (!thread_) {
        thread_ = new QThread(this);
        thread_->setObjectName("export");
        thread_->start();
    }
    job_ = new ExportJob(scene, settings);
    job_->moveToThread(thread_);
    connect(job_, &ExportJob::progress, this, &ExportController::progress);
    connect(job_, &ExportJob::finished, this, &ExportController::onFinished);
    emit running(true);
    QMetaObject::invokeMethod(job_, &ExportJob::run, Qt::QueuedConnection);
}

void ExportController::cancel() {
    if (job_) job_->cancel();
}

void ExportController::onFinished(const QString& error, bool cancelled, const QStringList& files) {
    files_ = files;
    error_ = error;
    job_->deleteLater();
    job_ = nullptr;
    emit running(false);
    emit finished(error, cancelled);
}

} // namespace glint::editor
