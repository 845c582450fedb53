// The BVH build and its flattened buffers: mesh conversion, determinism across thread counts,
// SAH quality, validation of corrupted buffers, buffer size limits, top-level updates.
#include "bvh_test_scenes.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/size_check.h"
#include "renderer/bvh/traverse.h"
#include "renderer/bvh/validate.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QTest>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>

using namespace glint;
using namespace glint::bvh;
using namespace glint::bvh::test;

namespace {

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameBytes(const FlatScene& a, const FlatScene& b)
{
    return sameBytes(a.nodes, b.nodes) && sameBytes(a.levels, b.levels) && sameBytes(a.trianglePositions, b.trianglePositions) &&
           sameBytes(a.triangleVertices, b.triangleVertices) && sameBytes(a.instances, b.instances) && a.topLevel == b.topLevel &&
           sameBytes(a.slotTriangle, b.slotTriangle);
}

TestScene bunnyScene(int threads = 1)
{
    return makeScene({loadBunny()}, {{0, glm::mat4(1.0f)}}, threads);
}

MeshTriangles copiesOfOneTriangle(int count)
{
    MeshTriangles copies;
    copies.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < count; ++i) {
        copies.triangles.emplace_back(0, 1, 2);
        copies.materials.push_back(0);
        copies.primitiveOf.push_back(0);
    }
    return copies;
}

// First interior node of the first mesh below the root, and its first child.
std::uint32_t someInteriorNode(const FlatScene& scene)
{
    for (std::uint32_t n = 1; n < scene.meshNodeCount; ++n)
        if (nodeLink(scene, n).y == 0) return n;
    return 0;
}

std::uint32_t someLeaf(const FlatScene& scene, std::uint32_t after)
{
    for (std::uint32_t n = after; n < scene.meshNodeCount; ++n)
        if (nodeLink(scene, n).y > 0) return n;
    return 0;
}

} // namespace

class TestBvhBuild : public QObject {
    Q_OBJECT
private slots:
    void meshTrianglesSpanPrimitivesWithMaterials()
    {
        Mesh mesh;
        Primitive a;
        a.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        a.indices = {0, 1, 2};
        a.material = MaterialId{7};
        Primitive b;
        b.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
        b.indices = {0, 1, 2, 2, 1, 3, 0, 1, 9}; // the last triangle points past the vertices
        mesh.primitives = {a, b};
        const MeshTriangles tris = trianglesFromMesh(mesh, [](MaterialId id) { return id.value == 7 ? 3u : 0u; });
        QCOMPARE(tris.positions.size(), std::size_t{7});
        QCOMPARE(tris.triangleCount(), std::size_t{3});
        QCOMPARE(tris.triangles[1], glm::uvec3(3, 4, 5));
        QCOMPARE(tris.triangles[2], glm::uvec3(5, 4, 6));
        QCOMPARE(tris.materials, (std::vector<std::uint32_t>{3, 0, 0}));
        QCOMPARE(tris.primitiveOf, (std::vector<std::uint32_t>{0, 1, 1}));
    }

    void buffersAreByteIdenticalWithOneAndFourThreads()
    {
        const MeshTriangles bunny = subdivided(loadBunny(), 1); // 277,804 triangles: many build tasks
        const TestScene one = makeScene({bunny}, {{0, glm::mat4(1.0f)}}, 1);
        const TestScene four = makeScene({bunny}, {{0, glm::mat4(1.0f)}}, 4);
        const TestScene three = makeScene({bunny}, {{0, glm::mat4(1.0f)}}, 3);
        QVERIFY(one.flat.nodes.size() > 1000);
        QVERIFY(sameBytes(one.flat, four.flat));
        QVERIFY(sameBytes(one.flat, three.flat));
        QVERIFY(one.meshes[0].bvh == four.meshes[0].bvh);
    }

    void sahCostIsReportedAndBeatsCoarseBinning()
    {
        const MeshTriangles bunny = loadBunny();
        BuildOptions fine;
        BuildOptions coarse;
        coarse.bins = 2;
        const MeshBvh fineBvh = buildMeshBvh(bunny, fine);
        const MeshBvh coarseBvh = buildMeshBvh(bunny, coarse);
        const double fineCost = sahCost(fineBvh.bvh);
        const double coarseCost = sahCost(coarseBvh.bvh);
        qInfo("bunny: %zu triangles, %zu nodes, depth %d, SAH cost %.3f (32 bins), %.3f (2 bins)", bunny.triangleCount(),
              fineBvh.bvh.nodes.size(), maxDepth(fineBvh.bvh), fineCost, coarseCost);
        QVERIFY(fineCost > 0.0);
        QVERIFY(fineCost < coarseCost);
        QVERIFY(fineCost < 0.01 * static_cast<double>(bunny.triangleCount())); // a single leaf would cost N
    }

    void leavesRespectTheSizeLimitAndCoverEveryTriangleOnce()
    {
        BuildOptions options;
        options.maxLeafSize = 100; // clamped to kMaxLeafTriangles
        const MeshBvh mesh = buildMeshBvh(loadBunny(), options);
        std::vector<int> seen(mesh.triangles.triangleCount(), 0);
        for (const BvhNode& node : mesh.bvh.nodes) {
            if (!node.leaf()) continue;
            QVERIFY(node.count <= kMaxLeafTriangles);
            for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) ++seen[mesh.bvh.itemOrder[slot]];
        }
        QVERIFY(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    }

    void identicalCentroidsStillSplit()
    {
        // No plane separates copies of one triangle: the build halves the range instead.
        const TestScene scene = makeScene({copiesOfOneTriangle(100)}, {{0, glm::mat4(1.0f)}});
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});
        QCOMPARE(maxDepth(scene.meshes[0].bvh), 6); // 100 -> 50 -> 25 -> 13 -> 7 -> 4 (leaves)
    }

    void validationAcceptsABuiltScene()
    {
        const TestScene scene = makeScene({loadBunny(), closedGridCube(4, 1.0f, glm::vec3(0.0f))},
                                          {{0, glm::mat4(1.0f)}, {1, glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0))}});
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});
    }

    void validationCatchesALinkBackwards()
    {
        TestScene scene = bunnyScene();
        const std::uint32_t node = someInteriorNode(scene.flat);
        setLink(scene.flat, node, 0, 0);
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(*problem),
                 QString("mesh 0: node %1 links to child 0, not a later node of its level (a cycle or a bad index)").arg(node));
    }

    void validationCatchesAChildBoxOutsideItsParent()
    {
        // The root's first child shrunk to one grid point: its own children no longer fit in it.
        TestScene scene = bunnyScene();
        const std::uint32_t parent = nodeLink(scene.flat, 0).x;
        QCOMPARE(nodeLink(scene.flat, parent).y, 0u);
        const GridBox box = unpackGridBox(glm::uvec3(scene.flat.nodes[parent]));
        const glm::uvec3 point = packGridBox(GridBox{box.lo, box.lo});
        scene.flat.nodes[parent] = glm::uvec4(point, scene.flat.nodes[parent].w);
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(*problem), QString("mesh 0: the box of node %1 is not inside the box of its parent %2")
                                                       .arg(nodeLink(scene.flat, parent).x)
                                                       .arg(parent));
    }

    void gridBoxesHoldTheirBoxesAndNoMore()
    {
        // Roots around the origin, far from it and tiny, huge, and flat: every quantised box holds
        // its box, and one grid step inwards on any side would cut into it.
        const Aabb roots[] = {{{-1, -1, -1}, {1, 1, 1}},
                              {{1000.0f, 1000.0f, -5e-4f}, {1000.001f, 1000.01f, 5e-4f}},
                              {{-3e37f, -1.0f, 0.0f}, {5e37f, 1.0f, 0.0f}},
                              {{0.1f, 0.1f, 0.1f}, {0.1f, 0.3f, 0.5f}},
                              {{2.5f, -1000.0f, 0.0f}, {2.5f, -1000.0f, 1.0f}}};
        std::mt19937 rng(7u);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        for (const Aabb& root : roots) {
            const BoxGrid grid = gridAround(root);
            QVERIFY(grid.origin == root.lo);
            for (int i = 0; i < 2000; ++i) {
                Aabb box;
                for (int corner = 0; corner < 2; ++corner) {
                    const glm::vec3 t{unit(rng), unit(rng), unit(rng)};
                    box.grow(glm::clamp(root.lo + t * (root.hi - root.lo), root.lo, root.hi));
                }
                if (i == 0) box = root;
                const std::optional<GridBox> q = quantize(grid, box);
                QVERIFY(q);
                QVERIFY(dequantize(grid, *q).contains(box));
                for (int axis = 0; axis < 3; ++axis) {
                    if (q->lo[axis] < kGridMax) QVERIFY(gridPoint(grid, q->lo + 1u)[axis] > box.lo[axis]);
                    if (q->hi[axis] > 0) QVERIFY(gridPoint(grid, q->hi - 1u)[axis] < box.hi[axis]);
                }
                const GridBox unpacked = unpackGridBox(packGridBox(*q));
                QVERIFY(unpacked.lo == q->lo && unpacked.hi == q->hi);
            }
        }
        // A flat axis away from the origin: one grid point holds it, and it rounds at once.
        const BoxGrid flat = gridAround(roots[4]);
        QVERIFY(flat.scale.x >= std::nextafter(2.5f, 3.0f) - 2.5f);
        const GridBox flatBox = *quantize(flat, roots[4]);
        QVERIFY(flatBox.lo.x == 0u && flatBox.hi.x == 0u && flatBox.lo.y == 0u && flatBox.hi.y == 0u);
        const BoxGrid unit1 = gridAround(roots[0]);
        QVERIFY(!quantize(unit1, Aabb{{0, 0, 0}, {4, 0, 0}})); // the grid spans [-1, 3) on each axis
        QVERIFY(quantize(unit1, Aabb{})->hi == glm::uvec3(0)); // empty: the origin point
        QVERIFY(!withinGridReach(Aabb{{0, 0, 0}, {1e38f, 0, 0}}));
    }

    void validationCatchesALevelThatDisagreesWithItsRoot()
    {
        // The shader enters a mesh at its level texel's root link, the CPU at its root node: they agree.
        TestScene scene = bunnyScene();
        scene.flat.levels[0].w += 16;
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QCOMPARE(*problem, std::string("mesh 0: its level texels and its root node 0 disagree"));
    }

    void validationCatchesAGridThatIsNotPowersOfTwo()
    {
        // A grid step that is not a power of two rounds its products differently on other hardware.
        TestScene scene = bunnyScene();
        const float scale = std::bit_cast<float>(scene.flat.levels[1].x);
        scene.flat.levels[1].x = std::bit_cast<std::uint32_t>(scale * 1.5f);
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QCOMPARE(*problem, std::string("mesh 0: its box grid is not a finite origin with power-of-two steps"));
    }

    void linksPastWhatTheTraversalPacksAreRefused()
    {
        QCOMPARE(checkLinkReach(kMaxLinkFirst, 1, 1), std::optional<std::string>{});
        QCOMPARE(checkLinkReach(1, kMaxLinkFirst + 1, 1),
                 std::optional<std::string>("the scene needs links to index 134217728, beyond the 134217728 the traversal can address"));
        QVERIFY(checkLinkReach(1, 1, std::size_t{kMaxLinkFirst} * 2).has_value());
    }

    void validationCatchesATriangleReferencedTwice()
    {
        // Copies of one triangle: every leaf has the same box, so only the double reference is wrong.
        TestScene scene = makeScene({copiesOfOneTriangle(100)}, {{0, glm::mat4(1.0f)}});
        const std::uint32_t first = someLeaf(scene.flat, 1);
        const std::uint32_t second = someLeaf(scene.flat, first + 1);
        setLink(scene.flat, second, nodeLink(scene.flat, first).x, 1);
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QVERIFY2(QString::fromStdString(*problem).contains(QString("triangle slot %1 is referenced twice").arg(nodeLink(scene.flat, first).x)),
                 problem->c_str());
    }

    void validationCatchesAnInstanceWithoutAMesh()
    {
        TestScene scene = bunnyScene();
        scene.flat.instances[3].y = 1; // the scene has one mesh
        const auto problem = validateFlatScene(scene.flat);
        QVERIFY(problem);
        QCOMPARE(*problem, std::string("instance 0: mesh 1 does not exist or has no triangles"));
    }

    void sizeCheckNamesTheBufferThatDoesNotFit()
    {
        const TestScene scene = bunnyScene();
        QCOMPARE(checkTextureBufferSizes(scene.flat, 134217728), std::optional<std::string>{});
        const auto problem = checkTextureBufferSizes(scene.flat, 65536);
        QVERIFY(problem);
        const std::size_t nodes = scene.flat.nodes.size();
        const std::string expected = nodes > 65536
            ? "BVH buffer uBvhNodes needs " + std::to_string(nodes) + " texels but GL_MAX_TEXTURE_BUFFER_SIZE is 65536 (" +
                  std::to_string(nodes) + " nodes)"
            : "BVH buffer uBvhTrianglePositions needs " + std::to_string(scene.flat.trianglePositions.size()) +
                  " texels but GL_MAX_TEXTURE_BUFFER_SIZE is 65536 (" + std::to_string(scene.flat.triangleVertices.size()) + " triangles)";
        QCOMPARE(*problem, expected);
    }

    void movingAnInstanceRewritesOnlyTheTopLevel()
    {
        TestScene scene = makeScene({loadBunny(), closedGridCube(4, 0.05f, glm::vec3(0.0f))},
                                    {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}, {0, glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0))}});
        const FlatScene before = scene.flat;
        std::vector<Instance> moved = scene.topLevel.instances;
        moved[1].worldFromLocal = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -3.0f));
        const TopLevel top = buildTopLevel(moved, scene.meshes);
        replaceTopLevel(scene.flat, flattenTopLevel(top, scene.flat.meshNodeCount));

        QVERIFY(sameBytes(scene.flat, flattenScene(scene.meshes, top)));
        const std::size_t meshNodes = scene.flat.meshNodeCount;
        QVERIFY(std::memcmp(before.nodes.data(), scene.flat.nodes.data(), meshNodes * sizeof(glm::uvec4)) == 0);
        QVERIFY(std::memcmp(before.levels.data(), scene.flat.levels.data(), kLevelTexels * scene.flat.meshes.size() * sizeof(glm::uvec4)) == 0);
        QVERIFY(sameBytes(before.trianglePositions, scene.flat.trianglePositions));
        QVERIFY(!sameBytes(before.instances, scene.flat.instances));
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});

        // The cube (0.2 m) now sits 3 m behind the origin: a ray down -z from z = -1 meets its face z = -2.8.
        const RayHit hit = intersectClosest(scene.flat, Ray{{0.1f, 0.1f, -1.0f}, {0.0f, 0.0f, -1.0f}}, 100.0f);
        QCOMPARE(hit.instance, 1);
        QCOMPARE(hit.t, 1.8f); // fuzzy float comparison
    }

    void instancesOfEmptyMeshesAndSingularTransformsAreLeftOut()
    {
        const TestScene scene = makeScene({MeshTriangles{}, closedGridCube(1, 1.0f, glm::vec3(0.0f))},
                                          {{0, glm::mat4(1.0f)}, {1, glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1))}, {1, glm::mat4(1.0f)}});
        QCOMPARE(scene.topLevel.instances.size(), std::size_t{1});
        QCOMPARE(scene.topLevel.instances[0].objectId, 3u);
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});
    }
};

QTEST_APPLESS_MAIN(TestBvhBuild)
#include "test_bvh_build.moc"
