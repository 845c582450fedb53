// Error against a converged reference on the bundled Cornell box or another scene (a program, not a
// test; figures in docs/PERFORMANCE.md, "Fireflies", "Samplers" and "Environment maps"):
//   bench_convergence reference OUT.exr [--size 128] [--bounces 4] [--spp 8192] [--seed 1000]
//       renders the reference (Accumulate; 32-bit RGB EXR)
//   bench_convergence curve REF.exr [--size 128] [--bounces 4] [--spp 256] [--seeds 4]
//       [--independent] [--label NAME] [--csv OUT.csv] [--fog D]
//       one progressive render per seed (seeds 0..), read back at 1, 2, 4, ... spp: relMSE, the share
//       of it in the worst 0.1 % of pixels and the mean luminance, per seed and averaged over seeds
//   bench_convergence fireflies REF.exr [--size 128] [--bounces 4] [--spp 64] [--seed 0] [--top 20]
//       the worst pixels of one render with their largest single sample (which sample, how much)
// The scene is resources/scenes/cornell_box as stored (with --fog D: filled with fog of density D,
// albedo 0.9, g 0.6), or with --scene FILE that glTF (and its project file), framed by its camera or
// by the default view; --env IMAGE lights it with that environment map. Give every
// mode the same --scene and --env. The reference seed differs from the runs'.
#include "error_share.h"

#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "renderer/offline_render.h"
#include "scene/core/default_view.h"
#include "scene/io/scene_io.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <string>
#include <vector>

using namespace glint;

namespace {

struct Options {
    std::string mode, file;
    int size = 128, bounces = 4, spp = 0, seeds = 4, top = 20;
    unsigned seed = 0;
    bool independent = false;
    std::string label = "default", csv;
    std::string scene, env; // another glTF than the Cornell box; an environment map lighting it
    float fog = 0.0f; // the Cornell box filled with fog of this density (albedo 0.9, g 0.6): docs/MEDIA.md
};

Options parse(int argc, char** argv) {
    Options o;
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_convergence reference|curve|fireflies FILE.exr [options] (see the source)\n");
        std::exit(2);
    }
    o.mode = argv[1];
    o.file = argv[2];
    for (int i = 3; i < argc; ++i) {
        const auto next = [&]() -> const char* {
            if (i + 1 >= argc) std::exit(2);
            return argv[++i];
        };
        if (!std::strcmp(argv[i], "--size")) o.size = std::atoi(next());
        else if (!std::strcmp(argv[i], "--bounces")) o.bounces = std::atoi(next());
        else if (!std::strcmp(argv[i], "--spp")) o.spp = std::atoi(next());
        else if (!std::strcmp(argv[i], "--seeds")) o.seeds = std::atoi(next());
        else if (!std::strcmp(argv[i], "--seed")) o.seed = static_cast<unsigned>(std::atoi(next()));
        else if (!std::strcmp(argv[i], "--top")) o.top = std::atoi(next());
        else if (!std::strcmp(argv[i], "--label")) o.label = next();
        else if (!std::strcmp(argv[i], "--csv")) o.csv = next();
        else if (!std::strcmp(argv[i], "--independent")) o.independent = true;
        else if (!std::strcmp(argv[i], "--fog")) o.fog = float(std::atof(next()));
        else if (!std::strcmp(argv[i], "--scene")) o.scene = next();
        else if (!std::strcmp(argv[i], "--env")) o.env = next();
        else {
            std::fprintf(stderr, "bench_convergence: unknown option %s\n", argv[i]);
            std::exit(2);
        }
    }
    return o;
}

Scene benchScene(const Options& o) {
    const std::filesystem::path file =
        o.scene.empty() ? std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf" : std::filesystem::path(o.scene);
    Scene scene = loadScene(file).scene;
    if (!defaultCamera(scene)) addDefaultView(scene, 1.0f);
    scene.settings.fog = {.density = o.fog, .color = glm::vec3(0.9f), .anisotropy = 0.6f};
    return scene;
}

// --env, else the scene's own environment beside it.
renderer::RenderRequest environmentOf(const Options& o) {
    renderer::RenderRequest request;
    request.envFile = o.env;
    request.sceneFolder = o.scene.empty() ? std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box"
                                          : std::filesystem::path(o.scene).parent_path();
    return request;
}

std::vector<float> readReference(const Options& o) {
    int w = 0, h = 0;
    std::vector<float> reference = test::readExrRgba(o.file, w, h);
    if (reference.empty() || w != o.size || h != o.size) {
        std::fprintf(stderr, "bench_convergence: %s: not a %dx%d EXR\n", o.file.c_str(), o.size, o.size);
        std::exit(1);
    }
    return reference;
}

// A progressive render on a FrameRenderer: one sample per frame, read back when `wanted` says so.
template <class AfterSample>
void progressive(const Scene& scene, const Options& o, unsigned seed, int spp, AfterSample&& afterSample) {
    static gl::HeadlessContext context;
    static renderer::FrameRenderer frames;
    renderer::FrameSettings s;
    s.spp = 1;
    s.bounces = o.bounces;
    s.seed = seed;
    s.independentSampler = o.independent;
    s.width = s.height = o.size;
    frames.setSettings(s);
    frames.setCamera(renderer::resolveCamera(scene, {}, o.size, o.size));
    if (!frames.hasScene()) frames.setScene(scene, renderer::environmentPath(scene, environmentOf(o)));
    frames.resetHistory();
    for (int k = 1; k <= spp; ++k) {
        frames.renderFrame();
        afterSample(k, frames);
    }
}

int reference(const Options& o) {
    const Scene scene = benchScene(o);
    renderer::RenderRequest request = environmentOf(o);
    request.width = request.height = o.size;
    request.bounces = o.bounces;
    request.spp = o.spp > 0 ? o.spp : 8192;
    request.seed = o.seed > 0 ? o.seed : 1000u;
    request.progress = [](int done, int total) {
        if (done % 256 == 0 || done == total) std::fprintf(stderr, "\r%d / %d spp", done, total);
    };
    const renderer::RenderOutput out = renderer::renderOffline(scene, request);
    std::fprintf(stderr, "\n%.1f ms per sample\n", out.timings.msPerSample);
    if (!test::writeExrRgb(o.file, out.radiance, o.size, o.size)) return 1;
    std::printf("wrote %s: %dx%d, %d bounces, %d spp, seed %u, mean luminance %.6f\n", o.file.c_str(), o.size, o.size, o.bounces,
                request.spp, request.seed, test::luminanceMean(out.radiance));
    return 0;
}

int curve(const Options& o) {
    const Scene scene = benchScene(o);
    const std::vector<float> ref = readReference(o);
    const int spp = o.spp > 0 ? o.spp : 256;
    std::map<int, std::vector<test::ErrorShare>> bySpp;
    FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
    if (csv) std::fprintf(csv, "sampler,seed,spp,relmse,worst_share,mean_luminance\n");
    for (int seed = 0; seed < o.seeds; ++seed) {
        progressive(scene, o, static_cast<unsigned>(seed), spp, [&](int k, renderer::FrameRenderer& frames) {
            if ((k & (k - 1)) != 0 && k != spp) return;
            const test::ErrorShare e = test::errorShare(frames.readImages().radiance, ref);
            bySpp[k].push_back(e);
            if (csv) std::fprintf(csv, "%s,%d,%d,%.8g,%.6f,%.8g\n", o.label.c_str(), seed, k, e.relMse, e.worstShare, e.meanLuminance);
        });
    }
    if (csv) std::fclose(csv);
    std::printf("%s sampler, %dx%d, %d bounces, mean over %d seeds (reference mean luminance %.6f)\n", o.label.c_str(), o.size, o.size,
                o.bounces, o.seeds, test::luminanceMean(ref));
    std::printf("spp  relMSE      worst 0.1%% share  mean luminance\n");
    for (const auto& [k, list] : bySpp) {
        double relMse = 0.0, share = 0.0, y = 0.0;
        for (const auto& e : list) {
            relMse += e.relMse;
            share += e.worstShare;
            y += e.meanLuminance;
        }
        const double n = static_cast<double>(list.size());
        std::printf("%4d %.6g  %.3f             %.6f\n", k, relMse / n, share / n, y / n);
    }
    return 0;
}

int fireflies(const Options& o) {
    const Scene scene = benchScene(o);
    const std::vector<float> ref = readReference(o);
    const int spp = o.spp > 0 ? o.spp : 64;
    const std::size_t n = static_cast<std::size_t>(o.size) * static_cast<std::size_t>(o.size);
    std::vector<double> previous(n * 3, 0.0), largest(n, -1.0);
    std::vector<int> largestAt(n, -1);
    std::vector<float> image, objectId;
    progressive(scene, o, o.seed, spp, [&](int k, renderer::FrameRenderer& frames) {
        const renderer::FrameImages im = frames.readImages();
        for (std::size_t p = 0; p < n; ++p) {
            double y = 0.0; // this sample's luminance, from the running means before and after it
            const double weights[3] = {0.2126, 0.7152, 0.0722};
            for (std::size_t c = 0; c < 3; ++c) {
                const double mean = im.radiance[p * 4 + c];
                y += weights[c] * (k * mean - (k - 1) * previous[p * 3 + c]);
                previous[p * 3 + c] = mean;
            }
            if (y > largest[p]) {
                largest[p] = y;
                largestAt[p] = k - 1;
            }
        }
        if (k == spp) {
            image = im.radiance;
            objectId = im.objectId;
        }
    });
    const test::ErrorShare e = test::errorShare(image, ref);
    std::printf("%dx%d, %d bounces, %d spp, seed %u: relMSE %.6g, worst 0.1%% (%zu pixels) share %.3f, mean luminance %.6f (reference %.6f)\n",
                o.size, o.size, o.bounces, spp, o.seed, e.relMse, e.worstPixels, e.worstShare, e.meanLuminance, e.referenceLuminance);
    const std::vector<double> error = test::pixelRelMse(image, ref);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return error[a] > error[b]; });
    std::printf("x    y    relMSE   Y       reference  largest sample (index)  first hit (node id)\n");
    const auto luminance = [](const std::vector<float>& v, std::size_t p) { return 0.2126 * v[p * 4] + 0.7152 * v[p * 4 + 1] + 0.0722 * v[p * 4 + 2]; };
    for (int i = 0; i < o.top && i < static_cast<int>(n); ++i) {
        const std::size_t p = order[static_cast<std::size_t>(i)];
        std::printf("%-4zu %-4zu %-8.4f %-7.4f %-10.4f %8.3f (%d)           %.0f\n", p % static_cast<std::size_t>(o.size),
                    p / static_cast<std::size_t>(o.size), error[p], luminance(image, p), luminance(ref, p), largest[p], largestAt[p], objectId[p]);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    if (o.mode == "reference") return reference(o);
    if (o.mode == "curve") return curve(o);
    if (o.mode == "fireflies") return fireflies(o);
    std::fprintf(stderr, "bench_convergence: unknown mode %s\n", o.mode.c_str());
    return 2;
}
