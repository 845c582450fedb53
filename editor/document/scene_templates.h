#pragma once
// What File > New starts from. Studio (the default): a ground plane, a camera framing it and the
// studio HDR environment that ships with Glint; Sun and sky: the ground under a sun and a blue sky;
// Cornell box: the bundled sample (also in fog); Portals: the sunlit ground with a portal pair that
// looks onto a corner out of the camera's view (docs/PORTALS.md); Empty: nothing (the viewport says why it is black). The shipped
// files are compiled into the editor and written once to the user's data folder, so an untitled
// scene can name them by absolute path until its first save copies them beside it.
#include "scene/core/scene.h"

#include <QString>

#include <array>

namespace glint::editor {

enum class SceneTemplate { Studio, Empty, SunAndSky, CornellBox, CornellBoxInFog, Portals };
inline constexpr std::array<SceneTemplate, 6> kSceneTemplates{SceneTemplate::Studio, SceneTemplate::Empty,
                                                              SceneTemplate::SunAndSky, SceneTemplate::CornellBox,
                                                              SceneTemplate::CornellBoxInFog, SceneTemplate::Portals};

// The menu text, untranslated (QT_TRANSLATE_NOOP in context glint::editor::SceneTemplates).
const char* templateTitle(SceneTemplate kind);
// The object name of its File > New action ("file.new.studio", ...).
const char* templateActionId(SceneTemplate kind);

// Throws std::runtime_error when a shipped file cannot be written to the data folder.
Scene buildTemplate(SceneTemplate kind);

// `settings` lit as the Studio template is: its shipped HDR environment and the exposure that suits
// it (Add > Light > Studio environment). Throws as buildTemplate does.
ProjectSettings withStudioLighting(ProjectSettings settings);

} // namespace glint::editor
