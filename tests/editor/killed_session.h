#pragma once
// The editing session that test_editor_killed runs in a child process and kills: seeded random
// commands pushed one per step into the editor's document; every 5th step is saved to the scene
// file, every other 3rd step autosaved, each reported on stdout ("saved N", "autosaved N") once it
// is complete. replaySession() repeats the first N steps on a document opened from the same start.
#include "editor/document/document.h"

#include "tests/history/random_commands.h"
#include "tests/history/random_source.h"

#include <cstdint>
#include <optional>

namespace glint::editor::test {

enum class SessionEvent { None, Save, Autosave };

// What the session does after step `step` (1-based).
inline SessionEvent sessionEventAfter(int step) {
    if (step % 5 == 0) return SessionEvent::Save;
    if (step % 3 == 0) return SessionEvent::Autosave;
    return SessionEvent::None;
}

// One step: a random command for the document's scene; one that the scene refuses is skipped,
// the same way in the session and in its replay.
inline void sessionStep(Document& document, glint::test::RandomSource& random) {
    try {
        document.push(glint::test::randomCommand(random, document.scene()));
    } catch (const std::exception&) {
    }
}

inline void replaySession(Document& document, std::uint32_t seed, int steps) {
    glint::test::RandomSource random(seed);
    for (int i = 0; i < steps; ++i) sessionStep(document, random);
}

} // namespace glint::editor::test
