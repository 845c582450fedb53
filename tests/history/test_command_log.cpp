// Commands as JSON: every type survives a round trip, and replaying a session's log on the
// scene it started from reproduces the scene it ended with.
#include "every_command.h"
#include "sample_scene.h"
#include "scene/history/asset_commands.h"
#include "scene/history/command_json.h"
#include "scene/history/history.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

#include <QtTest>

#include <set>

using namespace glint;
using namespace glint::test;

class TestCommandLog : public QObject {
    Q_OBJECT
private slots:
    void everyCommandTypeIsCovered() {
        SampleIds ids;
        sampleScene(&ids);
        std::set<std::string> covered;
        const auto commands = oneOfEachCommand(ids);
        for (const CommandPtr& command : commands) covered.insert(command->typeName());
        std::set<std::string> registered;
        for (const CommandType& type : commandTypes()) registered.insert(std::string(type.name));
        QCOMPARE(covered, registered);
        QCOMPARE(registered.size(), commandTypes().size()); // no name twice
    }

    // Numbers a field cannot hold are refused with an exception, never cast (a cast of 8e85 to a
    // byte is undefined behaviour: fuzz_command_log found it in an image's bytes).
    void numbersOutOfRangeAreRefused() {
        Image image;
        image.name = "tiny";
        image.encoded = std::vector<std::uint8_t>{1, 2, 3};
        const nlohmann::json good = commandToJson(AddAsset<Image>(image, ImageId{9}));
        QCOMPARE(commandToJson(*commandFromJson(good)), good);
        const auto refused = [](nlohmann::json j) {
            try {
                commandFromJson(j);
            } catch (const std::exception&) {
                return true;
            }
            return false;
        };
        nlohmann::json byte = good;
        byte["value"]["encoded"][0] = 8.44444e+85;
        QVERIFY(refused(byte));
        byte["value"]["encoded"][0] = 256;
        QVERIFY(refused(byte));
        byte["value"]["encoded"][0] = -1.5;
        QVERIFY(refused(byte));
        nlohmann::json huge = good;
        huge["value"]["width"] = 1e300;
        QVERIFY(refused(huge));
        nlohmann::json id = good;
        id["id"] = -3;
        QVERIFY(refused(id));
        nlohmann::json integral = good;
        integral["value"]["width"] = 4.0; // an integral float is an integer
        QCOMPARE(commandFromJson(integral)->typeName(), std::string("add_image"));
    }

    // The generated readers of value types refuse what an integer field cannot hold, naming the
    // key: a fraction (once cast, -1.5 into an unsigned was undefined and 2.5 became 2) and a
    // negative number for an unsigned field (once -1 became 4294967295).
    void integerFieldsRefuseFractionsAndNegatives() {
        Image image;
        image.name = "tiny";
        image.encoded = std::vector<std::uint8_t>{1, 2, 3};
        const nlohmann::json good = commandToJson(AddAsset<Image>(image, ImageId{9}));
        for (const nlohmann::json& bad : {nlohmann::json(-1.5), nlohmann::json(2.5), nlohmann::json("4")}) {
            nlohmann::json j = good;
            j["value"]["width"] = bad;
            try {
                commandFromJson(j);
                QFAIL(qPrintable(QString::fromStdString("width " + bad.dump() + " was accepted")));
            } catch (const std::invalid_argument& e) {
                QVERIFY2(std::string(e.what()).find("key 'width'") != std::string::npos, e.what());
            }
        }
        RenderSettings render;
        nlohmann::json settings = render;
        for (const double bad : {-1.5, -1.0, 0.5, 4294967296.0}) {
            settings["seed"] = bad;
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)settings.get<RenderSettings>());
        }
        settings["seed"] = -1; // as an integer too
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)settings.get<RenderSettings>());
        settings["seed"] = 4294967295.0;
        QCOMPARE(settings.get<RenderSettings>().seed, 4294967295u);
        settings.erase("seed"); // a missing key keeps the default
        QCOMPARE(settings.get<RenderSettings>().seed, render.seed);
    }

    void everyCommandRoundTripsThroughJsonText_data() {
        QTest::addColumn<int>("position");
        SampleIds ids;
        sampleScene(&ids);
        const auto commands = oneOfEachCommand(ids);
        for (std::size_t i = 0; i < commands.size(); ++i)
            QTest::newRow((std::to_string(i) + " " + commands[i]->typeName()).c_str()) << static_cast<int>(i);
    }

    // Applied first, so that ids a first apply assigns are part of the JSON too.
    void everyCommandRoundTripsThroughJsonText() {
        QFETCH(int, position);
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        auto commands = oneOfEachCommand(ids);
        for (int i = 0; i < position; ++i) commands[static_cast<std::size_t>(i)]->apply(scene);
        Command& command = *commands[static_cast<std::size_t>(position)];
        command.interaction = 7;
        Scene replayed = scene;
        command.apply(scene);

        const nlohmann::json written = commandToJson(command);
        const CommandPtr read = commandFromJson(nlohmann::json::parse(written.dump()));
        QCOMPARE(read->typeName(), command.typeName());
        QCOMPARE(read->interaction, std::uint64_t{7});
        QCOMPARE(read->label().empty(), false);
        QCOMPARE(commandToJson(*read), written);
        read->apply(replayed);
        QVERIFY(replayed == scene);
    }

    void replayingALogReproducesTheSession() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        for (CommandPtr& command : oneOfEachCommand(ids)) history.push(std::move(command));
        const std::uint64_t drag = history.beginInteraction();
        for (int i = 0; i < 3; ++i) {
            auto move = std::make_unique<SetTransform>(ids.camera, Transform{.translation = {float(i), 0, 0}});
            move->interaction = drag;
            history.push(std::move(move));
        }
        const std::string text = history.log().dump(1);

        Scene replayed = sampleScene();
        const ChangeSet changes = replayLog(replayed, nlohmann::json::parse(text));
        QVERIFY(replayed == scene);
        QVERIFY(changes.has(Change::Structure) && changes.has(Change::Material) && changes.has(Change::Animation));
    }

    void anUnknownTypeIsNamedInTheError() {
        try {
            commandFromJson({{"type", "paint_everything"}, {"interaction", 0}});
            QFAIL("an unknown type was accepted");
        } catch (const std::invalid_argument& error) {
            QCOMPARE(QString(error.what()), QString("unknown command type \"paint_everything\""));
        }
    }

    void aMissingFieldIsAnError() {
        QVERIFY_THROWS_EXCEPTION(nlohmann::json::exception,
                                 commandFromJson({{"type", "rename_node"}, {"interaction", 0}, {"node", 3}}));
    }

    // Fields added after logs were first written: their JSON carries them, and a log without them
    // (written before fog and volume scattering existed) still replays, with the defaults.
    void fogAndScatteringRoundTripAndMayBeMissing() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        ProjectSettings settings = scene.settings;
        settings.fog = {.density = 0.25f, .color = {0.5f, 0.75f, 1.0f}, .anisotropy = -0.5f, .heightFalloff = 0.1f, .baseHeight = 3.0f};
        nlohmann::json settingsJson = commandToJson(SetProjectSettings(settings));
        QVERIFY(settingsJson.dump().find("heightFalloff") != std::string::npos);
        commandFromJson(nlohmann::json::parse(settingsJson.dump()))->apply(scene);
        QVERIFY(scene.settings.fog == settings.fog);
        settingsJson["settings"].erase("fog");
        commandFromJson(settingsJson)->apply(scene);
        QVERIFY(scene.settings.fog == Fog{});

        Material red = scene.materials.at(ids.red);
        red.scatterColor = {0.25f, 0.5f, 1.0f};
        red.scatterAnisotropy = 0.75f;
        nlohmann::json materialJson = commandToJson(SetAsset<Material>(ids.red, red));
        commandFromJson(nlohmann::json::parse(materialJson.dump()))->apply(scene);
        QVERIFY(scene.materials.at(ids.red) == red);
        materialJson["value"].erase("scatterColor");
        materialJson["value"].erase("scatterAnisotropy");
        commandFromJson(materialJson)->apply(scene);
        QVERIFY(scene.materials.at(ids.red).scatterColor == glm::vec3(0.0f));
        QCOMPARE(scene.materials.at(ids.red).scatterAnisotropy, 0.0f);
    }

    // Every render setting survives a log (shutter and adaptive sampling were once left out, so
    // replaying a log dropped them); a log without them replays with the defaults.
    void everyRenderSettingSurvivesTheLog() {
        ProjectSettings settings;
        settings.render.shutter = 0.5f;
        settings.render.adaptive = {.threshold = 0.02f, .minSamples = 48, .goal = AdaptiveGoal::Mean};
        settings.render.bloom.strength = 0.25f;
        const nlohmann::json written = commandToJson(SetProjectSettings(settings));
        Scene scene;
        commandFromJson(nlohmann::json::parse(written.dump()))->apply(scene);
        QVERIFY(scene.settings.render == settings.render);
        nlohmann::json old = written;
        old["settings"]["render"].erase("shutter");
        old["settings"]["render"].erase("adaptive");
        commandFromJson(old)->apply(scene);
        QCOMPARE(scene.settings.render.shutter, 0.0f);
        QVERIFY(scene.settings.render.adaptive == AdaptiveSampling{});
    }

    void infiniteAttenuationDistanceSurvives() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        QVERIFY(std::isinf(scene.materials.at(ids.red).attenuationDistance)); // the glTF default
        auto command = commandFromJson(nlohmann::json::parse(
            commandToJson(SetAsset<Material>(ids.red, scene.materials.at(ids.red))).dump()));
        command->apply(scene);
        QVERIFY(scene == sampleScene());
    }
};

QTEST_APPLESS_MAIN(TestCommandLog)
#include "test_command_log.moc"
