#include "swatch_renderer.h"

#include "renderer/offline_render.h"
#include "scene/geometry/geometry.h"
#include "scene/history/value_json.h"

#include <QColor>
#include <QElapsedTimer>
#include <QThread>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string_view>

namespace glint::editor {

// Lives on the swatch thread: the headless context is current there for its whole life.
class SwatchWorker : public QObject {
    Q_OBJECT
public:
    void render(quint64 hash, std::shared_ptr<const Scene> scene) {
        QElapsedTimer clock;
        clock.start();
        if (!renderer_) {
            try {
                renderer_ = std::make_unique<renderer::OfflineRenderer>();
            } catch (const std::exception& e) {
                emit rendered(hash, {}, 0.0, QString::fromStdString(e.what()), true);
                return;
            }
        }
        try {
            renderer::RenderRequest request;
            request.configuration = renderer::Configuration::Accumulate;
            request.width = request.height = SwatchRenderer::kSize;
            request.spp = SwatchRenderer::kSpp;
            request.seed = 0;
            request.bounces = 6; // glass needs a few
            const renderer::RenderOutput out = renderer_->render(*scene, request);
            QImage image(out.tonemapped.data(), out.width, out.height, out.width * 4, QImage::Format_RGBA8888);
            emit rendered(hash, image.copy(), double(clock.nsecsElapsed()) / 1e6, {}, false);
        } catch (const std::exception& e) {
            emit rendered(hash, {}, double(clock.nsecsElapsed()) / 1e6, QString::fromStdString(e.what()), false);
        }
    }
    void release() { renderer_.reset(); }

signals:
    void rendered(quint64 hash, const QImage& image, double ms, const QString& error, bool unavailable);

private:
    std::unique_ptr<renderer::OfflineRenderer> renderer_;
};

namespace {

void mix(std::uint64_t& hash, std::uint64_t value) { hash ^= value + 0x9e3779b97f4a7c15ull + (hash << 6) + (hash >> 2); }

std::uint64_t bytesHash(std::string_view bytes) { return std::hash<std::string_view>{}(bytes); }

const TextureRef* refs(const Material& m, int i) {
    const TextureRef* all[] = {&m.baseColorTexture,     &m.metallicRoughnessTexture, &m.normalTexture,
                               &m.occlusionTexture,     &m.emissiveTexture,          &m.specularTexture,
                               &m.specularColorTexture, &m.transmissionTexture,      &m.thicknessTexture};
    return i < int(std::size(all)) ? all[i] : nullptr;
}

// A flat swatch of the base colour: what shows until the render arrives, and if it cannot.
QImage flatSwatch(const Material& m) {
    QImage image(SwatchRenderer::kSize, SwatchRenderer::kSize, QImage::Format_RGBA8888);
    auto srgb = [](float linear) {
        const float v = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
        return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const glm::vec3 c = glm::vec3(m.baseColorFactor) + m.emissiveFactor * m.emissiveStrength;
    image.fill(QColor(srgb(c.x), srgb(c.y), srgb(c.z)));
    return image;
}

} // namespace

SwatchRenderer::SwatchRenderer(QObject* parent) : QObject(parent) {
    thread_ = new QThread(this);
    thread_->setObjectName("swatches");
    worker_ = new SwatchWorker;
    worker_->moveToThread(thread_);
    connect(thread_, &QThread::finished, worker_, &QObject::deleteLater);
    connect(worker_, &SwatchWorker::rendered, this, &SwatchRenderer::onRendered, Qt::QueuedConnection);
    thread_->start();
}

SwatchRenderer::~SwatchRenderer() {
    queue_.clear();
    // The context goes on the thread that made it, after the render in flight.
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->release(); }, Qt::BlockingQueuedConnection);
    thread_->quit();
    thread_->wait();
}

std::uint64_t SwatchRenderer::contentHash(const Scene& scene, MaterialId material) {
    const Material* m = scene.materials.find(material);
    if (!m) return 0;
    Material unnamed = *m;
    unnamed.name.clear(); // a rename or a copy keeps its swatch
    nlohmann::json j = unnamed;
    std::uint64_t hash = bytesHash(j.dump());
    for (int i = 0; const TextureRef* ref = refs(*m, i); ++i) {
        const Texture* texture = scene.textures.find(ref->texture);
        if (!texture) continue;
        if (const Sampler* sampler = scene.samplers.find(texture->sampler)) mix(hash, bytesHash(nlohmann::json(*sampler).dump()));
        if (const Image* image = scene.images.find(texture->image))
            mix(hash, bytesHash({reinterpret_cast<const char*>(image->encoded.data()), image->encoded.size()}));
    }
    return hash == 0 ? 1 : hash;
}

Scene SwatchRenderer::swatchScene(const Scene& scene, MaterialId material) {
    Scene out;
    const Material& m = scene.materials.at(material);
    out.materials.insert(material, m);
    for (int i = 0; const TextureRef* ref = refs(m, i); ++i) {
        const Texture* texture = scene.textures.find(ref->texture);
        if (!texture || out.textures.contains(ref->texture)) continue;
        out.textures.insert(ref->texture, *texture);
        if (const Image* image = scene.images.find(texture->image); image && !out.images.contains(texture->image))
            out.images.insert(texture->image, *image);
        if (const Sampler* sampler = scene.samplers.find(texture->sampler); sampler && !out.samplers.contains(texture->sampler))
            out.samplers.insert(texture->sampler, *sampler);
    }
    // A sphere of radius 0.5 at the origin, seen from +Z and a little above: a uv-sphere mesh, since
    // the renderer textures triangles (uv0 and tangents), not analytic shapes.
    Shape round;
    round.kind = ShapeKind::Sphere;
    round.radius = 0.5f;
    Mesh mesh;
    mesh.name = "swatch";
    mesh.primitives.push_back(tessellateShape(round, 32)); // 2k triangles: smooth at 48 px
    mesh.primitives.back().material = material;
    Node sphere;
    sphere.name = "swatch";
    sphere.component = MeshInstance{out.meshes.add(std::move(mesh))};
    out.addNode(sphere);
    Node camera;
    camera.name = "camera";
    Camera lens;
    lens.yfov = 0.58f;
    lens.aspectRatio = 1.0f;
    camera.component = lens;
    const glm::quat down = glm::angleAxis(-0.25f, glm::vec3(1.0f, 0.0f, 0.0f));
    camera.local.rotation = down;
    camera.local.translation = down * glm::vec3(0.0f, 0.0f, 2.0f);
    out.settings.activeCamera = out.addNode(camera);
    // A key light from the upper left and a grey sky, so colour, gloss and glass all show.
    Node key;
    key.name = "key";
    Light sun;
    sun.type = LightType::Sun;
    sun.intensity = 3.0f;
    sun.angularDiameter = 0.2f;
    key.component = sun;
    key.local.rotation = glm::angleAxis(-0.6f, glm::vec3(0.0f, 1.0f, 0.0f)) * glm::angleAxis(-0.7f, glm::vec3(1.0f, 0.0f, 0.0f));
    out.addNode(key);
    out.settings.environment.color = glm::vec3(0.35f);
    out.settings.environment.intensity = 1.0f;
    out.settings.lightUnits = LightUnits::Raw;
    out.settings.render.exposure = 0.0f;
    out.settings.render.tonemapper = Tonemapper::PbrNeutral;
    return out;
}

QImage SwatchRenderer::cached(std::uint64_t hash) const {
    auto it = cache_.find(hash);
    return it == cache_.end() ? QImage() : it->second;
}

void SwatchRenderer::request(const Scene& scene, MaterialId material) {
    const std::uint64_t hash = contentHash(scene, material);
    if (!hash || cache_.count(hash) || queued_.count(hash) || hash == inFlight_) return;
    Job job{hash, std::make_shared<const Scene>(swatchScene(scene, material)), flatSwatch(scene.materials.at(material))};
    if (!error_.isEmpty()) { // no path tracer: the flat swatch is the swatch
        cache_[hash] = job.fallback;
        emit swatchReady(hash);
        return;
    }
    queued_.insert(hash);
    queue_.push_back(std::move(job));
    startNext();
}

void SwatchRenderer::keepOnly(const std::set<std::uint64_t>& wanted) {
    std::erase_if(queue_, [&](const Job& job) {
        if (wanted.count(job.hash)) return false;
        queued_.erase(job.hash);
        return true;
    });
}

void SwatchRenderer::startNext() {
    if (inFlight_ || queue_.empty()) return;
    Job job = std::move(queue_.front());
    queue_.pop_front();
    queued_.erase(job.hash);
    inFlight_ = job.hash;
    inFlightFallback_ = job.fallback;
    QMetaObject::invokeMethod(worker_, [w = worker_, hash = job.hash, scene = job.scene] { w->render(hash, scene); }, Qt::QueuedConnection);
}

void SwatchRenderer::onRendered(quint64 hash, const QImage& image, double ms, const QString& error, bool unavailable) {
    inFlight_ = 0;
    lastMs_ = ms;
    if (rendered_ == 0) firstMs_ = ms;
    ++rendered_;
    if (unavailable && error_.isEmpty()) error_ = error;
    if (!error.isEmpty()) lastFailure_ = error;
    cache_[hash] = image.isNull() ? inFlightFallback_ : image;
    emit swatchReady(hash);
    startNext();
}

} // namespace glint::editor

#include "swatch_renderer.moc"
