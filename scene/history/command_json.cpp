#include "command_json.h"

#include "checked_numbers.h"

#include "asset_commands.h"
#include "camera_path_commands.h"
#include "macro_command.h"
#include "material_commands.h"
#include "node_commands.h"
#include "set_node_field.h"
#include "settings_commands.h"

#include <stdexcept>
#include <string>

namespace glint {

std::span<const CommandType> commandTypes() {
    static constexpr CommandType types[] = {
        {"add_node", &AddNode::fromJson},
        {"remove_node", &RemoveNode::fromJson},
        {"duplicate_node", &DuplicateNode::fromJson},
        {"reparent_node", &ReparentNode::fromJson},
        {"rename_node", &RenameNode::fromJson},
        {"set_transform", &SetTransform::fromJson},
        {"set_visibility", &SetVisibility::fromJson},
        {"set_component", &SetComponent::fromJson},
        {"add_mesh", &AddAsset<Mesh>::fromJson},
        {"add_material", &AddAsset<Material>::fromJson},
        {"add_texture", &AddAsset<Texture>::fromJson},
        {"add_image", &AddAsset<Image>::fromJson},
        {"add_sampler", &AddAsset<Sampler>::fromJson},
        {"remove_mesh", &RemoveAsset<Mesh>::fromJson},
        {"remove_material", &RemoveAsset<Material>::fromJson},
        {"remove_texture", &RemoveAsset<Texture>::fromJson},
        {"remove_image", &RemoveAsset<Image>::fromJson},
        {"remove_sampler", &RemoveAsset<Sampler>::fromJson},
        {"set_mesh", &SetAsset<Mesh>::fromJson},
        {"set_material", &SetAsset<Material>::fromJson},
        {"set_texture", &SetAsset<Texture>::fromJson},
        {"set_image", &SetAsset<Image>::fromJson},
        {"set_sampler", &SetAsset<Sampler>::fromJson},
        {"set_primitive_material", &SetPrimitiveMaterial::fromJson},
        {"add_animation", &AddAsset<Animation>::fromJson},
        {"remove_animation", &RemoveAsset<Animation>::fromJson},
        {"set_animation", &SetAsset<Animation>::fromJson},
        {"add_camera_key", &AddCameraKey::fromJson},
        {"remove_camera_key", &RemoveCameraKey::fromJson},
        {"move_camera_key", &MoveCameraKey::fromJson},
        {"edit_camera_key", &EditCameraKey::fromJson},
        {"set_camera_path_mode", &SetCameraPathMode::fromJson},
        {"set_project_settings", &SetProjectSettings::fromJson},
        {"macro", &MacroCommand::fromJson},
    };
    return types;
}

nlohmann::json commandToJson(const Command& command) {
    nlohmann::json j = command.toJson();
    j["type"] = command.typeName();
    j["interaction"] = command.interaction;
    return j;
}

CommandPtr commandFromJson(const nlohmann::json& entry) {
    const nlohmann::json j = safeNumbers(entry); // a log may come from anywhere: no number cast is undefined
    const std::string type = j.at("type").get<std::string>();
    for (const CommandType& known : commandTypes()) {
        if (known.name != type) continue;
        CommandPtr command = known.fromJson(j);
        command->interaction = checkedNumber<std::uint64_t>(j.at("interaction"));
        return command;
    }
    throw std::invalid_argument("unknown command type \"" + type + "\"");
}

ChangeSet replayLog(Scene& scene, const nlohmann::json& log) {
    ChangeSet changes;
    for (const nlohmann::json& entry : log) changes.merge(commandFromJson(entry)->apply(scene));
    return changes;
}

} // namespace glint
