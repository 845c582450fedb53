#pragma once
// Scenes and helpers for the viewport's GUI tests: a small lit scene of analytic shapes, a large
// mesh scene for responsiveness, and the application set-up QOpenGLWidget needs (shared
// contexts, a 4.1 core default format) before QApplication exists.
#include "editor/document/document.h"
#include "scene/history/node_commands.h"

#include <QApplication>
#include <QImage>
#include <QSurfaceFormat>

#include <cmath>
#include <memory>

namespace glint::test {

// share = false: Qt re-creates a QOpenGLWidget's context whenever it changes windows.
inline void prepareGlApplication(bool share = true) {
    if (share) QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QSurfaceFormat::setDefaultFormat(format);
}

inline NodeId addShape(editor::Document& document, const char* name, ShapeKind kind, glm::vec3 at, glm::vec3 size = glm::vec3(1.0f)) {
    Node node;
    node.name = name;
    node.local.translation = at;
    Shape shape;
    shape.kind = kind;
    shape.size = size;
    node.component = shape;
    auto command = std::make_unique<AddNode>(std::move(node));
    AddNode* add = command.get();
    document.push(std::move(command));
    return add->nodeId();
}

// A sphere left, a box right and a ground plane under a grey sky, for a view from +Z at 5 m.
struct ShapesScene {
    NodeId sphere, box, ground;
};

inline ShapesScene buildShapesScene(editor::Document& document) {
    document.scene().settings.environment.color = glm::vec3(0.8f);
    ShapesScene s;
    s.sphere = addShape(document, "sphere", ShapeKind::Sphere, {-1.2f, 0.0f, 0.0f});
    s.box = addShape(document, "box", ShapeKind::Box, {1.2f, 0.0f, 0.0f}, glm::vec3(0.8f));
    s.ground = addShape(document, "ground", ShapeKind::GroundPlane, {0.0f, -0.5f, 0.0f});
    document.history().setClean();
    return s;
}

// A finely tessellated wavy grid: `n` x `n` quads, 2 n^2 triangles, as one mesh instance.
inline NodeId addGridMesh(editor::Document& document, int n) {
    Mesh mesh;
    Primitive p;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = 4.0f * float(i) / float(n) - 2.0f, z = 4.0f * float(j) / float(n) - 2.0f;
            p.positions.push_back({x, 0.1f * std::sin(7.0f * x) * std::cos(5.0f * z), z});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<std::uint32_t>(j * (n + 1) + i);
            const auto row = static_cast<std::uint32_t>(n + 1);
            p.indices.insert(p.indices.end(), {v, v + row, v + 1, v + 1, v + row, v + row + 1});
        }
    mesh.primitives.push_back(std::move(p));
    const MeshId id = document.scene().meshes.add(std::move(mesh));
    Node node;
    node.name = "grid";
    node.local.translation = {0.0f, -0.4f, 0.0f};
    node.component = MeshInstance{id};
    auto command = std::make_unique<AddNode>(std::move(node));
    AddNode* add = command.get();
    document.push(std::move(command));
    return add->nodeId();
}

// Share of pixels that are not black, and the mean of the RGB channels in [0, 1].
struct ImageStats {
    double nonBlack = 0.0;
    double mean = 0.0;
};

// The share of pixels in the raster preview's clear colour (0.22, 0.22, 0.24): a viewport showing
// only that has no picture of the scene.
inline double clearColourShare(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    long long n = 0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) n += rgb.pixel(x, y) == qRgb(56, 56, 61);
    return rgb.isNull() ? 1.0 : double(n) / (double(rgb.width()) * rgb.height());
}

// Mean 8-bit red, green and blue over the square of `half` pixels around `at` (inside the image).
inline glm::dvec3 meanRgbAround(const QImage& image, QPoint at, int half) {
    glm::dvec3 sum(0.0);
    int count = 0;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = at.y() - half; y <= at.y() + half; ++y)
        for (int x = at.x() - half; x <= at.x() + half; ++x) {
            if (!rgb.valid(x, y)) continue;
            const QRgb p = rgb.pixel(x, y);
            sum += glm::dvec3(qRed(p), qGreen(p), qBlue(p));
            ++count;
        }
    return count ? sum / double(count) : sum;
}

inline ImageStats imageStats(const QImage& image) {
    ImageStats s;
    if (image.isNull()) return s;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    long long lit = 0;
    double sum = 0.0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            const QRgb c = rgb.pixel(x, y);
            lit += (qRed(c) | qGreen(c) | qBlue(c)) != 0;
            sum += (qRed(c) + qGreen(c) + qBlue(c)) / (3.0 * 255.0);
        }
    const double n = double(rgb.width()) * rgb.height();
    s.nonBlack = double(lit) / n;
    s.mean = sum / n;
    return s;
}

} // namespace glint::test
