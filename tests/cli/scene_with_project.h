#pragma once
// A copy of a scene as dir/s.gltf beside a project file dir/s.glint.json holding `project`: how the
// CLI tests give a bundled scene the render settings they test.
#include <QByteArray>
#include <QFile>
#include <QIODevice>
#include <QString>
#include <QTemporaryDir>

inline QString sceneWithProject(const QString& scene, const QTemporaryDir& dir, const QByteArray& project) {
    const QString copy = dir.filePath("s.gltf");
    QFile::copy(scene, copy);
    QFile f(dir.filePath("s.glint.json"));
    if (f.open(QIODevice::WriteOnly)) f.write(project);
    return copy;
}
