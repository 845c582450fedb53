// The scene graph's invariants: hierarchy, stable ids, cached world transforms.
#include "scene/core/scene.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>

using namespace glint;

namespace {
Node named(const std::string& name, glm::vec3 translation = {}) {
    Node n;
    n.name = name;
    n.local.translation = translation;
    return n;
}
bool near(const glm::mat4& a, const glm::mat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > 1e-5f) return false;
    return true;
}
} // namespace

class TestSceneGraph : public QObject {
    Q_OBJECT
private slots:
    void idsAreStableAndFresh() {
        Scene s;
        NodeId a = s.addNode(named("a"));
        NodeId b = s.addNode(named("b"));
        QCOMPARE(a.value, 1u);
        QCOMPARE(b.value, 2u);
        s.removeLeaf(a);
        NodeId c = s.addNode(named("c"));
        QCOMPARE(c.value, 3u); // ids are never reused
        Node back = named("a");
        back.id = a;
        QCOMPARE(s.addNode(back), a);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, s.addNode(back));
    }

    void worldTransformFollowsParentAndIsInvalidated() {
        Scene s;
        NodeId parent = s.addNode(named("p", {1, 0, 0}));
        NodeId child = s.addNode(named("c", {0, 2, 0}), parent);
        QVERIFY(near(s.worldFromNode(child), glm::translate(glm::mat4(1), {1, 2, 0})));
        Transform t;
        t.translation = {5, 0, 0};
        s.setLocal(parent, t);
        QVERIFY(near(s.worldFromNode(child), glm::translate(glm::mat4(1), {5, 2, 0})));
        s.setParent(child, {});
        QVERIFY(near(s.worldFromNode(child), glm::translate(glm::mat4(1), {0, 2, 0})));
    }

    void reparentRefusesCycles() {
        Scene s;
        NodeId a = s.addNode(named("a"));
        NodeId b = s.addNode(named("b"), a);
        NodeId c = s.addNode(named("c"), b);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, s.setParent(a, c));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, s.setParent(a, a));
        QCOMPARE(s.at(c).parent, b);
        QCOMPARE(s.subtree(a), (std::vector<NodeId>{a, b, c}));
    }

    void siblingOrderIsKept() {
        Scene s;
        NodeId a = s.addNode(named("a"));
        NodeId b = s.addNode(named("b"));
        NodeId c = s.addNode(named("c"), {}, 0);
        QCOMPARE(s.roots(), (std::vector<NodeId>{c, a, b}));
        QCOMPARE(s.indexInParent(a), std::size_t(1));
        Node removed = s.removeLeaf(c);
        QCOMPARE(removed.name, std::string("c"));
        QCOMPARE(s.roots(), (std::vector<NodeId>{a, b}));
    }

    void negativeScaleFlipsWinding() {
        Transform t;
        t.scale = {-1, 1, 1};
        QVERIFY(flipsWinding(toMatrix(t)));
        t.scale = {-1, -1, 1};
        QVERIFY(!flipsWinding(toMatrix(t)));
    }

    void removingANodeWithChildrenIsRefused() {
        Scene s;
        NodeId a = s.addNode(named("a"));
        s.addNode(named("b"), a);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, s.removeLeaf(a));
    }

    void visibilityFollowsAncestorsAndIsInvalidated() {
        Scene s;
        NodeId a = s.addNode(named("a"));
        NodeId b = s.addNode(named("b"), a);
        NodeId c = s.addNode(named("c"), b);
        QVERIFY(s.visibleInWorld(c));
        s.setVisible(a, false);
        QVERIFY(!s.visibleInWorld(c) && !s.visibleInWorld(b));
        s.setParent(b, {});
        QVERIFY(s.visibleInWorld(c));
        s.setVisible(c, false);
        QVERIFY(s.visibleInWorld(b) && !s.visibleInWorld(c));
    }

    // A chain 200000 deep (the loader accepts one): asking every node about its world transform and
    // visibility is linear, not quadratic (that took minutes), and needs no recursion.
    void deepChainIsAnsweredInLinearTime() {
        constexpr int kDepth = 200000;
        Scene s;
        std::vector<NodeId> chain;
        NodeId parent{};
        for (int i = 0; i < kDepth; ++i) {
            parent = s.addNode(named("n", {1, 0, 0}), parent); // whole metres: the sums stay exact
            chain.push_back(parent);
        }
        s.setVisible(chain[1], false);
        int visible = 0;
        for (const NodeId id : chain) visible += s.visibleInWorld(id);
        QCOMPARE(visible, 1);
        const glm::mat4 leaf = s.worldFromNode(chain.back());
        QCOMPARE(leaf[3].x, float(kDepth));
        for (const NodeId id : chain) QVERIFY(std::isfinite(s.worldFromNode(id)[3].x));
    }

    void equalityComparesContent() {
        Scene a, b;
        a.addNode(named("x"));
        b.addNode(named("x"));
        QVERIFY(a == b);
        b.setName(NodeId{1}, "y");
        QVERIFY(!(a == b));
    }
};

QTEST_APPLESS_MAIN(TestSceneGraph)
#include "test_scene_graph.moc"
