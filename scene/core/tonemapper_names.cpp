#include "scene/core/tonemapper_names.h"

#include <algorithm>
#include <cctype>

namespace glint {

std::string_view tonemapperName(Tonemapper tonemapper) {
    switch (tonemapper) {
    case Tonemapper::None: return "none";
    case Tonemapper::AcesFitted: return "aces";
    case Tonemapper::PbrNeutral: return "pbrNeutral";
    case Tonemapper::AgX: return "agx";
    case Tonemapper::Reinhard: return "reinhard";
    case Tonemapper::Hable: return "hable";
    }
    return "none";
}

std::optional<Tonemapper> parseTonemapper(std::string_view name) {
    const auto same = [](std::string_view a, std::string_view b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
                   return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
               });
    };
    for (const Tonemapper t : kTonemappers)
        if (same(name, tonemapperName(t))) return t;
    if (same(name, "neutral")) return Tonemapper::PbrNeutral;
    return std::nullopt;
}

std::string_view tonemapperNames() { return "none, aces, pbrNeutral, agx, reinhard, hable"; }

} // namespace glint
