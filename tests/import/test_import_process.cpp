// importScene() end to end: the worker process, its reply, the GLB hand-over, and every way the
// worker can fail (crash, hang, endless output, unreadable reply, bad exit) reported as a FileError
// naming the file, never a crash of the caller. Bad input files give specific errors.
#include "import_test_util.h"

#include "scene/import/import.h"
#include "scene/import/worker_reply.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <functional>

using namespace glint;
using namespace glint::test;

namespace {

const std::filesystem::path kData = GLINT_TEST_DATA_DIR;

ImportOptions withBuiltWorker() {
    ImportOptions options;
    options.workerPath = GLINT_IMPORT_WORKER;
    options.timeout = std::chrono::seconds(30);
    return options;
}

// The worker reads GLINT_IMPORT_WORKER_TEST and misbehaves as asked; the child inherits it.
class WorkerTestMode {
public:
    explicit WorkerTestMode(const char* mode) { qputenv("GLINT_IMPORT_WORKER_TEST", mode); }
    ~WorkerTestMode() { qunsetenv("GLINT_IMPORT_WORKER_TEST"); }
    WorkerTestMode(const WorkerTestMode&) = delete;
    WorkerTestMode& operator=(const WorkerTestMode&) = delete;
};

FileError importError(const std::filesystem::path& file, const ImportOptions& options) {
    try {
        importScene(file, options);
    } catch (const FileError& e) {
        return e;
    }
    return FileError(file.string(), "no-error", "the import succeeded");
}

// Deterministic noise: the same "garbage" on every run.
std::string garbageBytes(std::size_t n) {
    std::string bytes(n, '\0');
    std::uint32_t state = 12345;
    for (char& c : bytes) {
        state = state * 1664525u + 1013904223u;
        c = static_cast<char>(state >> 24);
    }
    return bytes;
}

} // namespace

class TestImportProcess : public QObject {
    Q_OBJECT

private slots:
    void missingFileIsNotFound() {
        const FileError e = importError(kData / "import/no-such-file.obj", withBuiltWorker());
        QCOMPARE(e.code(), std::string("not-found"));
        QVERIFY(std::string(e.what()).find("no-such-file.obj: no such file") != std::string::npos);
    }

    void emptyFileIsReportedAsEmpty() {
        QTemporaryDir dir;
        const std::filesystem::path file = dir.filePath("empty.obj").toStdString();
        writeText(file, "");
        const FileError e = importError(file, withBuiltWorker());
        QCOMPARE(e.code(), std::string("empty-file"));
        QCOMPARE(e.file(), file.string());
    }

    void garbageBytesGiveTheImportersMessage() {
        QTemporaryDir dir;
        const std::filesystem::path stl = dir.filePath("garbage.stl").toStdString();
        const std::filesystem::path ply = dir.filePath("garbage.ply").toStdString();
        writeText(stl, garbageBytes(3000));
        writeText(ply, garbageBytes(3000));
        const FileError e = importError(stl, withBuiltWorker());
        QCOMPARE(e.code(), std::string("import-failed"));
        QCOMPARE(e.message(), std::string("Failed to determine STL storage representation for garbage.stl."));
        const FileError f = importError(ply, withBuiltWorker());
        QCOMPARE(f.code(), std::string("import-failed"));
        QVERIFY2(f.message().find("magic number") != std::string::npos, f.what());
    }

    void unknownExtensionIsUnsupported() {
        QTemporaryDir dir;
        const std::filesystem::path file = dir.filePath("model.xyz").toStdString();
        writeText(file, "1 2 3\n");
        QCOMPARE(importError(file, withBuiltWorker()).code(), std::string("unsupported-format"));
    }

    void fileOverTheSizeLimitIsRefused() {
        ImportOptions options = withBuiltWorker();
        options.maxFileBytes = 16;
        QCOMPARE(importError(kData / "import/tetra.stl", options).code(), std::string("too-large"));
    }

    void crashingImporterIsReported() {
        WorkerTestMode mode("crash");
        const auto file = kData / "import/tetra.stl";
        const FileError e = importError(file, withBuiltWorker());
        QCOMPARE(e.code(), std::string("importer-crashed"));
        QCOMPARE(e.message(), std::string("importer crashed (signal 6)"));
        QCOMPARE(e.file(), file.string());
    }

    void hangingImporterTimesOut() {
        WorkerTestMode mode("hang");
        ImportOptions options = withBuiltWorker();
        options.timeout = std::chrono::milliseconds(300);
        QElapsedTimer clock;
        clock.start();
        const FileError e = importError(kData / "import/tetra.stl", options);
        QCOMPARE(e.code(), std::string("importer-timeout"));
        QCOMPARE(e.message(), std::string("importer timed out after 300 ms"));
        QVERIFY(clock.elapsed() < 5000); // the 300 ms timeout fired, with a 16x margin for busy cores
    }

    void endlessOutputIsCapped() {
        WorkerTestMode mode("flood");
        ImportOptions options = withBuiltWorker();
        options.maxResultBytes = 4 << 20;
        const FileError e = importError(kData / "import/tetra.stl", options);
        QCOMPARE(e.code(), std::string("importer-failed"));
        QCOMPARE(e.message(), std::string("importer result is larger than 4194304 bytes"));
    }

    void unreadableReplyIsReported() {
        WorkerTestMode mode("garbage");
        const FileError e = importError(kData / "import/tetra.stl", withBuiltWorker());
        QCOMPARE(e.code(), std::string("importer-failed"));
        QCOMPARE(e.message(), std::string("importer failed (exit status 0, no readable result)"));
    }

    void failedExitIsReported() {
        WorkerTestMode mode("exit");
        const FileError e = importError(kData / "import/tetra.stl", withBuiltWorker());
        QCOMPARE(e.code(), std::string("importer-failed"));
        QCOMPARE(e.message(), std::string("importer failed (exit status 3, no readable result)"));
    }

    void missingWorkerIsReported() {
        QTemporaryDir dir;
        ImportOptions options = withBuiltWorker();
        options.workerPath = dir.filePath("no-worker-here").toStdString();
        const FileError e = importError(kData / "import/tetra.stl", options);
        QCOMPARE(e.code(), std::string("worker-not-found"));
    }

    void replyFramingRoundTripsAndRejectsDamage() {
        WorkerReply reply;
        reply.warnings.push_back({"", "missing-texture", "texture 'a.png' not found"});
        reply.glb = {1, 2, 3, 4, 5};
        const auto bytes = encodeWorkerReply(reply);
        auto decoded = decodeWorkerReply(bytes);
        QVERIFY(decoded);
        QCOMPARE(decoded->glb, reply.glb);
        QVERIFY(decoded->warnings == reply.warnings);
        QVERIFY(decoded->errorCode.empty());
        for (std::size_t cut : {std::size_t(0), std::size_t(7), std::size_t(20), bytes.size() - 1})
            QVERIFY(!decodeWorkerReply(std::span(bytes.data(), cut)));
        auto longer = bytes;
        longer.push_back(0);
        QVERIFY(!decodeWorkerReply(longer));

        WorkerReply failure;
        failure.errorCode = "import-failed";
        failure.errorMessage = "bad file";
        decoded = decodeWorkerReply(encodeWorkerReply(failure));
        QVERIFY(decoded);
        QCOMPARE(decoded->errorCode, std::string("import-failed"));
        QCOMPARE(decoded->errorMessage, std::string("bad file"));
    }

    // Found by fuzz_import_reply (seeds/import_reply/crash-error-is-an-array.bin): a header whose
    // "error" was an array threw nlohmann's type_error out of decodeWorkerReply, past importScene's
    // FileError. A header of the wrong shape is now a malformed reply, and an error never reads as
    // success.
    void replyHeaderOfTheWrongShapeIsRefused() {
        const auto framed = [](const std::string& header) {
            std::vector<std::uint8_t> bytes = {'G', 'L', 'I', 'N', 'T', 'I', 'M', 'P', 1, 0, 0, 0};
            for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(header.size() >> (8 * i)));
            bytes.insert(bytes.end(), header.begin(), header.end());
            bytes.insert(bytes.end(), 8, 0); // an empty GLB
            return bytes;
        };
        QVERIFY(decodeWorkerReply(framed(R"({"warnings":[]})")));
        for (const char* bad : {R"({"error":[],"warnings":[]})", R"({"error":{"code":7},"warnings":[]})",
                                R"({"error":{"message":null},"warnings":[]})", R"({"warnings":[{"code":[]}]})",
                                R"({"warnings":[{"message":1.5}]})"})
            QVERIFY2(!decodeWorkerReply(framed(bad)), bad);
        const auto blank = decodeWorkerReply(framed(R"({"error":{"code":"","message":"m"},"warnings":[]})"));
        QVERIFY(blank);
        QCOMPARE(blank->errorCode, std::string("import-failed"));
    }

    void bunnyArrivesThroughTheWorker() {
        const auto file = kData / "meshes/stanford-bunny.obj";
        QElapsedTimer clock;
        clock.start();
        LoadResult r = importScene(file, withBuiltWorker());
        qInfo("bunny import through the worker: %lld ms", static_cast<long long>(clock.elapsed()));
        QCOMPARE(totalTriangles(r.scene), std::size_t(69451));
        QCOMPARE(totalVertices(r.scene), std::size_t(34834)); // distinct positions (test_import_convert derives it)
        QVERIFY(r.warnings.empty());
    }

    void colladaUnitsSurviveTheHandOver() {
        LoadResult r = importScene(kData / "import/triangle_zup_cm.dae", withBuiltWorker());
        const auto world = worldPositions(r.scene);
        QCOMPARE(world.size(), std::size_t(3));
        QVERIFY(glm::length(world[1] - glm::vec3(1, 0, 0)) < 1e-5f);
        QVERIFY(glm::length(world[2] - glm::vec3(0, 2, 0)) < 1e-5f);
    }

    void textureBytesAndWarningsSurviveTheHandOver() { // and are not repeated
        QTemporaryDir dir;
        const std::filesystem::path folder = dir.path().toStdString();
        std::filesystem::copy_file(kData / "meshes/spot/spot_texture.png", folder / "spot_texture.png");
        writeText(folder / "m.mtl", "newmtl a\nmap_Kd spot_texture.png\nnewmtl b\nmap_Kd gone.png\n");
        writeText(folder / "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                    "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 2/2\n");
        LoadResult r = importScene(folder / "m.obj", withBuiltWorker());
        QCOMPARE(totalTriangles(r.scene), std::size_t(2));
        bool found = false;
        for (const auto& [id, image] : r.scene.images)
            if (!image.missing) found = found || image.encoded == readBytes(folder / "spot_texture.png");
        QVERIFY(found);
        // gone.png is named once, by the importer: not again when the transfer GLB is read, nor as
        // an image without bytes in that GLB.
        const auto missing = std::count_if(r.warnings.begin(), r.warnings.end(), [](const Warning& w) { return w.code == "missing-texture"; });
        QCOMPARE(missing, 1);
        QVERIFY(!hasWarning(r.warnings, "image-bytes-missing"));
        for (const Warning& w : r.warnings) QCOMPARE(w.file, (folder / "m.obj").string());
    }
};

QTEST_APPLESS_MAIN(TestImportProcess)
#include "test_import_process.moc"
