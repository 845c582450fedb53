// Adaptive sampling against uniform sampling: render time to a target error. A program, not a test;
// figures in docs/PERFORMANCE.md, "Adaptive sampling". Two scenes:
// - cornell: the bundled Cornell box, lit by a small ceiling light: its walls are about equally
//   noisy relative to their brightness, but for the black surround and a few firefly-prone pixels;
// - shelter: a roof on a back wall on a sunlit ground under a blue sky, built here: the sunlit
//   ground converges in a few samples (the sun is sampled directly) but costs whole paths like any
//   pixel, while the shade under the roof is lit only by bounced light and stays noisy.
//   bench_adaptive REF.exr [--scene cornell|shelter] [--reference-spp 4096] [--size 128] [--bounces 4]
//       [--uniform 16,32,...] [--thresholds 0.04,...] [--goal even|mean]
//       [--cap 1024] [--min-spp 0] [--runs 3] [--csv OUT.csv] [--chart OUT.png] [--from-csv IN.csv]
// --from-csv: no renders; the table, the times to each target and the chart from an earlier --csv.
// REF.exr: a converged render of the same scene, size and bounces, rendered first (seed 1000,
// --reference-spp) when the file does not exist. Each
// configuration renders --runs times (seed 0); the median render time is taken, relMSE as glint
// bench defines it. Time to a target relMSE is interpolated on each curve in log-log.
#include "error_share.h"
#include "scene_builder.h"
#include "speed_accuracy_chart.h"

#include "renderer/offline_render.h"
#include "scene/io/scene_io.h"

#include <QApplication>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace glint;

namespace {

struct Options {
    std::string reference, csv, chart, fromCsv, scene = "cornell";
    int size = 128, bounces = 4, cap = 1024, minSpp = 0, runs = 3, referenceSpp = 4096;
    std::vector<int> uniform = {16, 32, 64, 128, 256, 512, 1024};
    std::vector<double> thresholds = {0.08, 0.04, 0.02, 0.01, 0.005};
    AdaptiveGoal goal = AdaptiveGoal::Even;
};

template <class T> std::vector<T> parseList(const char* text) {
    std::vector<T> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) values.push_back(static_cast<T>(std::atof(item.c_str())));
    return values;
}

Options parse(int argc, char** argv) {
    Options o;
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_adaptive REF.exr [options] (see the source)\n");
        std::exit(2);
    }
    o.reference = argv[1];
    for (int i = 2; i < argc; ++i) {
        const auto next = [&]() -> const char* {
            if (i + 1 >= argc) std::exit(2);
            return argv[++i];
        };
        if (!std::strcmp(argv[i], "--size")) o.size = std::atoi(next());
        else if (!std::strcmp(argv[i], "--bounces")) o.bounces = std::atoi(next());
        else if (!std::strcmp(argv[i], "--cap")) o.cap = std::atoi(next());
        else if (!std::strcmp(argv[i], "--min-spp")) o.minSpp = std::atoi(next());
        else if (!std::strcmp(argv[i], "--runs")) o.runs = std::atoi(next());
        else if (!std::strcmp(argv[i], "--uniform")) o.uniform = parseList<int>(next());
        else if (!std::strcmp(argv[i], "--thresholds")) o.thresholds = parseList<double>(next());
        else if (!std::strcmp(argv[i], "--goal")) {
            const char* name = next();
            const auto goal = parseAdaptiveGoal(name);
            if (!goal) {
                std::fprintf(stderr, "bench_adaptive: unknown goal %s (even, mean)\n", name);
                std::exit(2);
            }
            o.goal = *goal;
        }
        else if (!std::strcmp(argv[i], "--csv")) o.csv = next();
        else if (!std::strcmp(argv[i], "--chart")) o.chart = next();
        else if (!std::strcmp(argv[i], "--from-csv")) o.fromCsv = next();
        else if (!std::strcmp(argv[i], "--scene")) o.scene = next();
        else if (!std::strcmp(argv[i], "--reference-spp")) o.referenceSpp = std::atoi(next());
        else {
            std::fprintf(stderr, "bench_adaptive: unknown option %s\n", argv[i]);
            std::exit(2);
        }
    }
    return o;
}

// A roof (2.4 x 2.4 m, 1.2 m up) on a back wall, on a grey ground, a sun from the front-left at 50
// degrees, a blue sky; the camera looks into the shade from the front.
Scene shelter() {
    Scene scene;
    const MaterialId grey = scene.materials.add(test::lambert(glm::vec3(0.5f)));
    const MaterialId white = scene.materials.add(test::lambert(glm::vec3(0.8f)));
    test::addShape(scene, ShapeKind::GroundPlane, grey, {0.0f, 0.0f, 0.0f});
    test::addShape(scene, ShapeKind::Box, white, {0.0f, 1.25f, 0.0f}, 0.5f, {2.4f, 0.1f, 2.4f});  // the roof
    test::addShape(scene, ShapeKind::Box, white, {0.0f, 0.6f, -1.15f}, 0.5f, {2.4f, 1.2f, 0.1f}); // the back wall
    test::addSun(scene, {0.5f, -1.2f, -0.6f}, 3.0f, 0.5f);
    scene.settings.environment.color = {0.25f, 0.35f, 0.55f};
    test::addPerspectiveCamera(scene, {1.2f, 1.1f, 4.2f}, {0.0f, 0.6f, 0.0f}, 0.7f);
    return scene;
}

Scene benchScene(const std::string& name) {
    if (name == "shelter") return shelter();
    if (name != "cornell") {
        std::fprintf(stderr, "bench_adaptive: unknown scene '%s' (cornell, shelter)\n", name.c_str());
        std::exit(2);
    }
    return loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf").scene;
}

// The converged image: read from `o.reference`, rendered and written there first if it is missing.
std::vector<float> referenceImage(const Options& o, const Scene& scene) {
    int w = 0, h = 0;
    if (std::filesystem::exists(o.reference)) {
        std::vector<float> image = test::readExrRgba(o.reference, w, h);
        if (image.empty() || w != o.size || h != o.size) {
            std::fprintf(stderr, "bench_adaptive: %s: not a %dx%d EXR\n", o.reference.c_str(), o.size, o.size);
            std::exit(1);
        }
        return image;
    }
    renderer::RenderRequest request;
    request.width = request.height = o.size;
    request.bounces = o.bounces;
    request.spp = o.referenceSpp;
    request.seed = 1000;
    const renderer::RenderOutput out = renderer::renderOffline(scene, request);
    test::writeExrRgb(o.reference, out.radiance, o.size, o.size);
    std::fprintf(stderr, "wrote the reference %s (%d spp, %.0f s)\n", o.reference.c_str(), o.referenceSpp, out.timings.renderMs / 1000.0);
    return out.radiance;
}

struct Point {
    std::string mode;      // "uniform", "adaptive" (goal even) or "mean" (goal mean)
    double threshold = 0.0;
    int spp = 0;           // uniform: spp; adaptive: the cap
    double meanSpp = 0.0;  // samples per pixel taken, on average
    double ms = 0.0;       // median render time
    double relMse = 0.0;
    double worstShare = 0.0;
    double worstTile = 0.0; // relMSE of the noisiest 8x8 tile: the patch of noise a viewer sees first
};

// The largest mean relMSE over the image's 8x8 tiles.
double worstTileRelMse(const std::vector<float>& image, const std::vector<float>& reference, int size) {
    const std::vector<double> perPixel = test::pixelRelMse(image, reference);
    double worst = 0.0;
    for (int ty = 0; ty + 8 <= size; ty += 8)
        for (int tx = 0; tx + 8 <= size; tx += 8) {
            double sum = 0.0;
            for (int y = ty; y < ty + 8; ++y)
                for (int x = tx; x < tx + 8; ++x) sum += perPixel[std::size_t(y) * std::size_t(size) + std::size_t(x)];
            worst = std::max(worst, sum / 64.0);
        }
    return worst;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

Point measure(renderer::OfflineRenderer& renderer, const Scene& scene, const Options& o, const std::vector<float>& reference,
              int spp, double threshold) {
    renderer::RenderRequest request;
    request.width = request.height = o.size;
    request.bounces = o.bounces;
    request.spp = spp;
    request.adaptive = {.threshold = float(threshold), .minSamples = o.minSpp, .goal = o.goal};
    std::vector<double> times;
    renderer::RenderOutput out;
    for (int run = 0; run < o.runs; ++run) {
        out = renderer.render(scene, request);
        times.push_back(out.timings.renderMs);
    }
    const char* mode = threshold <= 0.0 ? "uniform" : o.goal == AdaptiveGoal::Mean ? "mean" : "adaptive";
    Point p{mode, threshold, spp, 0.0, median(times), 0.0, 0.0, 0.0};
    double total = 0.0;
    for (const float c : out.sampleCounts) total += c;
    p.meanSpp = total / double(std::max<std::size_t>(1, out.sampleCounts.size()));
    const test::ErrorShare e = test::errorShare(out.radiance, reference);
    p.relMse = e.relMse;
    p.worstShare = e.worstShare;
    p.worstTile = worstTileRelMse(out.radiance, reference, o.size);
    return p;
}

// The points of an earlier --csv, split by mode.
void readCsv(const std::string& file, std::vector<Point>& uniform, std::vector<Point>& adaptive) {
    std::FILE* in = std::fopen(file.c_str(), "r");
    if (!in) return;
    char mode[32];
    Point p;
    std::fscanf(in, "%*[^\n]\n"); // the header
    while (std::fscanf(in, "%31[^,],%lf,%d,%lf,%lf,%lf,%lf,%lf\n", mode, &p.threshold, &p.spp, &p.meanSpp, &p.ms, &p.relMse,
                       &p.worstShare, &p.worstTile) == 8) {
        p.mode = mode;
        (p.mode == "uniform" ? uniform : adaptive).push_back(p);
    }
    std::fclose(in);
}

// relMSE against render time, one curve per mode (PNG, and SVG beside it), on Qt's offscreen platform.
void drawChart(const Options& o, const std::vector<Point>& uniform, const std::vector<Point>& adaptive) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    int argc = 1;
    char name[] = "bench_adaptive";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    const auto curve = [](const std::string& label, const std::vector<Point>& points, double Point::*error) {
        bench::ChartCurve c{label, {}};
        for (const Point& p : points) c.points.push_back({p.ms, p.*error});
        std::sort(c.points.begin(), c.points.end(), [](const auto& a, const auto& b) { return a.ms < b.ms; });
        return c;
    };
    const std::string svg = o.chart.substr(0, o.chart.rfind('.')) + ".svg";
    const std::string goal = adaptive.empty() || adaptive.front().mode == "adaptive" ? "adaptive" : "adaptive, goal " + adaptive.front().mode;
    bench::writeSpeedAccuracyChart({curve("uniform: relMSE", uniform, &Point::relMse),
                                    curve(goal + ": relMSE", adaptive, &Point::relMse),
                                    curve("uniform: worst 8x8 tile", uniform, &Point::worstTile),
                                    curve(goal + ": worst 8x8 tile", adaptive, &Point::worstTile)},
                                   o.scene + ", " + std::to_string(o.size) + "x" + std::to_string(o.size) + ", " +
                                       std::to_string(o.bounces) + " bounces, adaptive capped at " + std::to_string(o.cap) +
                                       " spp: relMSE against render time",
                                   o.chart, svg);
}

// The time at which `curve` (falling relMSE) reaches `target`, interpolated in log-log; unset
// outside the measured range.
std::optional<double> timeTo(std::vector<Point> curve, double target, double Point::*error = &Point::relMse) {
    std::sort(curve.begin(), curve.end(), [](const Point& a, const Point& b) { return a.ms < b.ms; });
    for (std::size_t i = 1; i < curve.size(); ++i) {
        const Point& a = curve[i - 1];
        const Point& b = curve[i];
        if (a.*error >= target && b.*error <= target) {
            const double t = std::log(target / a.*error) / std::log(b.*error / a.*error);
            return std::exp(std::log(a.ms) + t * (std::log(b.ms) - std::log(a.ms)));
        }
    }
    return std::nullopt;
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    const Scene scene = benchScene(o.scene);
    const std::vector<float> reference = referenceImage(o, scene);
    std::vector<Point> uniform, adaptive;
    std::printf("mode       threshold   spp  mean spp   median ms    relMSE  worst 0.1%% share  worst 8x8 tile\n");
    const auto print = [](const Point& p) {
        std::printf("%-9s  %9.4g  %4d  %8.1f  %10.1f  %8.3g  %15.1f %%  %14.3g\n", p.mode.c_str(), p.threshold, p.spp, p.meanSpp,
                    p.ms, p.relMse, 100.0 * p.worstShare, p.worstTile);
        std::fflush(stdout);
    };
    if (!o.fromCsv.empty()) {
        readCsv(o.fromCsv, uniform, adaptive);
        for (const auto* curve : {&uniform, &adaptive})
            for (const Point& p : *curve) print(p);
    } else {
        renderer::OfflineRenderer renderer;
        Options warmUp = o;
        warmUp.runs = 1;
        measure(renderer, scene, warmUp, reference, 4, 0.0); // compiles the programs
        for (const int spp : o.uniform) print(uniform.emplace_back(measure(renderer, scene, o, reference, spp, 0.0)));
        for (const double t : o.thresholds) print(adaptive.emplace_back(measure(renderer, scene, o, reference, o.cap, t)));
    }
    if (!o.csv.empty()) {
        if (FILE* csv = std::fopen(o.csv.c_str(), "w")) {
            std::fprintf(csv, "mode,threshold,spp,mean_spp,median_ms,relmse,worst_share,worst_tile\n");
            for (const auto* curve : {&uniform, &adaptive})
                for (const Point& p : *curve)
                    std::fprintf(csv, "%s,%g,%d,%.3f,%.3f,%.8g,%.6f,%.8g\n", p.mode.c_str(), p.threshold, p.spp, p.meanSpp, p.ms,
                                 p.relMse, p.worstShare, p.worstTile);
            std::fclose(csv);
        }
    }
    if (!o.chart.empty()) drawChart(o, uniform, adaptive);
    for (const auto& [name, error] : {std::pair{"relMSE", &Point::relMse}, std::pair{"worst tile", &Point::worstTile}}) {
        std::printf("\ntarget %-10s   uniform ms   adaptive ms   uniform / adaptive\n", name);
        for (const double target : {1e-2, 5e-3, 2e-3, 1e-3, 5e-4}) {
            const auto u = timeTo(uniform, target, error);
            const auto a = timeTo(adaptive, target, error);
            std::printf("%17.0e   %10s   %11s   %s\n", target, u ? std::to_string(int(*u)).c_str() : "-",
                        a ? std::to_string(int(*a)).c_str() : "-", u && a ? std::to_string(*u / *a).substr(0, 4).c_str() : "-");
        }
    }
    return 0;
}
