// Emissive shapes as lights on the CPU, through the GLSL's C++ twin (sampling/shape_emitter.glsl):
// the pdf a sample reports equals the pdf shapeEmitterPdf gives its point (what MIS weighs BSDF
// hits with; within 1e-3 where the shape is not seen edge-on), and the estimate of the projected solid angle, mean of cos / pdf, matches the closed
// form: pi F for a rectangle (under a rotated, scaled map) and a disk straight above the point,
// pi (r / d)^2 for a sphere, and pi (a hemisphere) for a point on an enclosing sphere's surface,
// rounded a hair outside (the furnace's wall, which once sampled only itself; area sampling makes
// that estimate exact). 2^18 samples each; within 0.5 % and 4 standard errors (+ 1e-6 relative).
#include "renderer/cpu_twin/glsl_twin.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QTest>

#include <cmath>

using namespace glint::twin;

namespace {

constexpr int kSamples = 1 << 18;
constexpr double kPi = 3.14159265358979;

ShapeEmitter emitter(int kind, float radius, vec3 size, float height, const mat4& worldFromLocal) {
    const mat4 rows = transpose(inverse(worldFromLocal));
    const mat4 worldRows = transpose(worldFromLocal);
    return ShapeEmitter{kind, radius, size, height, rows[0], rows[1], rows[2], worldRows[0], worldRows[1], worldRows[2],
                        std::abs(determinant(mat3(worldFromLocal)))};
}

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
    double worstPdfMismatch = 0.0; // relative, sample pdf vs shapeEmitterPdf
};

// Mean of max(cos at p about `normal`, 0) / pdf over light samples from p (0 where none).
Estimate projectedSolidAngle(const ShapeEmitter& e, vec3 p, vec3 normal) {
    Rng rng = rngStart(uvec2(3u, 7u), 0u, 11u);
    double sum = 0.0, sum2 = 0.0, worst = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        ShapePoint s;
        double x = 0.0;
        if (sampleShapeEmitter(e, p, rand3(rng), s)) {
            const vec3 w = normalize(s.point - p);
            x = std::max(double(dot(w, normal)), 0.0) / double(s.pdf);
            // (Where the shape is seen edge-on, pdf ~ 1 / cos magnifies rounding: not compared.)
            if (std::abs(dot(s.normal, w)) > 0.01f) {
                const double again = shapeEmitterPdf(e, p, s.point, s.normal);
                worst = std::max(worst, std::abs(again / double(s.pdf) - 1.0));
            }
        }
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / kSamples;
    return {mean, std::sqrt(std::max(sum2 / kSamples - mean * mean, 0.0) / kSamples), worst};
}

double cornerViewFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

void check(const char* what, const Estimate& e, double expected) {
    qInfo("%s: %.6f vs %.6f (%+.3f %%, standard error %.3f %%), worst pdf mismatch %.2g", what, e.mean, expected,
          100.0 * (e.mean / expected - 1.0), 100.0 * e.standardError / expected, e.worstPdfMismatch);
    QVERIFY2(std::abs(e.mean / expected - 1.0) < 0.005 && std::abs(e.mean - expected) < 4.0 * e.standardError + 1e-6 * expected,
             qPrintable(QString("%1: %2 vs %3").arg(what).arg(e.mean).arg(expected)));
    QVERIFY2(e.worstPdfMismatch < 1e-3, qPrintable(QString("%1: pdf mismatch %2").arg(what).arg(e.worstPdfMismatch)));
}

} // namespace

class TestTwinShapeEmitter : public QObject {
    Q_OBJECT

private slots:
    // A 1 x 0.5 m rectangle (local 0.5 x 0.25 scaled by 2, turned about X and Y), the point 1 m
    // in front of its centre, facing it.
    void rectangle() {
        mat4 m = translate(mat4(1.0f), vec3(0.3f, 1.2f, -0.4f));
        m = rotate(m, 0.7f, vec3(0.0f, 1.0f, 0.0f));
        m = rotate(m, 0.4f, vec3(1.0f, 0.0f, 0.0f));
        m = scale(m, vec3(2.0f));
        const ShapeEmitter e = emitter(EMITTER_QUAD, 0.0f, vec3(0.5f, 1.0f, 0.25f), 1.0f, m);
        const vec3 normal = normalize(vec3(m * vec4(0.0f, 1.0f, 0.0f, 0.0f)));
        const vec3 centre = vec3(m * vec4(0.0f, 0.0f, 0.0f, 1.0f));
        check("rectangle", projectedSolidAngle(e, centre + normal, -normal), kPi * 4.0 * cornerViewFactor(0.5, 0.25, 1.0));
    }

    // A disk of radius 0.4 m, the point 1 m below its centre: pi R^2 / (h^2 + R^2).
    void disk() {
        const ShapeEmitter e = emitter(EMITTER_DISK, 0.4f, vec3(1.0f), 1.0f, mat4(1.0f));
        check("disk", projectedSolidAngle(e, vec3(0.0f, -1.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f)), kPi * 0.16 / 1.16);
    }

    // A sphere of radius 0.5 m seen from 2 m, facing its centre: pi (r / d)^2.
    void sphereOutside() {
        const ShapeEmitter e = emitter(EMITTER_SPHERE, 0.5f, vec3(1.0f), 1.0f, translate(mat4(1.0f), vec3(1.0f, 2.0f, 3.0f)));
        check("sphere outside", projectedSolidAngle(e, vec3(1.0f, 0.0f, 3.0f), vec3(0.0f, 1.0f, 0.0f)), kPi * 0.0625);
    }

    // A point on a sphere of radius 5, a few ULPs outside, facing in: it sees the whole inside, a
    // hemisphere (pi).
    void pointOnTheSphere() {
        const ShapeEmitter e = emitter(EMITTER_SPHERE, 5.0f, vec3(1.0f), 1.0f, mat4(1.0f));
        const vec3 p(0.0f, std::nextafter(std::nextafter(5.0f, 6.0f), 6.0f), 0.0f);
        check("on the sphere", projectedSolidAngle(e, p, vec3(0.0f, -1.0f, 0.0f)), kPi);
    }

    // Boxes and cylinders from outside and inside: the pdf a sample reports is the one MIS evaluates.
    void boxAndCylinderPdfsAgree() {
        const mat4 m = rotate(translate(mat4(1.0f), vec3(0.2f, 0.5f, -0.1f)), 0.5f, vec3(0.3f, 1.0f, 0.2f));
        for (const int kind : {EMITTER_BOX, EMITTER_CYLINDER}) {
            const ShapeEmitter e = emitter(kind, 0.4f, vec3(0.6f, 0.8f, 1.0f), 0.9f, m);
            for (const vec3 p : {vec3(2.0f, 0.7f, 0.3f), vec3(0.2f, 0.5f, -0.1f), vec3(0.3f, -1.5f, 0.0f)}) {
                const Estimate est = projectedSolidAngle(e, p, normalize(vec3(m[3]) - p + vec3(0.0f, 0.01f, 0.0f)));
                QVERIFY2(est.mean > 0.0 && est.worstPdfMismatch < 1e-3,
                         qPrintable(QString("kind %1: mean %2, pdf mismatch %3").arg(kind).arg(est.mean).arg(est.worstPdfMismatch)));
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestTwinShapeEmitter)
#include "test_twin_shape_emitter.moc"
