// Portal pairs in the editor: Add > Shape > Portal pair adds two linked 2 m quads standing side by
// side as one undo step; the Properties panel's "Portal to" links a quad to another, clearing the
// previous partners' links, as one undo step, and says when a link is one-sided (its partner
// deleted). Duplicating a pair makes a new pair, duplicating one side an ordinary quad; an
// imported pair stays linked under its new ids. Undo and redo restore the exact scene.
#include "editor_fixtures.h"

#include "editor/document/edit_operations.h"
#include "editor/document/node_placement.h"
#include "editor/document/portal_edits.h"
#include "editor/document/scene_merge.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/properties/properties_panel.h"

#include "scene/core/portal.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QMenu>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

namespace {

void settle() {
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

NodeId addQuad(Document& document, const char* name) {
    Shape quad = std::get<Shape>(defaultShape(ShapeKind::Quad));
    addNode(document, name, quad);
    return document.currentNode();
}

NodeId portalOf(const Document& document, NodeId quad) { return document.scene().at(quad).get<Shape>()->portal; }

} // namespace

class TestPortalEditing : public QObject {
    Q_OBJECT

private slots:
    // At a focus (1, 3, 2) with a floor 3 m below, looking at 4 m: A and B stand on it (centres 1 m
    // up), 2 m square as a new quad there is, 3 m apart, facing +Z, each with its own material,
    // linked; one undo step takes both away. Looking at a 0.55 m box they are 0.2 m squares.
    void addMenuAddsALinkedPair() {
        Document document;
        document.setViewFocusProvider([] { return ViewFocus{{1.0, 3.0, 2.0}, 4.0, 1e30, 3.0}; });
        OutlinerPanel outliner(document);
        const Scene empty = document.scene();
        QAction* add = actionNamed(outliner.addMenu(), "Portal pair");
        QVERIFY(add);
        add->trigger();
        settle();
        const Scene& scene = document.scene();
        const NodeId a = *scene.findByName("Portal A");
        const NodeId b = *scene.findByName("Portal B");
        QCOMPARE(portalPartner(scene, a), std::optional<NodeId>(b));
        QCOMPARE(portalPartner(scene, b), std::optional<NodeId>(a));
        for (const NodeId id : {a, b}) {
            const Shape& quad = *scene.at(id).get<Shape>();
            QCOMPARE(quad.size, glm::vec3(2.0f, 1.0f, 2.0f));
            QVERIFY(quad.material.valid());
            const glm::vec3 normal = glm::mat3(scene.worldFromNode(id)) * glm::vec3(0, 1, 0);
            QVERIFY(glm::length(normal - glm::vec3(0, 0, 1)) < 1e-5f);
        }
        QVERIFY(scene.at(a).get<Shape>()->material != scene.at(b).get<Shape>()->material);
        QCOMPARE(scene.at(a).local.translation, glm::vec3(-0.5f, 1.0f, 2.0f));
        QCOMPARE(scene.at(b).local.translation, glm::vec3(2.5f, 1.0f, 2.0f));
        QCOMPARE(document.selection(), (std::vector<NodeId>{a, b}));
        QCOMPARE(document.history().count(), std::size_t(1));
        QCOMPARE(document.history().label(0), std::string("Add Portal Pair"));
        const Scene added = scene;
        document.undo();
        QVERIFY(document.scene() == empty);
        document.redo();
        QVERIFY(document.scene() == added);

        const PortalPairPlacement small = placePortalPair(ViewFocus{{0.28, 0.27, 0.28}, 0.55, 1e30, 0.27});
        QCOMPARE(small.edge, 0.2f);
        QVERIFY(glm::length(small.a.translation - glm::vec3(0.13f, 0.1f, 0.28f)) < 1e-6f);
        QVERIFY(glm::length(small.b.translation - glm::vec3(0.43f, 0.1f, 0.28f)) < 1e-6f);
    }

    // A-B and C-D are pairs; linking A to C pairs them and leaves B and D unlinked, in one step.
    void linkingKeepsEveryLinkTwoSided() {
        Document document;
        const NodeId a = addQuad(document, "a"), b = addQuad(document, "b"), c = addQuad(document, "c"), d = addQuad(document, "d");
        QCOMPARE(linkPortal(document, a, b), QString());
        QCOMPARE(linkPortal(document, c, d), QString());
        QCOMPARE(portalOf(document, b), a);
        const Scene before = document.scene();
        const std::size_t steps = document.history().count();
        QCOMPARE(linkPortal(document, a, c), QString());
        QCOMPARE(document.history().count(), steps + 1);
        QCOMPARE(portalOf(document, a), c);
        QCOMPARE(portalOf(document, c), a);
        QVERIFY(!portalOf(document, b).valid());
        QVERIFY(!portalOf(document, d).valid());
        const Scene after = document.scene();
        document.undo();
        QVERIFY(document.scene() == before);
        document.redo();
        QVERIFY(document.scene() == after);
        QCOMPARE(linkPortal(document, a, c), QString()); // already a pair: nothing to do
        QCOMPARE(document.history().count(), steps + 1);
        QCOMPARE(linkPortal(document, a, NodeId{}), QString());
        QVERIFY(!portalOf(document, a).valid() && !portalOf(document, c).valid());
        QVERIFY(!linkPortal(document, a, a).isEmpty());
    }

    // The panel lists None and the other quads; choosing one links both ways. Deleting the partner
    // leaves a one-sided link the panel names; undoing the delete pairs them again.
    void panelLinksAndShowsOneSidedLinks() {
        Document document;
        const NodeId a = addQuad(document, "a"), b = addQuad(document, "b");
        addNode(document, "ball", defaultShape(ShapeKind::Sphere));
        document.setSelection({a});
        PropertiesPanel panel(document, false);
        settle();
        auto* combo = fieldNamed<QComboBox>(panel, "Portal to");
        QVERIFY(combo);
        QCOMPARE(combo->count(), 2); // None, b (the sphere is not a quad)
        QCOMPARE(combo->itemText(1), QString("b"));
        const std::size_t steps = document.history().count();
        combo->setCurrentIndex(1);
        emit combo->activated(1);
        settle();
        QCOMPARE(portalOf(document, a), b);
        QCOMPARE(portalOf(document, b), a);
        QCOMPARE(document.history().count(), steps + 1);
        auto* state = panel.findChild<QLabel*>("portalState");
        QVERIFY(state && state->isHidden());

        document.setSelection({b});
        QCOMPARE(deleteSelection(document), QString());
        document.setSelection({a});
        settle();
        combo = fieldNamed<QComboBox>(panel, "Portal to");
        state = panel.findChild<QLabel*>("portalState");
        QVERIFY(combo && state);
        QVERIFY(!state->isHidden());
        QVERIFY(state->text().startsWith("Not paired"));
        QCOMPARE(combo->currentText(), QString("node %1, deleted").arg(b.value));
        QVERIFY(!portalPartner(document.scene(), a));
        document.undo();
        settle();
        QCOMPARE(portalPartner(document.scene(), a), std::optional<NodeId>(b));
        QVERIFY(panel.findChild<QLabel*>("portalState")->isHidden());
    }

    void duplicatingAPairMakesANewPair() {
        Document document;
        const NodeId a = addQuad(document, "a"), b = addQuad(document, "b");
        QCOMPARE(linkPortal(document, a, b), QString());
        const Scene before = document.scene();
        const std::size_t steps = document.history().count();
        document.setSelection({a, b});
        QCOMPARE(duplicateSelection(document), QString());
        QCOMPARE(document.history().count(), steps + 1);
        const std::vector<NodeId> copies = document.selection();
        QCOMPARE(copies.size(), std::size_t(2));
        QCOMPARE(portalOf(document, copies[0]), copies[1]);
        QCOMPARE(portalOf(document, copies[1]), copies[0]);
        QCOMPARE(portalOf(document, a), b); // the originals keep each other
        QCOMPARE(portalOf(document, b), a);
        document.undo();
        QVERIFY(document.scene() == before);

        document.setSelection({a});
        QCOMPARE(duplicateSelection(document), QString());
        const NodeId copy = document.selection().front();
        QVERIFY(!portalOf(document, copy).valid()); // one side copied: an ordinary quad
        QCOMPARE(portalOf(document, b), a);
    }

    // The imported file's ids are taken in the target: the links follow the new ids.
    void importedPairStaysLinked() {
        Scene target;
        for (int i = 0; i < 3; ++i) target.addNode(Node{});
        Scene imported;
        const NodeId a = imported.addNode(Node{});
        Node quad;
        quad.component = std::get<Shape>(defaultShape(ShapeKind::Quad));
        std::get<Shape>(quad.component).portal = NodeId{3};
        const NodeId first = imported.addNode(quad, a);
        std::get<Shape>(quad.component).portal = first;
        const NodeId second = imported.addNode(quad);
        QCOMPARE(second, NodeId{3});
        for (CommandPtr& command : mergeCommands(target, std::move(imported))) command->apply(target);
        const NodeId newFirst{5}, newSecond{6}; // after 1..3, in depth-first order: 4 (a), 5, 6
        QCOMPARE(target.at(newFirst).get<Shape>()->portal, newSecond);
        QCOMPARE(target.at(newSecond).get<Shape>()->portal, newFirst);
        QCOMPARE(portalPartner(target, newFirst), std::optional<NodeId>(newSecond));
    }
};

QTEST_MAIN(TestPortalEditing)
#include "test_portal_editing.moc"
