// Fuzzes the undo/command log: JSON text -> commands -> applied to the sample scene and reverted.
// Exceptions are clean rejections (a malformed log, a command whose target does not exist); a
// command that applied must revert to exactly the scene before it. Anything else is a bug.
#include "tests/history/sample_scene.h"
#include "scene/history/command_json.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const glint::Scene start = glint::test::sampleScene();
    nlohmann::json log;
    try {
        log = nlohmann::json::parse(data, data + size);
    } catch (const std::exception&) {
        return 0;
    }
    if (!log.is_array()) return 0;
    glint::Scene scene = start;
    for (const nlohmann::json& entry : log) {
        glint::CommandPtr command;
        try {
            command = glint::commandFromJson(entry);
        } catch (const std::exception&) {
            continue;
        }
        const glint::Scene before = scene;
        try {
            command->apply(scene);
        } catch (const std::exception&) {
            scene = before; // refused: the next command starts from the scene as it was
            continue;
        }
        glint::Scene reverted = scene;
        command->revert(reverted);
        if (!(reverted == before)) std::abort(); // undo must restore exactly
        (void)glint::commandToJson(*command);
    }
    return 0;
}
