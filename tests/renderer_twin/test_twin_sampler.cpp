// The low-discrepancy stream of shaders/common/rng.glsl through its C++ twin (Owen-scrambled Sobol',
// Burley 2020): Sobol' dimension 1 equals the textbook construction, the first 2^k samples of every
// draw are (0,k,2)-nets (2D) and stratified (1D) in every pixel and dimension, and so is each
// following block of 2^k, scrambling and shuffling decorrelate pixels and dimensions, the independent
// stream is untouched, and the points integrate a smooth function with far less error than
// independent samples.
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace glint::twin;

namespace {

// Sobol' dimension 1 the textbook way: primitive polynomial x + 1, m_1 = 1, m_k = 2 m_(k-1) xor
// m_(k-1), direction numbers v_k = m_k / 2^k as 32-bit fractions, point = xor of v_(j+1) over the
// index's set bits j.
uint textbookSobolDimension1(uint index) {
    std::array<uint, 32> v{};
    std::uint64_t m = 1;
    for (int k = 1; k <= 32; ++k) {
        if (k > 1) m = (2 * m) ^ m;
        v[static_cast<std::size_t>(k - 1)] = static_cast<uint>(m << (32 - k));
    }
    uint x = 0;
    for (int j = 0; j < 32; ++j)
        if ((index >> j) & 1u) x ^= v[static_cast<std::size_t>(j)];
    return x;
}

// Draw `dimension` of sample `index` of a pixel's low-discrepancy stream (a draw depends on its
// key and dimension only, so the draws before it need not be made).
template <class Draw>
auto drawAt(uvec2 pixel, uint index, uint seed, int dimension, Draw draw) {
    Rng r = rngStartLowDiscrepancy(pixel, index, seed);
    r.dimension = static_cast<uint>(dimension);
    return draw(r);
}

// One point per elementary interval 2^-a x 2^-(k-a) for every a: a (0,k,2)-net in base 2.
bool isNet(const std::vector<vec2>& points, int k) {
    for (int a = 0; a <= k; ++a) {
        const int nx = 1 << a, ny = 1 << (k - a);
        std::vector<int> cells(static_cast<std::size_t>(nx * ny), 0);
        for (const vec2 p : points) {
            const int cx = std::min(nx - 1, static_cast<int>(p.x * static_cast<float>(nx)));
            const int cy = std::min(ny - 1, static_cast<int>(p.y * static_cast<float>(ny)));
            if (++cells[static_cast<std::size_t>(cy * nx + cx)] > 1) return false;
        }
    }
    return true;
}

bool isStratified(const std::vector<float>& values, int k) {
    std::vector<int> strata(static_cast<std::size_t>(1 << k), 0);
    for (const float v : values)
        if (++strata[static_cast<std::size_t>(std::min((1 << k) - 1, static_cast<int>(v * static_cast<float>(1 << k))))] > 1) return false;
    return true;
}

} // namespace

class TwinSamplerTest : public QObject {
    Q_OBJECT
private slots:
    void sobolDimension1MatchesTextbook() {
        for (uint index = 0; index < 4096u; ++index) QCOMPARE(sobolDimension1(index), textbookSobolDimension1(index));
        uint i = 1u; // 32-bit indices of every size
        for (int n = 0; n < 10000; ++n, i = i * 2654435761u + 12345u) QCOMPARE(sobolDimension1(i), textbookSobolDimension1(i));
        QCOMPARE(sobolDimension1(0xffffffffu), textbookSobolDimension1(0xffffffffu));
    }

    // The scramble is a bijection of 32-bit values that keeps prefixes: values equal in their top b
    // bits stay equal in their top b bits (what Owen scrambling means).
    void scrambleIsOwen() {
        const uint seed = 0x1234567u;
        for (uint x = 0; x < 5000u; ++x) {
            const uint y = x * 0x9e3779b9u;
            const uint z = y ^ (1u << (x % 31u)); // differs from y below bit (x % 31) + 1 only
            const uint top = ~0u << ((x % 31u) + 1u);
            QVERIFY((nestedUniformScramble(y, seed) & top) == (nestedUniformScramble(z, seed) & top));
            QVERIFY(nestedUniformScramble(y, seed) != nestedUniformScramble(z, seed));
        }
    }

    // For pixels, seeds and dimensions alike, samples [0, 2^k) and [2^k, 2^(k+1)) of rand2 and of
    // rand3's (y, z) are (0,k,2)-nets, and rand1 and rand3's x put one value in each of 2^k strata.
    void blocksOfSamplesAreNets() {
        const std::array<uvec2, 3> pixels = {uvec2(0u, 0u), uvec2(17u, 93u), uvec2(1023u, 4u)};
        for (const uvec2 pixel : pixels)
            for (const uint seed : {0u, 7u})
                for (int dimension : {0, 1, 5, 23})
                    for (int k : {4, 6, 8})
                        for (uint block = 0; block < 2u; ++block) {
                            std::vector<vec2> pairs, triples;
                            std::vector<float> singles, choices;
                            const uint first = block << k;
                            for (uint i = first; i < first + (1u << k); ++i) {
                                pairs.push_back(drawAt(pixel, i, seed, dimension, [](Rng& r) { return rand2(r); }));
                                const vec3 t = drawAt(pixel, i, seed, dimension, [](Rng& r) { return rand3(r); });
                                triples.push_back(vec2(t.y, t.z));
                                choices.push_back(t.x);
                                singles.push_back(drawAt(pixel, i, seed, dimension, [](Rng& r) { return rand1(r); }));
                            }
                            const QString where = QString("pixel %1,%2 seed %3 dimension %4 k %5 block %6")
                                                      .arg(pixel.x).arg(pixel.y).arg(seed).arg(dimension).arg(k).arg(block);
                            QVERIFY2(isNet(pairs, k), qPrintable("rand2, " + where));
                            QVERIFY2(isNet(triples, k), qPrintable("rand3 (y, z), " + where));
                            QVERIFY2(isStratified(choices, k), qPrintable("rand3 x, " + where));
                            QVERIFY2(isStratified(singles, k), qPrintable("rand1, " + where));
                        }
    }

    // Padding: two draws of one path (dimensions d and d + 1) are not the same sequence twice. Over
    // 1024 samples of a pixel, their first components fill a 32 x 32 grid like independent points
    // (expected 1024 (1 - (1 - 1/1024)^1024) = 647 occupied cells; a shared order would give 32),
    // and correlate by less than 0.1.
    void dimensionsAreDecorrelated() {
        for (int d = 0; d < 6; ++d) {
            std::vector<int> cells(1024, 0);
            double sxy = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
            for (uint i = 0; i < 1024u; ++i) {
                Rng r = rngStartLowDiscrepancy(uvec2(5u, 6u), i, 3u);
                r.dimension = static_cast<uint>(d);
                const float x = rand2(r).x;
                const float y = rand2(r).x;
                cells[static_cast<std::size_t>(static_cast<int>(y * 32.0f) * 32 + static_cast<int>(x * 32.0f))] = 1;
                sx += x, sy += y, sxy += double(x) * y, sxx += double(x) * x, syy += double(y) * y;
            }
            int occupied = 0;
            for (const int c : cells) occupied += c;
            const double n = 1024.0;
            const double corr = (sxy / n - sx / n * sy / n) / std::sqrt((sxx / n - sx * sx / n / n) * (syy / n - sy * sy / n / n));
            QVERIFY2(occupied > 560 && occupied < 730, qPrintable(QString("dimension %1: %2 cells").arg(d).arg(occupied)));
            QVERIFY2(std::abs(corr) < 0.1, qPrintable(QString("dimension %1: correlation %2").arg(d).arg(corr)));
        }
    }

    // Pixels are scrambled apart: sample 0 of 4096 pixels is uniform over 16 x 16 cells (chi-square
    // within 5 sigma of its mean, dof 255) and no two pixels share their first point.
    void pixelsAreScrambledApart() {
        std::vector<int> cells(256, 0);
        std::vector<vec2> firsts;
        for (uint p = 0; p < 4096u; ++p) {
            Rng r = rngStartLowDiscrepancy(uvec2(p % 64u, p / 64u), 0u, 0u);
            const vec2 u = rand2(r);
            ++cells[static_cast<std::size_t>(static_cast<int>(u.y * 16.0f) * 16 + static_cast<int>(u.x * 16.0f))];
            firsts.push_back(u);
        }
        double chi2 = 0.0;
        for (const int c : cells) chi2 += (c - 16.0) * (c - 16.0) / 16.0;
        QVERIFY2(std::abs(chi2 - 255.0) < 5.0 * std::sqrt(2.0 * 255.0), qPrintable(QString("chi2 %1").arg(chi2)));
        std::sort(firsts.begin(), firsts.end(), [](vec2 a, vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        QVERIFY(std::adjacent_find(firsts.begin(), firsts.end()) == firsts.end());
    }

    // The same draw gives the same bits every time (no state beyond the key), and the independent
    // stream is the one test_twin_rng pins: the low-discrepancy key does not leak into it.
    void deterministicAndSeparate() {
        Rng a = rngStartLowDiscrepancy(uvec2(9u, 9u), 300u, 42u);
        Rng b = rngStartLowDiscrepancy(uvec2(9u, 9u), 300u, 42u);
        QCOMPARE(rand3(a), rand3(b));
        QCOMPARE(rand2(a), rand2(b));
        Rng r = rngStart(uvec2(3u, 5u), 7u, 11u);
        rand1(r);
        rand1(r);
        QCOMPARE(rand1(r), 0.6838541030883789f);
        Rng s = rngStartLowDiscrepancy(uvec2(3u, 5u), 7u, 11u);
        QCOMPARE(s.key, r.key); // the per-sample key (alpha bits) is the independent stream's
    }

    // Integrating f(x, y) = exp(-(x^2 + y^2)) cos(3x) over the unit square with 256 points, in 64
    // pixels: the RMS error of the scrambled Sobol' points is below a tenth of independent points'
    // (for a smooth integrand it falls like N^-1.5 against N^-0.5: about 16x here).
    void integratesBetterThanIndependent() {
        const auto f = [](vec2 u) { return std::exp(-(u.x * u.x + u.y * u.y)) * std::cos(3.0 * u.x); };
        // Reference by a 2048^2 midpoint rule.
        double exact = 0.0;
        for (int j = 0; j < 2048; ++j)
            for (int i = 0; i < 2048; ++i) exact += f(vec2((i + 0.5f) / 2048.0f, (j + 0.5f) / 2048.0f));
        exact /= 2048.0 * 2048.0;
        double lowDiscrepancy = 0.0, independent = 0.0;
        for (uint p = 0; p < 64u; ++p) {
            double a = 0.0, b = 0.0;
            for (uint i = 0; i < 256u; ++i) {
                Rng r = rngStartLowDiscrepancy(uvec2(p, 1u), i, 0u);
                Rng s = rngStart(uvec2(p, 1u), i, 0u);
                a += f(rand2(r));
                b += f(rand2(s));
            }
            lowDiscrepancy += (a / 256.0 - exact) * (a / 256.0 - exact);
            independent += (b / 256.0 - exact) * (b / 256.0 - exact);
        }
        const double ratio = std::sqrt(lowDiscrepancy / independent);
        QVERIFY2(ratio < 0.1, qPrintable(QString("RMS error ratio %1").arg(ratio)));
    }
};

QTEST_APPLESS_MAIN(TwinSamplerTest)
#include "test_twin_sampler.moc"
