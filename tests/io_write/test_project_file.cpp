// The project file and the number formatting under it: shortest floats, any locale, unknown keys
// kept, wrong types and newer schemas refused with errors that name the key.
#include "scene/io/json/json_numbers.h"
#include "scene/io/project/project_file.h"

#include <QtTest>

#include <clocale>

using namespace glint;
using nlohmann::json;

namespace {

ProjectFile sampleProject()
{
    ProjectFile p;
    p.sceneFile = "shot.gltf";
    p.settings.activeCamera = NodeId{7};
    p.settings.render.exposure = 0.1f;
    p.settings.render.seed = 4000000000u;
    p.settings.render.tonemapper = Tonemapper::PbrNeutral;
    p.settings.render.bloom = {.strength = 0.25f, .radius = 0.1f};
    p.settings.render.shutter = 0.5f;
    p.settings.render.sampleBlock = 4;
    p.settings.render.adaptive = {.threshold = 0.02f, .minSamples = 48, .goal = AdaptiveGoal::Mean};
    p.settings.environment = {.file = "studio.hdr", .color = {0.1f, 0.2f, 0.3f}, .intensity = 1.5f, .rotationDegrees = 33.3f};
    p.settings.timeline = {.start = 0.5, .end = 10.1, .fpsNumerator = 24000, .fpsDenominator = 1001};
    p.settings.output = {.path = "frames/shot_####.exr", .aovs = "none", .passes = "light,Vector", .codec = "prores"};
    p.settings.lightUnits = LightUnits::Raw;
    p.settings.fog = {.density = 0.05f, .color = {0.9f, 0.8f, 0.7f}, .anisotropy = -0.3f, .heightFalloff = 0.25f, .baseHeight = -1.5f};
    return p;
}

std::string expectError(const std::string& text)
{
    Warnings warnings;
    try {
        parseProjectFile(text, "p.glint.json", warnings);
    } catch (const FileError& e) {
        return e.code() + ": " + e.message();
    }
    return "no error";
}

} // namespace

class TestProjectFile : public QObject {
    Q_OBJECT

private slots:
    void floatsPrintAsShortestDecimals()
    {
        QCOMPARE(deterministicJsonText(jsonFloat(0.1f), -1), std::string("0.1"));
        QCOMPARE(deterministicJsonText(jsonFloat(1.0f / 3.0f), -1), std::string("0.33333334"));
        QCOMPARE(deterministicJsonText(jsonFloat(16777216.0f), -1), std::string("16777216"));
        QCOMPARE(deterministicJsonText(jsonFloat(1e-7f), -1), std::string("1e-07"));
        QCOMPARE(deterministicJsonText(jsonFloat(-2.5f), -1), std::string("-2.5"));
        QCOMPARE(deterministicJsonText(jsonFloat(3.4028235e38f), -1), std::string("3.4028235e+38"));
        QCOMPARE(deterministicJsonText(jsonFloat(std::numeric_limits<float>::infinity()), -1), std::string("null"));
        QCOMPARE(deterministicJsonText(json(0.1), -1), std::string("0.1"));
        QCOMPARE(deterministicJsonText(jsonFloat(-0.0f), -1), std::string("0"));
        QCOMPARE(deterministicJsonText(json(0.1f), -1), std::string("0.10000000149011612")); // why jsonFloat exists
    }

    void everyFloatReadsBack()
    {
        // A spread of bit patterns: the printed decimal parses back to the very same float.
        for (std::uint32_t bits = 0x00800000u; bits < 0x7f800000u; bits += 0x00f0f0f1u) {
            float f = 0.0f;
            std::memcpy(&f, &bits, sizeof f);
            const std::string text = deterministicJsonText(jsonFloat(f), -1);
            QCOMPARE(json::parse(text).get<float>(), f);
        }
    }

    void textIsSortedAndLocaleIndependent()
    {
        const std::string before = writeProjectFileText(sampleProject());
        QVERIFY2(std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr,
                 "the locale de_DE.UTF-8 is missing: generate it (localedef -i de_DE -f UTF-8 de_DE.UTF-8)");
        const std::string german = writeProjectFileText(sampleProject());
        std::setlocale(LC_ALL, "C");
        QCOMPARE(german, before);
        QVERIFY(before.find("\"exposure\": 0.1,") != std::string::npos);
        QVERIFY(before.find("\"rotation\": 33.3") != std::string::npos);
        QVERIFY(before.find("\"fps\": [24000, 1001]") != std::string::npos);
        QVERIFY(before.find("\"activeCamera\": 7") < before.find("\"environment\"")); // sorted keys
        QVERIFY(before.ends_with("}\n"));
    }

    void roundTripsExactly()
    {
        const ProjectFile original = sampleProject();
        Warnings warnings;
        const ProjectFile parsed = parseProjectFile(writeProjectFileText(original), "p.glint.json", warnings);
        QVERIFY(warnings.empty());
        QCOMPARE(parsed.sceneFile, original.sceneFile);
        QVERIFY(parsed.settings == original.settings);
        QCOMPARE(writeProjectFileText(parsed), writeProjectFileText(original));
        QVERIFY(writeProjectFileText(original).find(R"("passes": "light,Vector")") != std::string::npos);
        QVERIFY(writeProjectFileText(original).find(R"("sampleBlock": 4)") != std::string::npos);
        // No passes and no sample blocks (the defaults): no keys, so files saved before they existed
        // keep their bytes.
        QVERIFY(writeProjectFileText(ProjectFile{}).find("passes") == std::string::npos);
        QVERIFY(writeProjectFileText(ProjectFile{}).find("sampleBlock") == std::string::npos);
    }

    // A fog is written whole and reads back to the same bytes; without one there is no "fog" key,
    // so projects saved before fog existed keep their bytes.
    void fogRoundTripsAndIsLeftOutWhenDefault()
    {
        ProjectFile foggy;
        foggy.settings.fog = {.density = 0.1f, .color = {1.0f, 0.5f, 0.25f}, .anisotropy = 0.99f, .heightFalloff = 0.3f, .baseHeight = 2.0f};
        const std::string text = writeProjectFileText(foggy);
        QVERIFY(text.find(R"("fog": {)") != std::string::npos);
        QVERIFY(text.find(R"("heightFalloff": 0.3)") != std::string::npos);
        Warnings warnings;
        const ProjectFile parsed = parseProjectFile(text, "p.glint.json", warnings);
        QVERIFY(warnings.empty());
        QVERIFY(parsed.settings.fog == foggy.settings.fog);
        QCOMPARE(writeProjectFileText(parsed), text);

        QVERIFY(writeProjectFileText(ProjectFile{}).find("fog") == std::string::npos);
        // Any value off its default counts, even with no density yet (an edit in progress is kept).
        ProjectFile colourOnly;
        colourOnly.settings.fog.color = {0.5f, 0.5f, 0.5f};
        QVERIFY(json::parse(writeProjectFileText(colourOnly)).contains("fog"));
        // Keys left out take the defaults.
        const ProjectFile partial = parseProjectFile(R"({"glint": 1, "fog": {"density": 0.5}})", "p.glint.json", warnings);
        QVERIFY(partial.settings.fog == (Fog{.density = 0.5f}));
        QVERIFY(warnings.empty());
    }

    void defaultsFromAMinimalFile()
    {
        Warnings warnings;
        const ProjectFile parsed = parseProjectFile(R"({"glint": 1})", "p.glint.json", warnings);
        QVERIFY(parsed.settings == ProjectSettings{});
        QVERIFY(parsed.sceneFile.empty());
    }

    void unknownKeysAreKeptWithWarnings()
    {
        Warnings warnings;
        const std::string text = R"({"glint": 1, "future": {"a": [1, 2]}, "render": {"spp": 8, "denoiser": "oidn"}})";
        const ProjectFile parsed = parseProjectFile(text, "p.glint.json", warnings);
        QCOMPARE(parsed.settings.render.spp, 8);
        QCOMPARE(warnings.size(), std::size_t{2});
        QCOMPARE(warnings[0].code, std::string("unknown-key"));
        QCOMPARE(warnings[0].file, std::string("p.glint.json"));
        QVERIFY(warnings[1].message.find("'render.denoiser'") != std::string::npos || warnings[0].message.find("'render.denoiser'") != std::string::npos);
        QVERIFY(parsed.settings.unknown == json::parse(R"({"future": {"a": [1, 2]}, "render": {"denoiser": "oidn"}})"));
        const json written = json::parse(writeProjectFileText(parsed));
        QCOMPARE(written["render"]["denoiser"].get<std::string>(), std::string("oidn"));
        QCOMPARE(written["render"]["spp"].get<int>(), 8);
        QVERIFY(written["future"] == json::parse(R"({"a": [1, 2]})"));
    }

    void wrongTypesNameTheKey()
    {
        QCOMPARE(expectError(R"({"glint": 1, "render": {"width": "wide"}})"), std::string("wrong-type: key 'render.width' must be an integer"));
        QCOMPARE(expectError(R"({"glint": 1, "render": {"spp": 1.5}})"), std::string("wrong-type: key 'render.spp' must be an integer"));
        QCOMPARE(expectError(R"({"glint": 1, "environment": {"color": [1, 2]}})"), std::string("wrong-type: key 'environment.color' must be an array of 3 numbers"));
        QCOMPARE(expectError(R"({"glint": 1, "timeline": {"fps": [24, 0]}})"), std::string("wrong-type: key 'timeline.fps' must be [numerator, denominator] with positive integers"));
        QCOMPARE(expectError(R"({"glint": 1, "output": []})"), std::string("wrong-type: key 'output' must be an object"));
        QCOMPARE(expectError(R"({"glint": 1, "activeCamera": -1})"), std::string("wrong-type: key 'activeCamera' must be an integer from 0 to 4294967295"));
        QCOMPARE(expectError(R"({"glint": 1, "lightUnits": "photometric"})"), std::string("bad-value: key 'lightUnits' must be one of blender, raw, not 'photometric'"));
        QCOMPARE(expectError(R"([1])"), std::string("wrong-type: a project file must be a JSON object"));
        QVERIFY(expectError(R"({"glint": 1,)").starts_with("invalid-json: not valid JSON: "));
        QVERIFY(expectError(R"({"glint": 1,)").find("json.exception") == std::string::npos);
        QVERIFY(expectError(std::string(200, '[') + std::string(200, ']')).starts_with("json-too-deep: "));
        QCOMPARE(expectError(R"({"glint": 1, "render": {"exposure": 1e400}})"),
                 std::string("non-finite-value: render.exposure is 1e400, beyond the range of a number"));
    }

    // Render values are checked at load with the command line's ranges, naming the file and the key.
    void valuesOutOfRangeNameTheKey_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        const auto row = [](const char* name, const char* text, const char* error) { QTest::newRow(name) << text << error; };
        row("width 0", R"({"glint": 1, "render": {"width": 0, "height": 0}})", "bad-value: key 'render.width' must be an integer from 1 to 16384");
        row("height huge", R"({"glint": 1, "render": {"height": 100000}})", "bad-value: key 'render.height' must be an integer from 1 to 16384");
        row("spp 0", R"({"glint": 1, "render": {"spp": 0}})", "bad-value: key 'render.spp' must be an integer from 1 to 1048576");
        row("spp days", R"({"glint": 1, "render": {"spp": 2000000000}})", "bad-value: key 'render.spp' must be an integer from 1 to 1048576");
        row("bounces -1", R"({"glint": 1, "render": {"bounces": -1}})", "bad-value: key 'render.bounces' must be an integer from 0 to 1024");
        row("exposure 1e308", R"({"glint": 1, "render": {"exposure": 1e308}})", "bad-value: key 'render.exposure' must be a number of stops from -64 to 64");
        row("clamp -1", R"({"glint": 1, "render": {"clamp": -1}})", "bad-value: key 'render.clamp' must be 0 (off) or a positive number");
        row("shutter 2", R"({"glint": 1, "render": {"shutter": 2}})", "bad-value: key 'render.shutter' must be a fraction of a frame from 0 (off) to 1");
        row("sampleBlock 3", R"({"glint": 1, "render": {"sampleBlock": 3}})", "bad-value: key 'render.sampleBlock' must be 1 (off), 2, 4 or 8");
        row("sampleBlock 16", R"({"glint": 1, "render": {"sampleBlock": 16}})", "bad-value: key 'render.sampleBlock' must be 1 (off), 2, 4 or 8");
        row("adaptive threshold 2", R"({"glint": 1, "render": {"adaptive": {"threshold": 2}}})", "bad-value: key 'render.adaptive.threshold' must be a number from 0 (off) to 1");
        row("adaptive goal median", R"({"glint": 1, "render": {"adaptive": {"goal": "median"}}})", "bad-value: key 'render.adaptive.goal' must be one of even, mean, not 'median'");
        row("adaptive minSpp -1", R"({"glint": 1, "render": {"adaptive": {"minSpp": -1}}})", "bad-value: key 'render.adaptive.minSpp' must be an integer from 0 (automatic) to 1048576");
        row("intensity -5", R"({"glint": 1, "environment": {"intensity": -5}})", "bad-value: key 'environment.intensity' must be a number of at least 0");
        row("colour -1", R"({"glint": 1, "environment": {"color": [0, -1, 0]}})", "bad-value: key 'environment.color' must be 3 numbers of at least 0");
        row("rotation 1e39", R"({"glint": 1, "environment": {"rotation": 1e39}})", "bad-value: key 'environment.rotation' must be a finite number of degrees");
        row("fog density -0.1", R"({"glint": 1, "fog": {"density": -0.1}})", "bad-value: key 'fog.density' must be a number of at least 0 (per metre)");
        row("fog density 1e39", R"({"glint": 1, "fog": {"density": 1e39}})", "bad-value: key 'fog.density' must be a number of at least 0 (per metre)");
        row("fog colour 1.5", R"({"glint": 1, "fog": {"color": [1, 1.5, 1]}})", "bad-value: key 'fog.color' must be 3 numbers from 0 to 1");
        row("fog colour -0.1", R"({"glint": 1, "fog": {"color": [-0.1, 0, 0]}})", "bad-value: key 'fog.color' must be 3 numbers from 0 to 1");
        row("fog colour 2 numbers", R"({"glint": 1, "fog": {"color": [1, 1]}})", "wrong-type: key 'fog.color' must be an array of 3 numbers");
        row("fog anisotropy 1", R"({"glint": 1, "fog": {"anisotropy": 1}})", "bad-value: key 'fog.anisotropy' must be a number from -0.99 to 0.99");
        row("fog anisotropy -0.995", R"({"glint": 1, "fog": {"anisotropy": -0.995}})", "bad-value: key 'fog.anisotropy' must be a number from -0.99 to 0.99");
        row("fog falloff -1", R"({"glint": 1, "fog": {"heightFalloff": -1}})", "bad-value: key 'fog.heightFalloff' must be a number of at least 0 (per metre)");
        row("fog base height 1e39", R"({"glint": 1, "fog": {"baseHeight": 1e39}})", "bad-value: key 'fog.baseHeight' must be a finite number of metres");
        row("fog base height text", R"({"glint": 1, "fog": {"baseHeight": "ground"}})", "wrong-type: key 'fog.baseHeight' must be a number");
        row("fog not an object", R"({"glint": 1, "fog": 0.1})", "wrong-type: key 'fog' must be an object");
    }

    void valuesOutOfRangeNameTheKey()
    {
        QFETCH(QString, text);
        QFETCH(QString, error);
        QCOMPARE(QString::fromStdString(expectError(text.toStdString())), error);
        Warnings warnings;
        try {
            parseProjectFile(text.toStdString(), "shot.glint.json", warnings);
        } catch (const FileError& e) {
            QCOMPARE(QString::fromStdString(e.file()), QStringLiteral("shot.glint.json"));
        }
    }

    void limitsThemselvesAreAllowed()
    {
        Warnings warnings;
        const ProjectFile p = parseProjectFile(
            R"({"glint": 1, "render": {"width": 16384, "height": 1, "spp": 1048576, "bounces": 0, "exposure": -64, "clamp": 0},
                "environment": {"intensity": 0, "color": [0, 0, 0], "rotation": -720}})", "p.glint.json", warnings);
        QCOMPARE(p.settings.render.width, 16384);
        QCOMPARE(p.settings.render.spp, 1048576);
        QCOMPARE(p.settings.render.exposure, -64.0f);
        QCOMPARE(p.settings.environment.rotationDegrees, -720.0f);
        QVERIFY(warnings.empty());
        const ProjectFile fog = parseProjectFile(
            R"({"glint": 1, "fog": {"density": 0, "color": [0, 1, 0], "anisotropy": -0.99, "heightFalloff": 0}})", "p.glint.json", warnings);
        QCOMPARE(fog.settings.fog.anisotropy, -0.99f);
        QVERIFY(fog.settings.fog.color == glm::vec3(0.0f, 1.0f, 0.0f));
        QVERIFY(warnings.empty());
    }

    void schemaVersions()
    {
        QCOMPARE(expectError(R"({"glint": 2})"), std::string("newer-version: written by a newer Glint (project schema 2; this Glint reads up to 1)"));
        QCOMPARE(expectError(R"({"render": {}})"), std::string("not-a-project: not a Glint project file: the schema version 'glint' is missing"));
        QCOMPARE(expectError(R"({"glint": "1"})"), std::string("wrong-type: key 'glint' must be an integer"));
        QCOMPARE(expectError(R"({"glint": 0})"), std::string("bad-version: project schema 0 does not exist"));
    }

    void pathsBesideTheScene()
    {
        QCOMPARE(projectPathFor("a/b.gltf"), std::filesystem::path("a/b.glint.json"));
        QCOMPARE(projectPathFor("b.glb"), std::filesystem::path("b.glint.json"));
        QVERIFY(isProjectPath("dir/x.glint.json"));
        QVERIFY(!isProjectPath("dir/x.json"));
        QVERIFY(!isProjectPath(".glint.json"));
    }
};

QTEST_APPLESS_MAIN(TestProjectFile)
#include "test_project_file.moc"
