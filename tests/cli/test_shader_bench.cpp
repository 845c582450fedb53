// `glint bench --suite shaders` (app/bench/shader_suite.h): one build of the Cornell box's path
// tracer writes a CSV row with its source size and non-negative times. A smoke test, not a timing.
#include "shader_suite.h"

#include <QTemporaryDir>
#include <QTest>

#include <fstream>
#include <stdexcept>
#include <string>

class TestShaderBench : public QObject {
    Q_OBJECT
private slots:
    void writesOneRowPerBuild() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        glint::bench::ShaderSuiteOptions o;
        o.scene = GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf";
        o.out = dir.path().toStdString();
        o.variants = {"accumulate", "ao"};
        o.prelude = {"#pragma optionNV(unroll none)"}; // NVIDIA's; other drivers ignore it
        QCOMPARE(glint::bench::runShaderSuite(o), 0);
        std::ifstream csv(o.out + "/shader_bench.csv");
        std::string line;
        QVERIFY(std::getline(csv, line));
        QVERIFY(line.rfind("variant,compile,fragment_bytes,", 0) == 0);
        for (const char* variant : {"accumulate", "ao"}) {
            QVERIFY(std::getline(csv, line));
            QVERIFY2(line.rfind(std::string(variant) + ",1,", 0) == 0, line.c_str());
            QVERIFY2(line.find("HAS_MESHES") != std::string::npos, line.c_str());
            QVERIFY2(line.find(",-") == std::string::npos, line.c_str()); // no negative figure
            const std::size_t bytes = std::stoul(line.substr(line.find(",1,") + 3));
            QVERIFY(bytes > 50000);
        }
        QVERIFY(!std::getline(csv, line));
        QVERIFY(std::ifstream(o.out + "/shader_bench.json").good());
        o.variants = {"nonsense"};
        bool refused = false;
        try {
            glint::bench::runShaderSuite(o);
        } catch (const std::runtime_error&) {
            refused = true;
        }
        QVERIFY(refused);
    }
};

QTEST_GUILESS_MAIN(TestShaderBench)
#include "test_shader_bench.moc"
