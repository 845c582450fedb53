#pragma once
// A random editing session on a History: single commands, drags (several edits with one
// interaction serial), macros, undos and redos, all from one seed.
#include "random_source.h"
#include "scene/history/history.h"

#include <map>
#include <string>

namespace glint::test {

struct SessionStats {
    std::size_t pushes = 0;
    std::size_t undos = 0;
    std::size_t redos = 0;
    std::map<std::string, std::size_t> commandsByType; // "macro" counts macros
};

// Pushes `commandCount` commands (plus undos and redos in between), then redoes what is left
// undone, so the scene ends at the top of the stack.
SessionStats runRandomSession(History& history, const Scene& scene, std::uint32_t seed, std::size_t commandCount);

} // namespace glint::test
