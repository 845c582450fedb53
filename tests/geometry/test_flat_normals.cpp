// glTF's rule for primitives without normals: flat normals, one per face.
#include "scene/geometry/geometry.h"

#include <QtTest>

using namespace glint;

namespace {

// A unit cube on 8 shared corners, 12 triangles counter-clockwise seen from outside.
Primitive sharedCornerCube() {
    Primitive p;
    for (int i = 0; i < 8; ++i) p.positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
    for (int i = 0; i < 8; ++i) p.uv0.push_back({float(i), float(-i)});
    p.indices = {0, 4, 6, 0, 6, 2,  // -X
                 1, 3, 7, 1, 7, 5,  // +X
                 0, 1, 5, 0, 5, 4,  // -Y
                 2, 6, 7, 2, 7, 3,  // +Y
                 0, 2, 3, 0, 3, 1,  // -Z
                 4, 5, 7, 4, 7, 6}; // +Z
    return p;
}

} // namespace

class TestFlatNormals : public QObject {
    Q_OBJECT
private slots:
    void cubeGetsOneOutwardNormalPerFace() {
        const Primitive original = sharedCornerCube();
        Primitive p = original;
        generateFlatNormals(p);
        QCOMPARE(p.positions.size(), std::size_t(36));
        QCOMPARE(p.normals.size(), std::size_t(36));
        const std::vector<glm::vec3> faceNormals = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0},
                                                    {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
        for (std::size_t c = 0; c < 36; ++c) {
            QCOMPARE(p.indices[c], std::uint32_t(c));
            QCOMPARE(p.normals[c], faceNormals[c / 6]);
            QCOMPARE(p.positions[c], original.positions[original.indices[c]]);
            QCOMPARE(p.uv0[c], original.uv0[original.indices[c]]); // other attributes follow their corner
        }
    }

    void degenerateTriangleGetsUp() {
        Primitive p;
        p.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}; // collinear
        p.indices = {0, 1, 2};
        generateFlatNormals(p);
        for (const glm::vec3& n : p.normals) QCOMPARE(n, glm::vec3(0, 1, 0));
    }

    void staleTangentsAreDropped() {
        Primitive p = sharedCornerCube();
        p.tangents.assign(8, glm::vec4(1, 0, 0, 1));
        generateFlatNormals(p);
        QVERIFY(p.tangents.empty());
    }
};

QTEST_APPLESS_MAIN(TestFlatNormals)
#include "test_flat_normals.moc"
