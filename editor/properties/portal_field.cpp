// A quad's "Portal to" field: the other quads it may lead to, and whether its link is a pair.
#include "sections.h"

#include "editor/document/document.h"
#include "editor/document/portal_edits.h"
#include "editor/outliner/node_names.h"

#include <QComboBox>
#include <QLabel>
#include <QVBoxLayout>

namespace glint::editor {
namespace {

using Items = std::vector<std::pair<QString, std::uint32_t>>;

// "None", the other quads, and the quad's present partner when it is none of them (deleted, or
// no longer a quad), so a one-sided link shows what it names.
Items portalItems(const Scene& scene, NodeId quad) {
    Items items{{PropertyForm::tr("None"), 0}};
    const std::vector<NodeId> candidates = portalCandidates(scene, quad);
    for (const NodeId id : candidates) items.emplace_back(nodeDisplayName(scene, id), id.value);
    const Node* node = scene.node(quad);
    const Shape* shape = node ? node->get<Shape>() : nullptr;
    const NodeId partner = shape ? shape->portal : NodeId{};
    if (partner.valid() && std::find(candidates.begin(), candidates.end(), partner) == candidates.end()) {
        const QString name = scene.node(partner) ? nodeDisplayName(scene, partner) : PropertyForm::tr("node %1, deleted").arg(partner.value);
        items.emplace_back(name, partner.value);
    }
    return items;
}

bool sameItems(const QComboBox* combo, const Items& items) {
    if (combo->count() != static_cast<int>(items.size())) return false;
    for (int i = 0; i < combo->count(); ++i)
        if (combo->itemText(i) != items[std::size_t(i)].first || combo->itemData(i).toUInt() != items[std::size_t(i)].second) return false;
    return true;
}

void showLink(const Scene& scene, NodeId quad, QComboBox* combo, QLabel* state) {
    const Items items = portalItems(scene, quad);
    QSignalBlocker block(combo);
    if (!sameItems(combo, items)) { // not while unchanged: this may run inside the combo's own signal
        combo->clear();
        for (const auto& [text, id] : items) combo->addItem(text, id);
    }
    const Shape* shape = scene.node(quad) ? scene.at(quad).get<Shape>() : nullptr;
    combo->setCurrentIndex(std::max(0, combo->findData(shape ? shape->portal.value : 0u)));
    const bool oneSided = portalLink(scene, quad) == PortalLink::OneSided;
    state->setVisible(oneSided);
    if (oneSided)
        state->setText(PropertyForm::tr("Not paired: the other side does not lead back here, so this quad is an ordinary "
                                        "surface. Choose a quad to pair them again."));
}

} // namespace

void addPortalField(PropertyForm* form, Document& document, NodeId quad, const Report& report) {
    auto* box = new QWidget(form);
    auto* combo = newFormComboBox(box);
    auto* state = new QLabel(box);
    state->setWordWrap(true);
    state->setObjectName(QStringLiteral("portalState"));
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(combo);
    layout->addWidget(state);
    combo->setToolTip(PropertyForm::tr("What enters this quad leaves the quad chosen here, and the other way round."));
    QObject::connect(combo, &QComboBox::activated, form, [&document, quad, report, combo](int i) {
        const QString error = linkPortal(document, quad, NodeId{combo->itemData(i).toUInt()});
        if (!error.isEmpty()) report(error);
    });
    form->addWidget(PropertyForm::tr("Portal to"), box, [&document, quad, combo, state] { showLink(document.scene(), quad, combo, state); });
    combo->setAccessibleName(PropertyForm::tr("Portal to"));
}

} // namespace glint::editor
