// glint bench SCENE: for each configuration, N frames of a still view, timed per frame (median and
// spread, finished on the GPU) and compared with a converged reference (relMSE, SSIM as docs/CLI.md
// defines them). Writes bench.csv, bench.json and the speed-vs-accuracy chart (PNG + SVG), and
// prints the table. Scenes with a camera path or animation are also run along it
// (bench_camera_path.h: bench_path.csv, bench_path.json, speed_accuracy_path.png/.svg, same columns).
// Headless: the chart is drawn on Qt's offscreen platform, set only here.
#include "bench_camera_path.h"
#include "command.h"
#include "common_options.h"
#include "exit_codes.h"
#include "render_setup.h"
#include "report.h"
#include "scene_defaults.h"
#include "scene_file.h"

#include "image_metrics.h"
#include "percentile.h"
#include "renderer_suite_cli.h"
#include "speed_accuracy_chart.h"

#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"

#include <QApplication>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace glint::cli {
namespace {

struct BenchOptions {
    std::string scene;
    std::vector<std::string> configs{"baseline", "realistic", "full", "heavy", "accumulate"};
    int frames = 32;
    Size size{128, 128};
    std::string out = "bench";
    std::optional<int> spp;
    std::uint32_t seed = 0;
    std::optional<int> bounces;
    std::string camera;
    std::string env;
    int referenceSpp = 1024;
    bool denoise = false; // Accumulate and Reference also measured through the mean denoiser
    PathBenchOptions path;
};

// One sampled frame of a row: its number, the time so far, and its errors.
struct BenchSample {
    int frame = 0;
    double ms = 0, relmse = 0, ssim = 0;
};

struct BenchRow {
    renderer::Configuration config{};
    int spp = 1, bounces = 0, frames = 0;
    double msMedian = 0, msP10 = 0, msP90 = 0, relmse = 0, ssim = 0;
    bench::ChartCurve curve;
    bool denoised = false;
    std::vector<BenchSample> samples;
};

// "accumulate", or "accumulate+denoise" for a mean shown through the denoiser.
std::string rowName(const BenchRow& r) {
    return std::string(renderer::configurationName(r.config)) + (r.denoised ? "+denoise" : "");
}

using Clock = std::chrono::steady_clock;

renderer::FrameSettings settingsFor(const BenchOptions& o, const Scene& scene, renderer::Configuration config,
                                    bool denoise = false) {
    renderer::FrameSettings s;
    s.configuration = config;
    s.spp = o.spp.value_or(0);
    s.bounces = o.bounces.value_or(scene.settings.render.bounces);
    s.seed = o.seed;
    s.width = o.size.width;
    s.height = o.size.height;
    s.denoise = denoise;
    return s;
}

// The converged image every configuration is measured against (another seed than the runs).
std::vector<float> renderReference(renderer::FrameRenderer& frames, const BenchOptions& o, const Scene& scene) {
    renderer::FrameSettings s = settingsFor(o, scene, renderer::Configuration::Reference);
    s.spp = o.referenceSpp;
    s.seed = o.seed + 0x9e3779b9u;
    frames.setSettings(s);
    frames.resetHistory();
    frames.renderFrame();
    return frames.readImages().radiance;
}

// Errors are sampled at frames 1, 2, 4, ... and the last one (reading back costs time not counted).
bool sampledFrame(int frame, int last) { return frame == last || (frame & (frame - 1)) == 0; }

BenchRow runConfiguration(renderer::FrameRenderer& frames, const BenchOptions& o, const Scene& scene,
                          renderer::Configuration config, const std::vector<float>& reference, bool denoise) {
    const renderer::FrameSettings s = settingsFor(o, scene, config, denoise);
    frames.setSettings(s);
    frames.resetHistory();
    frames.renderFrame(); // warm-up: shader compilation is not a frame time
    glFinish();
    frames.resetHistory();
    BenchRow row;
    row.config = config;
    row.spp = s.spp > 0 ? s.spp : renderer::traitsOf(config).sppPerFrame;
    row.bounces = renderer::traitsOf(config).gi ? s.bounces : 0;
    row.frames = o.frames;
    row.denoised = s.denoise;
    row.curve.name = rowName(row);
    std::vector<double> ms;
    double total = 0.0;
    std::vector<float> last;
    for (int f = 1; f <= o.frames; ++f) {
        const auto start = Clock::now();
        frames.renderFrame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        total += ms.back();
        if (!sampledFrame(f, o.frames)) continue;
        last = frames.readImages().radiance;
        row.curve.points.push_back({total, bench::relMse(last, reference)});
        row.samples.push_back({f, total, row.curve.points.back().relmse, bench::ssim(last, reference, o.size.width, o.size.height)});
    }
    row.msMedian = bench::percentile(ms, 0.5);
    row.msP10 = bench::percentile(ms, 0.1);
    row.msP90 = bench::percentile(ms, 0.9);
    row.relmse = bench::relMse(last, reference);
    row.ssim = bench::ssim(last, reference, o.size.width, o.size.height);
    return row;
}

// The camera-path rows in the still rows' shape: the same columns, table and chart.
std::vector<BenchRow> benchRows(const std::vector<PathBenchRow>& path) {
    std::vector<BenchRow> rows;
    for (const PathBenchRow& p : path)
        rows.push_back({p.config, p.spp, p.bounces, p.frames, p.msMedian, p.msP10, p.msP90, p.relmse, p.ssim, p.curve, false, {}});
    return rows;
}

const char* yesNo(bool b) { return b ? "yes" : "no"; }

std::string csvLine(const BenchRow& r) {
    const auto t = renderer::traitsOf(r.config);
    std::string line = rowName(r);
    for (const std::string& v : {std::to_string(r.spp), std::to_string(r.bounces), std::string(yesNo(t.gi)),
                                 std::string(yesNo(t.ao)), std::string(yesNo(t.taa)), std::string(yesNo(t.svgf)),
                                 std::to_string(r.frames), formatNumber(r.msMedian), formatNumber(r.msP10),
                                 formatNumber(r.msP90), formatNumber(1000.0 / r.msMedian), formatNumber(r.relmse),
                                 formatNumber(r.ssim)})
        line += "," + v;
    return line;
}

const char* kColumns = "config,spp,bounces,gi,ao,taa,svgf,frames,ms_median,ms_p10,ms_p90,fps,relmse,ssim";

void writeCsv(const std::filesystem::path& file, const std::vector<BenchRow>& rows) {
    std::ofstream out(file, std::ios::binary);
    out << kColumns << "\n";
    for (const BenchRow& r : rows) out << csvLine(r) << "\n";
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

void writeJson(const std::filesystem::path& file, const std::vector<BenchRow>& rows) {
    std::ofstream out(file, std::ios::binary);
    out << "[\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto t = renderer::traitsOf(rows[i].config);
        const BenchRow& r = rows[i];
        out << "  {\"config\": \"" << rowName(r) << "\", \"spp\": " << r.spp
            << ", \"bounces\": " << r.bounces << ", \"gi\": " << (t.gi ? "true" : "false")
            << ", \"ao\": " << (t.ao ? "true" : "false") << ", \"taa\": " << (t.taa ? "true" : "false")
            << ", \"svgf\": " << (t.svgf ? "true" : "false") << ", \"frames\": " << r.frames
            << ", \"ms_median\": " << formatNumber(r.msMedian) << ", \"ms_p10\": " << formatNumber(r.msP10)
            << ", \"ms_p90\": " << formatNumber(r.msP90) << ", \"fps\": " << formatNumber(1000.0 / r.msMedian)
            << ", \"relmse\": " << formatNumber(r.relmse) << ", \"ssim\": " << formatNumber(r.ssim) << ", \"samples\": [";
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            const BenchSample& p = r.samples[k];
            out << (k ? ", " : "") << "{\"frame\": " << p.frame << ", \"ms\": " << formatNumber(p.ms)
                << ", \"relmse\": " << formatNumber(p.relmse) << ", \"ssim\": " << formatNumber(p.ssim) << "}";
        }
        out << "]}" << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    out << "]\n";
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

void printTable(const std::vector<BenchRow>& rows) {
    std::printf("%-18s %4s %-6s %-8s %9s %7s %9s %7s\n", "config", "spp", "GI/AO", "TAA/SVGF", "ms/frame", "fps",
                "relMSE", "SSIM");
    for (const BenchRow& r : rows) {
        const auto t = renderer::traitsOf(r.config);
        const std::string giAo = std::string(t.gi ? "GI" : "-") + "/" + (t.ao ? "AO" : "-");
        const std::string filters = std::string(t.taa ? "TAA" : "-") + "/" + (t.svgf ? "SVGF" : "-");
        std::printf("%-18s %4d %-6s %-8s %9s %7s %9s %7s\n", rowName(r).c_str(),
                    r.spp, giAo.c_str(), filters.c_str(), formatNumber(std::round(r.msMedian * 100) / 100).c_str(),
                    formatNumber(std::round(1000.0 / r.msMedian * 10) / 10).c_str(),
                    formatNumber(std::round(r.relmse * 1e5) / 1e5).c_str(), formatNumber(std::round(r.ssim * 1e4) / 1e4).c_str());
    }
}

void drawChart(const std::vector<BenchRow>& rows, const std::vector<BenchRow>& path, const std::filesystem::path& dir,
               const std::string& title) {
    qputenv("QT_QPA_PLATFORM", "offscreen"); // charts only; bench opens no window
    int argc = 1;
    char name[] = "glint";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    std::vector<bench::ChartCurve> curves;
    for (const BenchRow& r : rows) curves.push_back(r.curve);
    bench::writeSpeedAccuracyChart(curves, title, (dir / "speed_accuracy.png").string(), (dir / "speed_accuracy.svg").string());
    if (path.empty()) return;
    curves.clear();
    for (const BenchRow& r : path) curves.push_back(r.curve);
    bench::writeSpeedAccuracyChart(curves, title + " (camera path)", (dir / "speed_accuracy_path.png").string(),
                                   (dir / "speed_accuracy_path.svg").string());
}

std::vector<renderer::Configuration> parseConfigs(const std::vector<std::string>& names) {
    std::vector<renderer::Configuration> configs;
    for (const std::string& n : names) {
        const auto c = renderer::parseConfiguration(n);
        if (!c) throw CLI::ValidationError("--config", "unknown configuration '" + n + "'");
        configs.push_back(*c);
    }
    return configs;
}

int runBench(const BenchOptions& o) {
    LoadResult loaded = openSceneFile(o.scene);
    completeForRender(loaded, o.scene, o.camera, !o.env.empty(), o.size);
    if (reportWarnings(loaded.warnings, false)) return kFailure;
    Scene& scene = loaded.scene;
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);
    std::vector<BenchRow> rows;
    std::vector<PathBenchRow> path;
    {
        gl::HeadlessContext context;
        std::fprintf(stderr, "glint: GL_RENDERER: %s\n", context.renderer().c_str());
        renderer::FrameRenderer frames;
        renderer::RenderRequest environment; // --env, else the project's environment beside the scene
        environment.envFile = o.env;
        environment.sceneFolder = std::filesystem::path(o.scene).parent_path();
        frames.setScene(scene, renderer::environmentPath(scene, environment));
        reportWarnings(withFile(frames.warnings(), o.scene), false);
        frames.setSettings(settingsFor(o, scene, renderer::Configuration::Reference));
        frames.useSceneCamera(o.camera);
        std::fprintf(stderr, "glint: reference: %d spp\n", o.referenceSpp);
        const std::vector<float> reference = renderReference(frames, o, scene);
        for (const renderer::Configuration c : parseConfigs(o.configs)) {
            std::fprintf(stderr, "glint: %s: %d frames\n", std::string(renderer::configurationName(c)).c_str(), o.frames);
            rows.push_back(runConfiguration(frames, o, scene, c, reference, false));
            if (o.denoise && renderer::traitsOf(c).accumulate) rows.push_back(runConfiguration(frames, o, scene, c, reference, true));
        }
        if (wantsPathBench(o.path, scene))
            path = runPathBench(frames, scene, o.path, parseConfigs(o.configs),
                                [&](renderer::Configuration c) { return settingsFor(o, scene, c); });
    }
    writeCsv(dir / "bench.csv", rows);
    writeJson(dir / "bench.json", rows);
    const std::vector<BenchRow> pathRows = benchRows(path);
    if (!pathRows.empty()) writeCsv(dir / "bench_path.csv", pathRows), writeJson(dir / "bench_path.json", pathRows);
    drawChart(rows, pathRows, dir, std::filesystem::path(o.scene).filename().string() + ", " + std::to_string(o.size.width) + "x" +
                             std::to_string(o.size.height) + ": error vs time");
    printTable(rows);
    if (!pathRows.empty()) std::printf("along the camera path (%d frames):\n", pathRows.front().frames), printTable(pathRows);
    std::fprintf(stderr, "glint: wrote %s/bench.csv, bench.json, speed_accuracy.png, speed_accuracy.svg\n", o.out.c_str());
    return kSuccess;
}

} // namespace

void addBenchCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand("bench", "Time each configuration and measure its error against a converged "
                                                "reference; writes CSV, JSON and the speed-vs-accuracy chart.");
    cmd->add_option("SCENE", o->scene, "Scene: .gltf, .glb or .glint.json")->required();
    cmd->add_option("--config", o->configs, "Configurations, comma-separated, case-insensitive (default: "
                                            "baseline,realistic,full,heavy,accumulate)")
        ->delimiter(',');
    cmd->add_option("--frames", o->frames, "Frames per configuration, still camera (default: 32)")->check(CLI::Range(1, 100000));
    cmd->add_option_function<std::string>("--size", [o](const std::string& s) { o->size = parseSize(s); },
                                          "Image size WxH (default: 128x128)");
    cmd->add_option("--out", o->out, "Output folder for bench.csv, bench.json, speed_accuracy.png/.svg (default: bench)");
    cmd->add_option("--spp", o->spp, "Samples per pixel per frame (default: each configuration's own)")->check(CLI::Range(1, 1 << 16));
    cmd->add_option("--seed", o->seed, "Random seed (default: 0)");
    cmd->add_option("--bounces", o->bounces, "Maximum bounces (default: the project's)")->check(CLI::Range(0, 63));
    cmd->add_option("--camera", o->camera, "Camera by glTF node name, else camera name (default: the active camera)");
    cmd->add_option("--env", o->env, "Environment map (.hdr, .exr), anywhere on disk (default: the project's)");
    cmd->add_option("--reference-spp", o->referenceSpp, "Samples per pixel of the reference (default: 1024)")
        ->check(CLI::Range(1, 1 << 20));
    cmd->add_flag("--denoise", o->denoise,
                  "Also measure Accumulate and Reference through the mean denoiser, as the viewport shows them "
                  "(rows 'accumulate+denoise'; default: off)");
    addPathBenchOptions(*cmd, o->path);
    const auto suite = bench::addRendererSuiteOptions(*cmd); // --suite renderer: app/bench/renderer_suite.h
    cmd->callback([&action, o, suite, cmd] {
        if (suite->requested()) {
            const bench::SuiteOptions s = bench::suiteOptions(*suite, *cmd, o->scene, o->out, o->size.width, o->size.height,
                                                              o->spp, o->bounces, o->referenceSpp);
            action = [s] { return bench::runRendererSuiteCommand(s); };
            return;
        }
        parseConfigs(o->configs); // usage errors before any work
        action = [o] {
            try {
                return runBench(*o);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "glint: %s: %s\n", o->scene.c_str(), e.what());
                return static_cast<int>(kFailure);
            }
        };
    });
}

} // namespace glint::cli
