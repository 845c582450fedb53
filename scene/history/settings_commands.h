#pragma once
// Edits of the project settings (render, display, environment, active camera, timeline,
// output, light units): the whole ProjectSettings value, old and new. Its change set says
// which sections differ, so that an exposure or tonemapper drag does not restart accumulation.
#include "command.h"

namespace glint {

class SetProjectSettings final : public Command {
public:
    explicit SetProjectSettings(ProjectSettings settings) : new_(std::move(settings)) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Edit settings"; }
    std::string typeName() const override { return "set_project_settings"; }
    std::string mergeKey() const override { return "set_project_settings"; }
    bool mergeWith(const Command& next) override;
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    ProjectSettings new_;
    ProjectSettings old_;
};

// Which sections differ between two settings values.
ChangeSet settingsChange(const ProjectSettings& before, const ProjectSettings& after);

} // namespace glint
