#include "renderer_suite.h"

#include "bench_scenes.h"
#include "image_metrics.h"
#include "ray_count.h"
#include "percentile.h"
#include "sample_timer.h"
#include "speed_accuracy_chart.h"

#include "renderer/output/image_files.h"
#include "renderer/output/render_plan.h"
#include "scene/io/scene_io.h"

#include <QApplication>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace glint::bench {
namespace {

using renderer::formatNumber;

struct ThroughputRow {
    std::string scene;
    std::size_t triangles = 0;
    double msMedian = 0, msMin = 0, msMax = 0;
    double setupMs = 0;     // SampleTimer::load: setScene (BVH build, upload; the driver may defer part to the first frame)
    double cpuMsMedian = 0; // process CPU time (all llvmpipe threads) per sample
    RayCount rays;
    double pathsPerSecond(int pixels) const { return pixels / (msMedian / 1000.0); }
};

double median(std::vector<double> v) { return percentile(std::move(v), 0.5); }

ThroughputRow measureThroughput(SampleTimer& timer, const BenchScene& s, const SuiteOptions& o) {
    std::fprintf(stderr, "glint: %s (%zu triangles): warm-up and %d runs of %d spp at %dx%d\n", s.name.c_str(), s.triangles,
                 o.runs, o.spp, o.width, o.height);
    ThroughputRow row;
    row.scene = s.name;
    row.triangles = s.triangles;
    row.setupMs = timer.load(s.scene, o.width, o.height, o.bounces);
    timer.render(1, 0); // warm-up: shader compilation
    std::vector<double> ms, cpu;
    for (int i = 0; i < o.runs; ++i) {
        const SampleTime t = timer.render(o.spp, static_cast<std::uint32_t>(i));
        ms.push_back(t.wallMs / o.spp);
        cpu.push_back(t.cpuMs / o.spp);
        std::fprintf(stderr, "glint:   run %d: %.1f ms/sample (CPU %.1f)\n", i + 1, ms.back(), cpu.back());
    }
    row.msMedian = median(ms);
    row.msMin = *std::min_element(ms.begin(), ms.end());
    row.msMax = *std::max_element(ms.begin(), ms.end());
    row.cpuMsMedian = median(cpu);
    // The ray count does not depend on the image size: a 128x128 grid with 2 paths each is plenty.
    row.rays = countRays(s.scene, 128, 128, o.bounces, 2);
    return row;
}

void writeThroughput(const std::filesystem::path& dir, const std::vector<ThroughputRow>& rows, const SuiteOptions& o,
                     const std::string& glRenderer) {
    const int pixels = o.width * o.height;
    std::ofstream csv(dir / "renderer_bench.csv", std::ios::binary);
    csv << "scene,triangles,width,height,bounces,spp_per_run,runs,ms_per_sample_median,ms_per_sample_min,"
           "ms_per_sample_max,cpu_ms_per_sample_median,mpaths_per_s,rays_per_path,closest_rays_per_path,shadow_rays_per_path,mrays_per_s,load_ms\n";
    std::ofstream json(dir / "renderer_bench.json", std::ios::binary);
    json << "{\n  \"gl_renderer\": \"" << glRenderer << "\",\n  \"rows\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ThroughputRow& r = rows[i];
        const double paths = static_cast<double>(r.rays.paths);
        const std::vector<std::pair<const char*, std::string>> fields{
            {"scene", r.scene},
            {"triangles", std::to_string(r.triangles)},
            {"width", std::to_string(o.width)},
            {"height", std::to_string(o.height)},
            {"bounces", std::to_string(o.bounces)},
            {"spp_per_run", std::to_string(o.spp)},
            {"runs", std::to_string(o.runs)},
            {"ms_per_sample_median", formatNumber(r.msMedian)},
            {"ms_per_sample_min", formatNumber(r.msMin)},
            {"ms_per_sample_max", formatNumber(r.msMax)},
            {"cpu_ms_per_sample_median", formatNumber(r.cpuMsMedian)},
            {"mpaths_per_s", formatNumber(r.pathsPerSecond(pixels) / 1e6)},
            {"rays_per_path", formatNumber(r.rays.raysPerPath())},
            {"closest_rays_per_path", formatNumber(static_cast<double>(r.rays.closestRays) / paths)},
            {"shadow_rays_per_path", formatNumber(static_cast<double>(r.rays.shadowRays) / paths)},
            {"mrays_per_s", formatNumber(r.pathsPerSecond(pixels) * r.rays.raysPerPath() / 1e6)},
            {"load_ms", formatNumber(r.setupMs)}};
        json << "    {";
        for (std::size_t f = 0; f < fields.size(); ++f) {
            csv << fields[f].second << (f + 1 < fields.size() ? "," : "\n");
            const bool text = f == 0;
            json << "\"" << fields[f].first << "\": " << (text ? "\"" : "") << fields[f].second << (text ? "\"" : "")
                 << (f + 1 < fields.size() ? ", " : "");
        }
        json << "}" << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    json << "  ]\n}\n";
    if (!csv || !json) throw std::runtime_error("cannot write into " + dir.string());
}

void printThroughput(const std::vector<ThroughputRow>& rows, const SuiteOptions& o) {
    const int pixels = o.width * o.height;
    std::printf("| scene | triangles | size | ms/sample median (min-max) | CPU ms/sample | Mpaths/s | rays/path | Mrays/s | load ms |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const ThroughputRow& r : rows)
        std::printf("| %s | %zu | %dx%d | %.0f (%.0f-%.0f) | %.0f | %.3f | %.2f | %.2f | %.0f |\n", r.scene.c_str(), r.triangles, o.width,
                    o.height, r.msMedian, r.msMin, r.msMax, r.cpuMsMedian, r.pathsPerSecond(pixels) / 1e6, r.rays.raysPerPath(),
                    r.pathsPerSecond(pixels) * r.rays.raysPerPath() / 1e6, r.setupMs);
}

// Cycles' convergence CSV (samples,seconds,relmse); its last row is the reference (relmse 0).
struct Curves {
    ChartCurve wall, cpu;
};

Curves readCyclesCurves(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open");
    Curves curves{{"Cycles CPU", {}}, {"Cycles CPU", {}}};
    std::string line;
    std::getline(in, line); // header: samples,seconds,relmse,cpu_seconds[,worst_share]
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string samples, seconds, error, cpuSeconds;
        if (!std::getline(fields, samples, ',') || !std::getline(fields, seconds, ',') || !std::getline(fields, error, ',') ||
            !std::getline(fields, cpuSeconds, ',')) // a worst_share column may follow
            throw std::runtime_error(file + ": bad line '" + line + "'");
        const double relmse = std::stod(error);
        if (relmse <= 0.0) continue; // the reference itself
        curves.wall.points.push_back({1000.0 * std::stod(seconds), relmse});
        curves.cpu.points.push_back({1000.0 * std::stod(cpuSeconds), relmse});
    }
    return curves;
}

bool powerOfTwo(int k) { return (k & (k - 1)) == 0; }

// One progressive render of 1 .. curveSpp samples, read back (untimed) at 1, 2, 4, ...
Curves glintConvergence(SampleTimer& timer, const Scene& scene, const SuiteOptions& o, const std::filesystem::path& dir) {
    const int size = o.convergenceSize;
    timer.load(scene, size, size, o.bounces);
    std::fprintf(stderr, "glint: Cornell box reference: %d spp at %dx%d\n", o.referenceSpp, size, size);
    renderer::RenderOutput reference;
    const SampleTime referenceTime = timer.render(o.referenceSpp, 1, [&](int k) { return k == o.referenceSpp; },
                                                  [&](int, const SampleTime&, const renderer::FrameImages& image) {
                                                      static_cast<renderer::FrameImages&>(reference) = image;
                                                  });
    renderer::writeRenderImage(dir / "glint_reference.exr", reference, renderer::parseAovList("none"),
                               {{"spp", std::to_string(o.referenceSpp)}});
    const std::string label = "Glint (" + timer.glRenderer() + ")"; // the device it ran on
    Curves curves{{label, {}}, {label, {}}};
    std::ofstream csv(dir / "glint_convergence.csv", std::ios::binary);
    csv << "samples,seconds,relmse,cpu_seconds\n";
    timer.render(o.curveSpp, 0, powerOfTwo, [&](int k, const SampleTime& t, const renderer::FrameImages& image) {
        const double error = relMse(image.radiance, reference.radiance);
        curves.wall.points.push_back({t.wallMs, error});
        curves.cpu.points.push_back({t.cpuMs, error});
        csv << k << "," << formatNumber(t.wallMs / 1000.0) << "," << formatNumber(error) << "," << formatNumber(t.cpuMs / 1000.0) << "\n";
        std::printf("glint: %5d spp  %9.3f s  (CPU %.3f s)  relMSE %.6g\n", k, t.wallMs / 1000.0, t.cpuMs / 1000.0, error);
    });
    csv << o.referenceSpp << "," << formatNumber(referenceTime.wallMs / 1000.0) << ",0," << formatNumber(referenceTime.cpuMs / 1000.0) << "\n";
    std::printf("glint: reference %d spp  %.3f s  (CPU %.3f s)\n", o.referenceSpp, referenceTime.wallMs / 1000.0,
                referenceTime.cpuMs / 1000.0);
    return curves;
}

// Two charts: against wall time (convergence.png/.svg) and against process CPU time
// (convergence_cpu.png/.svg), the fairer axis when the machine is shared.
void drawConvergenceCharts(const std::vector<Curves>& curves, const std::filesystem::path& dir, const SuiteOptions& o) {
    qputenv("QT_QPA_PLATFORM", "offscreen"); // charts only; the bench opens no window
    int argc = 1;
    char name[] = "glint";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    const std::string size = std::to_string(o.convergenceSize);
    const std::string title = "Cornell box, " + size + "x" + size + ", " + std::to_string(o.bounces) +
                              " bounces: relMSE against each renderer's converged image";
    std::vector<ChartCurve> wall, cpu;
    for (const Curves& c : curves) wall.push_back(c.wall), cpu.push_back(c.cpu);
    writeSpeedAccuracyChart(wall, title + " (wall time)", (dir / "convergence.png").string(), (dir / "convergence.svg").string());
    writeSpeedAccuracyChart(cpu, title + " (CPU time)", (dir / "convergence_cpu.png").string(),
                            (dir / "convergence_cpu.svg").string());
}

} // namespace

int runRendererSuite(const SuiteOptions& o) {
    const LoadResult loaded = loadScene(o.cornellBox);
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);
    SampleTimer timer;
    std::fprintf(stderr, "glint: GL_RENDERER: %s\n", timer.glRenderer().c_str());
    if (o.throughput) {
        std::vector<ThroughputRow> rows;
        SaveOptions glbOnly;
        glbOnly.writeProjectFile = false;
        for (const BenchScene& s : benchScenes(loaded.scene, o.bunny)) {
            if (o.writeScenes) saveScene(s.scene, dir / (s.name + ".glb"), glbOnly);
            rows.push_back(measureThroughput(timer, s, o));
        }
        writeThroughput(dir, rows, o, timer.glRenderer());
        printThroughput(rows, o);
    }
    if (o.convergence) {
        Scene cornell = loaded.scene;
        if (o.lambert) // KHR_materials_specular 0: pure Lambert, as Cycles' Diffuse BSDF (--materials diffuse)
            for (auto& [id, material] : cornell.materials) material.specularFactor = 0.0f;
        std::vector<Curves> curves{glintConvergence(timer, cornell, o, dir)};
        if (!o.cyclesCsv.empty()) curves.push_back(readCyclesCurves(o.cyclesCsv));
        drawConvergenceCharts(curves, dir, o);
    }
    std::fprintf(stderr, "glint: wrote %s\n", dir.string().c_str());
    return 0;
}

} // namespace glint::bench
