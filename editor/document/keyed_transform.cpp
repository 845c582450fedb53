#include "editor/document/keyed_transform.h"

#include "editor/document/in_macro.h"

#include "scene/anim/node_animation.h"
#include "scene/anim/node_keys.h"
#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"

#include <QCoreApplication>

#include <memory>

namespace glint::editor {

Transform shownTransform(const Document& document, NodeId node) {
    const Scene& scene = document.scene();
    if (!nodeKeyAnimation(scene, node)) return scene.at(node).local;
    return sampleLocalTransform(scene, node, document.currentTime());
}

bool editKeysNode(const Document& document, NodeId node) {
    return document.autoKey() || nodeKeyAnimation(document.scene(), node).has_value();
}

void pushNodeKey(Document& document, NodeId node, double t, const Transform& local, std::uint64_t interaction) {
    const Scene& scene = document.scene();
    CommandPtr command;
    if (const std::optional<AnimationId> id = nodeKeyAnimation(scene, node)) {
        const Animation& animation = scene.animations.at(*id);
        command = std::make_unique<SetAsset<Animation>>(*id, withNodeKey(animation, node, t, local, nodeKeyInterpolation(animation, node)));
    } else {
        Animation animation = withNodeKey({}, node, t, local, Interpolation::Linear);
        animation.name = scene.at(node).name;
        command = std::make_unique<AddAsset<Animation>>(std::move(animation));
    }
    command->interaction = interaction;
    document.push(std::move(command));
}

QString pushTransform(Document& document, NodeId node, const Transform& local, std::uint64_t interaction) {
    auto set = [&] {
        auto command = std::make_unique<SetTransform>(node, local);
        command->interaction = interaction;
        if (document.scene().at(node).local != local) document.push(std::move(command));
    };
    if (!editKeysNode(document, node)) {
        try {
            set();
        } catch (const std::exception& e) {
            return QString::fromStdString(e.what());
        }
        return {};
    }
    return inMacro(document, QCoreApplication::translate("glint::editor::KeyedTransform", "Transform and key"), [&] {
        set();
        pushNodeKey(document, node, document.currentTime(), local, interaction);
    });
}

} // namespace glint::editor
