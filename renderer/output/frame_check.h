#pragma once
// Whether a frame already on disk can be kept (--resume): it must decode completely (a file cut
// short by a crash or a full disk does not) and carry the settings hash of the render asked for.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace glint::renderer {

// The settings hash recorded in an image Glint wrote, when the whole image decodes; nullopt for
// a missing, truncated or foreign file.
std::optional<std::string> completeFrameSettingsHash(const std::filesystem::path& file);

// The string attributes "glint:<key>" of an image's header (empty when unreadable).
std::map<std::string, std::string> readGlintMetadata(const std::filesystem::path& file);

} // namespace glint::renderer
