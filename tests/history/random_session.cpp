#include "random_session.h"

#include "random_commands.h"

namespace glint::test {
namespace {

class Session {
public:
    Session(History& history, const Scene& scene, std::uint32_t seed) : history_(history), scene_(scene), random_(seed) {}

    SessionStats run(std::size_t commandCount) {
        while (stats_.pushes < commandCount) step(commandCount - stats_.pushes);
        while (history_.canRedo()) history_.redo();
        return stats_;
    }

private:
    void step(std::size_t budget) {
        const std::uint32_t action = random_.below(100);
        if (action < 10 && history_.canUndo()) {
            undo(1 + random_.below(3));
        } else if (action < 30 && history_.canRedo()) {
            history_.redo();
            ++stats_.redos;
        } else if (action < 17 && budget >= 2) {
            macro(std::min<std::size_t>(budget, 2 + random_.below(3)));
        } else if (action < 25 && budget >= 2) {
            drag(std::min<std::size_t>(budget, 2 + random_.below(4)));
        } else {
            push(randomCommand(random_, scene_));
        }
    }

    void undo(std::uint32_t steps) {
        for (; steps > 0 && history_.canUndo(); --steps) {
            history_.undo();
            ++stats_.undos;
        }
    }

    void macro(std::size_t size) {
        history_.beginMacro("random group");
        for (std::size_t i = 0; i < size; ++i) push(randomCommand(random_, scene_));
        history_.endMacro();
        ++stats_.commandsByType["macro"];
    }

    // Moves one node, or edits one material, several times within one interaction.
    void drag(std::size_t size) {
        const std::uint64_t serial = history_.beginInteraction();
        const std::vector<NodeId> nodes = scene_.depthFirst();
        const bool material = nodes.empty() || (!scene_.materials.empty() && random_.chance(30));
        if (material && scene_.materials.empty()) {
            push(randomCommand(random_, scene_));
            return;
        }
        const NodeId node = nodes.empty() ? NodeId{} : random_.pick(nodes);
        const MaterialId target = material ? scene_.materials.begin()->first : MaterialId{};
        for (std::size_t i = 0; i < size; ++i) {
            CommandPtr edit = material ? randomMaterialEdit(random_, scene_, target)
                                       : randomTransformEdit(random_, scene_, node);
            edit->interaction = serial;
            push(std::move(edit));
        }
    }

    void push(CommandPtr command) {
        ++stats_.commandsByType[command->typeName()];
        ++stats_.pushes;
        history_.push(std::move(command));
    }

    History& history_;
    const Scene& scene_;
    RandomSource random_;
    SessionStats stats_;
};

} // namespace

SessionStats runRandomSession(History& history, const Scene& scene, std::uint32_t seed, std::size_t commandCount) {
    return Session(history, scene, seed).run(commandCount);
}

} // namespace glint::test
