#include "settings_commands.h"

#include "value_json.h"

namespace glint {

ChangeSet settingsChange(const ProjectSettings& before, const ProjectSettings& after) {
    ChangeSet changes;
    // Exposure and tonemapping act after accumulation: compare the rest with them equalised.
    RenderSettings renderWithoutDisplay = after.render;
    renderWithoutDisplay.exposure = before.render.exposure;
    renderWithoutDisplay.tonemapper = before.render.tonemapper;
    renderWithoutDisplay.bloom = before.render.bloom;
    if (renderWithoutDisplay != before.render || before.lightUnits != after.lightUnits) changes.add(Change::Settings);
    if (before.render.exposure != after.render.exposure || before.render.tonemapper != after.render.tonemapper ||
        before.render.bloom != after.render.bloom)
        changes.add(Change::Display);
    // Fog is part of what the renderer uploads with the environment (its medium and shader
    // variant): a fog edit re-uploads the scene as an environment edit does.
    if (before.environment != after.environment || before.fog != after.fog) changes.add(Change::Environment);
    if (before.activeCamera != after.activeCamera) {
        changes.add(Change::Camera);
        for (NodeId camera : {before.activeCamera, after.activeCamera})
            if (camera) changes.nodes.insert(camera);
    }
    if (before.timeline != after.timeline || before.output != after.output || before.unknown != after.unknown)
        changes.add(Change::Project);
    return changes;
}

ChangeSet SetProjectSettings::apply(Scene& scene) {
    old_ = scene.settings;
    scene.settings = new_;
    return settingsChange(old_, new_);
}

ChangeSet SetProjectSettings::revert(Scene& scene) {
    scene.settings = old_;
    return settingsChange(new_, old_);
}

bool SetProjectSettings::mergeWith(const Command& next) {
    const auto* same = dynamic_cast<const SetProjectSettings*>(&next);
    if (!same) return false;
    new_ = same->new_;
    return true;
}

nlohmann::json SetProjectSettings::toJson() const { return {{"settings", new_}}; }

CommandPtr SetProjectSettings::fromJson(const nlohmann::json& j) {
    return std::make_unique<SetProjectSettings>(j.at("settings").get<ProjectSettings>());
}

} // namespace glint
