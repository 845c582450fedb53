// Tessellated analytic shapes: outward normals, winding that agrees with them, closed shapes
// closed, exact radii and extents, and filled uv0 and tangents.
#include "scene/geometry/geometry.h"

#include <QtTest>

#include <map>

using namespace glint;

namespace {

glm::vec3 faceNormal(const Primitive& p, std::size_t f) {
    const glm::vec3 &a = p.positions[p.indices[3 * f]], &b = p.positions[p.indices[3 * f + 1]],
                    &c = p.positions[p.indices[3 * f + 2]];
    return glm::cross(b - a, c - a);
}

// Every triangle's geometric normal (from its winding) points the way its vertex normals do
// and away from the origin (all shapes here are centred there; flat ones face +Y).
void verifyWindingAndOutwardNormals(const Primitive& p, bool flatFacingUp) {
    for (std::size_t f = 0; f < p.triangleCount(); ++f) {
        const glm::vec3 n = faceNormal(p, f);
        QVERIFY2(glm::length(n) > 0.0f, "degenerate triangle");
        glm::vec3 centroid(0.0f);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = p.indices[3 * f + std::size_t(k)];
            QVERIFY(glm::dot(n, p.normals[v]) > 0.0f);
            centroid += p.positions[v] / 3.0f;
        }
        if (flatFacingUp) QVERIFY(glm::normalize(n).y > 0.999f);
        else QVERIFY(glm::dot(n, centroid) > 0.0f);
    }
}

// Closed and consistently wound: every edge (by position) is walked once in each direction.
bool isClosedAndConsistent(const Primitive& p) {
    auto key = [](const glm::vec3& v) { return std::make_tuple(v.x, v.y, v.z); };
    std::map<std::pair<decltype(key(glm::vec3())), decltype(key(glm::vec3()))>, int> directed;
    for (std::size_t c = 0; c < p.indices.size(); ++c) {
        const std::size_t next = c - c % 3 + (c + 1) % 3;
        ++directed[{key(p.positions[p.indices[c]]), key(p.positions[p.indices[next]])}];
    }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
    }
    return true;
}

void verifyAttributesFilled(const Primitive& p) {
    QVERIFY(!p.positions.empty());
    QCOMPARE(p.normals.size(), p.positions.size());
    QCOMPARE(p.uv0.size(), p.positions.size());
    QCOMPARE(p.tangents.size(), p.positions.size());
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
        QVERIFY(std::abs(glm::length(p.normals[v]) - 1.0f) < 1e-5f);
        QVERIFY(std::abs(glm::length(glm::vec3(p.tangents[v])) - 1.0f) < 1e-4f);
        QVERIFY(std::abs(glm::dot(glm::vec3(p.tangents[v]), p.normals[v])) < 1e-4f);
    }
}

Shape shapeOf(ShapeKind kind) {
    Shape s;
    s.kind = kind;
    s.radius = 0.75f;
    s.size = {2.0f, 3.0f, 4.0f};
    s.height = 1.5f;
    s.material = MaterialId{7};
    return s;
}

} // namespace

class TestShapeTessellation : public QObject {
    Q_OBJECT
private slots:
    void sphereIsClosedOutwardAndOnItsRadius() {
        const Primitive p = tessellateShape(shapeOf(ShapeKind::Sphere), 16);
        verifyAttributesFilled(p);
        verifyWindingAndOutwardNormals(p, false);
        for (std::size_t v = 0; v < p.positions.size(); ++v) {
            QVERIFY(std::abs(glm::length(p.positions[v]) - 0.75f) < 1e-6f);
            QVERIFY(glm::length(p.normals[v] - p.positions[v] / 0.75f) < 1e-6f);
        }
        QCOMPARE(p.triangleCount(), std::size_t(16 * 8 * 2 - 2 * 16)); // no pole slivers
        QVERIFY(isClosedAndConsistent(p));
        QCOMPARE(p.material, MaterialId{7});
    }

    // u runs along the longitude (counter-clockwise seen from +Y) and v from the north pole down,
    // so MikkTSpace's tangent is the eastward direction and the glTF bitangent points north. On the
    // uv seam (u = 0 or 1) MikkTSpace sees one side only: the tangent is the chord of one segment,
    // half a segment angle (180 / 32 degrees) off.
    void sphereTangentsFollowTheLongitude() {
        const int segments = 32;
        const Primitive p = tessellateShape(shapeOf(ShapeKind::Sphere), segments);
        for (std::size_t v = 0; v < p.positions.size(); ++v) {
            const glm::vec3 n = p.normals[v];
            if (std::abs(n.y) == 1.0f) continue; // at the poles longitude has no direction
            const glm::vec3 east = glm::normalize(glm::vec3(n.z, 0.0f, -n.x)); // d/d(longitude)
            const glm::vec3 tangent(p.tangents[v]);
            const bool onSeam = p.uv0[v].x == 0.0f || p.uv0[v].x == 1.0f;
            const float toleranceDegrees = onSeam ? 180.0f / segments + 0.1f : 0.1f; // 0.1: float rounding
            QVERIFY2(glm::dot(tangent, east) >= std::cos(glm::radians(toleranceDegrees)), qPrintable(QString::number(v)));
            const glm::vec3 bitangent = glm::cross(n, tangent) * p.tangents[v].w;
            QVERIFY(bitangent.y > 0.0f);
        }
    }

    void boxIsClosedOutwardWithItsExtents() {
        const Primitive p = tessellateShape(shapeOf(ShapeKind::Box));
        verifyAttributesFilled(p);
        verifyWindingAndOutwardNormals(p, false);
        QCOMPARE(p.triangleCount(), std::size_t(12));
        for (const glm::vec3& v : p.positions) QCOMPARE(glm::abs(v), glm::vec3(1.0f, 1.5f, 2.0f));
        QVERIFY(isClosedAndConsistent(p));
    }

    void cylinderIsClosedOutwardWithCaps() {
        const Primitive p = tessellateShape(shapeOf(ShapeKind::Cylinder), 12);
        verifyAttributesFilled(p);
        verifyWindingAndOutwardNormals(p, false);
        QCOMPARE(p.triangleCount(), std::size_t(12 * 2 + 2 * 12));
        for (const glm::vec3& v : p.positions) {
            QVERIFY(std::abs(v.y) == 0.75f);
            const float r = glm::length(glm::vec2(v.x, v.z));
            QVERIFY(std::abs(r - 0.75f) < 1e-6f || r == 0.0f);
        }
        QVERIFY(isClosedAndConsistent(p));
    }

    void flatShapesFaceUp() {
        const Primitive quad = tessellateShape(shapeOf(ShapeKind::Quad));
        verifyAttributesFilled(quad);
        verifyWindingAndOutwardNormals(quad, true);
        for (const glm::vec3& v : quad.positions) QCOMPARE(v, glm::vec3(v.x > 0 ? 1 : -1, 0, v.z > 0 ? 2 : -2));

        const Primitive disk = tessellateShape(shapeOf(ShapeKind::Disk), 10);
        verifyAttributesFilled(disk);
        verifyWindingAndOutwardNormals(disk, true);
        QCOMPARE(disk.triangleCount(), std::size_t(10));

        const Primitive ground = tessellateShape(shapeOf(ShapeKind::GroundPlane), 48, 50.0f);
        verifyWindingAndOutwardNormals(ground, true);
        for (const glm::vec3& v : ground.positions) QCOMPARE(glm::abs(v), glm::vec3(25.0f, 0.0f, 25.0f));
    }

    void tessellationIsDeterministic() {
        for (ShapeKind kind : {ShapeKind::Sphere, ShapeKind::Quad, ShapeKind::Disk, ShapeKind::Box,
                               ShapeKind::Cylinder, ShapeKind::GroundPlane})
            QVERIFY(tessellateShape(shapeOf(kind), 24) == tessellateShape(shapeOf(kind), 24));
    }
};

QTEST_APPLESS_MAIN(TestShapeTessellation)
#include "test_shape_tessellation.moc"
