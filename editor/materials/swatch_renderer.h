#pragma once
// Material swatches rendered by Glint's own path tracer: a sphere with the material under a fixed
// light, 48x48 pixels, 16 samples, seed 0 (deterministic: the same material gives the same pixels).
// Renders run on a worker thread of their own with its own headless context (as exports do), one
// at a time, and are cached by the material's content hash (its values and the bytes of the images
// it reads, not its name or id), so each look renders once and copies share a swatch.
#include "scene/core/scene.h"

#include <QImage>
#include <QObject>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>

class QThread;

namespace glint::editor {

class SwatchWorker;

class SwatchRenderer : public QObject {
    Q_OBJECT
public:
    static constexpr int kSize = 48;
    static constexpr int kSpp = 16;

    explicit SwatchRenderer(QObject* parent = nullptr);
    ~SwatchRenderer() override;

    // The material's content hash: its values, its textures' samplers and images (bytes included).
    static std::uint64_t contentHash(const Scene& scene, MaterialId material);
    // The scene a swatch renders: the material (and what it reads) on a sphere, lit and framed.
    static Scene swatchScene(const Scene& scene, MaterialId material);

    // The cached swatch of `hash`; a null image while it is not rendered yet.
    QImage cached(std::uint64_t hash) const;
    // Queues `material`'s swatch unless it is cached or queued; swatchReady follows.
    void request(const Scene& scene, MaterialId material);
    // Drops queued renders of hashes not in `wanted` (materials edited again or removed).
    void keepOnly(const std::set<std::uint64_t>& wanted);
    bool busy() const { return inFlight_ != 0 || !queue_.empty(); }
    // Milliseconds of the last render (upload + samples; the first one includes compiling).
    double lastRenderMs() const { return lastMs_; }
    double firstRenderMs() const { return firstMs_; } // with the context and the programs' compilation
    int rendered() const { return rendered_; }
    // Set when the path tracer is not available (no OpenGL 4.1): swatches are flat base colours.
    const QString& error() const { return error_; }
    const QString& lastFailure() const { return lastFailure_; } // of one render (a broken texture)

signals:
    void swatchReady(quint64 hash);

private:
    struct Job {
        std::uint64_t hash;
        std::shared_ptr<const Scene> scene;
        QImage fallback;
    };
    void startNext();
    void onRendered(quint64 hash, const QImage& image, double ms, const QString& error, bool unavailable);

    QThread* thread_ = nullptr;
    SwatchWorker* worker_ = nullptr;
    std::map<std::uint64_t, QImage> cache_;
    std::deque<Job> queue_;
    std::set<std::uint64_t> queued_;
    std::uint64_t inFlight_ = 0;
    QImage inFlightFallback_;
    double lastMs_ = 0.0;
    double firstMs_ = 0.0;
    int rendered_ = 0;
    QString error_;
    QString lastFailure_;
};

} // namespace glint::editor
