// Every feature Glint writes, as .gltf (+ .bin + image) and as .glb, passes the Khronos glTF
// validator with 0 errors.
#include "feature_scene.h"
#include "validator_run.h"

#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace glint;

class TestGltfValidator : public QObject {
    Q_OBJECT

private slots:
    void featureSceneHasNoErrors()
    {
        QTemporaryDir dir;
        const std::filesystem::path folder = dir.path().toStdString();
        saveScene(test::featureScene(), folder / "features.gltf");
        saveScene(test::featureScene(), folder / "features.glb");
        const std::string errors = test::validatorErrors({folder / "features.gltf", folder / "features.glb"});
        QVERIFY2(errors.empty(), errors.c_str());
    }

    void largeMeshWithWideIndicesHasNoErrors()
    {
        QTemporaryDir dir;
        const std::filesystem::path folder = dir.path().toStdString();
        saveScene(test::largeScene(300, 0), folder / "large.glb"); // 90,601 vertices: uint32 indices
        const std::string errors = test::validatorErrors({folder / "large.glb"});
        QVERIFY2(errors.empty(), errors.c_str());
    }

    void aBrokenFileIsCaught()
    {
        // The check itself must be able to fail: a glTF whose accessor points past its buffer.
        QTemporaryDir dir;
        const std::filesystem::path file = std::filesystem::path(dir.path().toStdString()) / "broken.gltf";
        std::ofstream(file) << R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="}],)"
                               R"("bufferViews": [{"buffer": 0, "byteLength": 64}]})";
        QVERIFY(!test::validatorErrors({file}).empty());
    }
};

QTEST_APPLESS_MAIN(TestGltfValidator)
#include "test_gltf_validator.moc"
