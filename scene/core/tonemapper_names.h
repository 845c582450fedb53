#pragma once
// The tonemappers' names, one spelling everywhere: the project file, `--tonemap`, EXR metadata and
// the settings hash. Parsing is case-insensitive and also takes "neutral", the command line's and the
// metadata's spelling of pbrNeutral before the names were unified.
#include "scene/core/settings.h"

#include <array>
#include <optional>
#include <string_view>

namespace glint {

inline constexpr std::array<Tonemapper, 6> kTonemappers{Tonemapper::None,     Tonemapper::AcesFitted, Tonemapper::PbrNeutral,
                                                       Tonemapper::AgX,      Tonemapper::Reinhard,   Tonemapper::Hable};

std::string_view tonemapperName(Tonemapper tonemapper); // "none", "aces", "pbrNeutral", "agx", "reinhard", "hable"
std::optional<Tonemapper> parseTonemapper(std::string_view name);
// "none, aces, pbrNeutral, agx, reinhard, hable", for messages and --help.
std::string_view tonemapperNames();

} // namespace glint
