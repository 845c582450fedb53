// The undo property: 10,000 random commands (fixed seed), then undo all gives the start scene
// (equal, and saved byte for byte the same), redo all gives the end scene, the session's log
// replays to the end scene, and the same seed gives the same session.
#include "random_session.h"
#include "sample_scene.h"
#include "scene/history/command_json.h"
#include "scene/history/history.h"
#include "scene/io/scene_io.h"

#include <QtTest>

using namespace glint;
using namespace glint::test;

namespace {

constexpr std::uint32_t kSeed = 20261122;
constexpr std::size_t kCommands = 10000;
// Deep enough that no bound drops a step of the session.
constexpr HistoryLimits kUnbounded{.maxDepth = kCommands + 1, .maxBytes = std::size_t{1} << 40};

struct Session {
    Scene start;
    Scene scene;
    std::unique_ptr<History> history;
    SessionStats stats;
    Scene end;
};

std::unique_ptr<Session> recordSession(std::uint32_t seed) {
    auto session = std::make_unique<Session>();
    session->start = sampleScene();
    session->scene = session->start;
    session->history = std::make_unique<History>(session->scene, kUnbounded);
    session->stats = runRandomSession(*session->history, session->scene, seed, kCommands);
    session->end = session->scene;
    return session;
}

void undoAll(History& history) {
    while (history.canUndo()) history.undo();
}

void redoAll(History& history) {
    while (history.canRedo()) history.redo();
}

} // namespace

class TestUndoProperty : public QObject {
    Q_OBJECT
    std::unique_ptr<Session> session_;

private slots:
    void initTestCase() {
        session_ = recordSession(kSeed);
        QCOMPARE(session_->stats.pushes, kCommands);
        qInfo("%zu commands, %zu undos, %zu redos, %zu steps on the stack, %zu nodes at the end", session_->stats.pushes,
              session_->stats.undos, session_->stats.redos, session_->history->count(), session_->end.nodeCount());
    }

    void theSessionUsesEveryCommandType() {
        for (const CommandType& type : commandTypes())
            QVERIFY2(session_->stats.commandsByType.count(std::string(type.name)) != 0, type.name.data());
        QVERIFY(session_->stats.undos > 100);
        QVERIFY(session_->stats.redos > 100);
        QVERIFY(!(session_->end == session_->start));
    }

    void undoAllGivesTheStartAndRedoAllTheEnd() {
        History& history = *session_->history;
        undoAll(history);
        QCOMPARE(history.index(), std::size_t{0});
        QVERIFY(session_->scene == session_->start);
        redoAll(history);
        QVERIFY(session_->scene == session_->end);
    }

    void undoAllSavesByteIdenticalGlb() {
        History& history = *session_->history;
        const std::vector<std::uint8_t> startBytes = writeGlb(session_->start);
        const std::vector<std::uint8_t> endBytes = writeGlb(session_->end);
        QVERIFY(startBytes != endBytes);
        undoAll(history);
        QVERIFY(writeGlb(session_->scene) == startBytes);
        redoAll(history);
        QVERIFY(writeGlb(session_->scene) == endBytes);
    }

    void jumpingToEveryHundredthStepAndBackIsExact() {
        History& history = *session_->history;
        for (std::size_t index = history.count(); index > 0; index = index > 100 ? index - 100 : 0) history.jumpTo(index);
        history.jumpTo(0);
        QVERIFY(session_->scene == session_->start);
        history.jumpTo(history.count());
        QVERIFY(session_->scene == session_->end);
    }

    void replayingTheLogGivesTheEnd() {
        Scene replayed = session_->start;
        replayLog(replayed, nlohmann::json::parse(session_->history->log().dump()));
        QVERIFY(replayed == session_->end);
    }

    void theSameSeedGivesTheSameSession() {
        const auto again = recordSession(kSeed);
        QVERIFY(again->end == session_->end);
        QCOMPARE(again->history->log(), session_->history->log());
        QCOMPARE(again->stats.commandsByType, session_->stats.commandsByType);

        const auto other = recordSession(kSeed + 1);
        QVERIFY(!(other->end == session_->end));
    }
};

QTEST_APPLESS_MAIN(TestUndoProperty)
#include "test_undo_property.moc"
