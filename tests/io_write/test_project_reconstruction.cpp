// The project file's render.taa and render.svgf: written only where they differ from the defaults
// (files that never set them keep their bytes), read back exactly, refused with an error naming the
// key when out of range, and carried by the settings command's JSON (undo logs).
#include "scene/history/settings_commands.h"
#include "scene/history/value_json.h"
#include "scene/io/project/project_file.h"

#include <QtTest>

using namespace glint;
using nlohmann::json;

namespace {

std::string expectError(const std::string& render)
{
    Warnings warnings;
    try {
        parseProjectFile(R"({"glint": 1, "render": )" + render + "}", "p.glint.json", warnings);
    } catch (const FileError& e) {
        return e.code() + ": " + e.message();
    }
    return "no error";
}

ProjectFile tuned()
{
    ProjectFile p;
    p.sceneFile = "shot.gltf";
    p.settings.render.taa = {.blend = 0.05f, .clip = TaaClip::MinMax, .clipGamma = 2.5f, .perceptualBlend = true};
    p.settings.render.svgf.iterations = 3;
    p.settings.render.svgf.sigmaNormal = 0.0f;
    p.settings.render.svgf.fireflyRatio = 16.5f;
    return p;
}

} // namespace

class TestProjectReconstruction : public QObject {
    Q_OBJECT

private slots:
    void defaultsAreNotWritten()
    {
        // The text a project had before these settings existed, byte for byte.
        ProjectFile p;
        p.sceneFile = "shot.gltf";
        const std::string text = writeProjectFileText(p);
        QVERIFY(text.find("taa") == std::string::npos && text.find("svgf") == std::string::npos);
        Warnings warnings;
        const ProjectFile back = parseProjectFile(text, "p.glint.json", warnings);
        QVERIFY(warnings.empty());
        QCOMPARE(writeProjectFileText(back), text);
    }

    void onlyChangedValuesAreWrittenAndReadBack()
    {
        const std::string text = writeProjectFileText(tuned());
        const json render = json::parse(text).at("render");
        QCOMPARE(render.at("taa").dump(), std::string(R"({"blend":0.05,"clip":"minmax","clipGamma":2.5,"perceptualBlend":true})"));
        QCOMPARE(render.at("svgf").dump(), std::string(R"({"fireflyRatio":16.5,"iterations":3,"sigmaNormal":0})"));
        Warnings warnings;
        const ProjectFile back = parseProjectFile(text, "p.glint.json", warnings);
        QVERIFY(warnings.empty());
        QVERIFY(back.settings == tuned().settings);
        QCOMPARE(writeProjectFileText(back), text);
    }

    void unknownKeysInsideAreKept()
    {
        Warnings warnings;
        const ProjectFile p = parseProjectFile(R"({"glint": 1, "render": {"svgf": {"iterations": 2, "future": 1}}})",
                                               "p.glint.json", warnings);
        QCOMPARE(p.settings.render.svgf.iterations, 2);
        QCOMPARE(warnings.size(), std::size_t(1));
        QVERIFY(warnings[0].message.find("render.svgf.future") != std::string::npos);
        QVERIFY(writeProjectFileText(p).find("\"future\": 1") != std::string::npos);
    }

    void badValuesNameTheKey()
    {
        QCOMPARE(expectError(R"({"svgf": {"iterations": 0}})"),
                 std::string("bad-value: key 'render.svgf.iterations' must be an integer from 1 to 10"));
        QCOMPARE(expectError(R"({"svgf": {"iterations": 2.5}})"),
                 std::string("wrong-type: key 'render.svgf.iterations' must be an integer"));
        QCOMPARE(expectError(R"({"taa": {"blend": 0}})"),
                 std::string("bad-value: key 'render.taa.blend' must be greater than 0 and at most 1"));
        QCOMPARE(expectError(R"({"taa": {"blend": 1.5}})"),
                 std::string("bad-value: key 'render.taa.blend' must be greater than 0 and at most 1"));
        QCOMPARE(expectError(R"({"taa": {"clipGamma": -1}})"),
                 std::string("bad-value: key 'render.taa.clipGamma' must be greater than 0 and at most 16"));
        QCOMPARE(expectError(R"({"taa": {"clip": "box"}})"),
                 std::string("bad-value: key 'render.taa.clip' must be one of variance, minmax, none, not 'box'"));
        QCOMPARE(expectError(R"({"taa": {"perceptualBlend": 1}})"),
                 std::string("wrong-type: key 'render.taa.perceptualBlend' must be true or false"));
        QCOMPARE(expectError(R"({"svgf": {"sigmaDepth": 0}})"),
                 std::string("bad-value: key 'render.svgf.sigmaDepth' must be a positive number"));
        QCOMPARE(expectError(R"({"svgf": {"sigmaLuminance": 1e39}})"),
                 std::string("bad-value: key 'render.svgf.sigmaLuminance' must be a positive number"));
        QCOMPARE(expectError(R"({"svgf": {"fireflyRatio": 0.5}})"),
                 std::string("bad-value: key 'render.svgf.fireflyRatio' must be a number of at least 1"));
        QCOMPARE(expectError(R"({"svgf": {"alpha": 2}})"),
                 std::string("bad-value: key 'render.svgf.alpha' must be greater than 0 and at most 1"));
        QCOMPARE(expectError(R"({"svgf": 5})"), std::string("wrong-type: key 'render.svgf' must be an object"));
    }

    void settingsCommandCarriesThem()
    {
        const SetProjectSettings command(tuned().settings);
        const CommandPtr back = SetProjectSettings::fromJson(command.toJson());
        QCOMPARE(back->toJson(), command.toJson());
        // A log written before these settings existed still replays, with the defaults.
        json old = command.toJson();
        old["settings"]["render"].erase("taa");
        old["settings"]["render"].erase("svgf");
        const ProjectSettings replayed = old.at("settings").get<ProjectSettings>();
        QVERIFY(replayed.render.taa == TaaParameters{});
        QVERIFY(replayed.render.svgf == SvgfParameters{});
    }
};

QTEST_APPLESS_MAIN(TestProjectReconstruction)
#include "test_project_reconstruction.moc"
