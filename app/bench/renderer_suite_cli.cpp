#include "renderer_suite_cli.h"

#include <cstdio>
#include <exception>

namespace glint::bench {

std::shared_ptr<SuiteCli> addRendererSuiteOptions(CLI::App& bench) {
    auto cli = std::make_shared<SuiteCli>();
    SuiteOptions& o = cli->options;
    bench.add_option("--suite", cli->suite,
                     "renderer: SCENE is the Cornell box; time it, the bunny in its room and 16 bunnies (1.1M "
                     "triangles) at --size (default 512x512) and measure its convergence; shaders: compile, link "
                     "and first-draw time of SCENE's path-tracer program (default: off, the configuration bench)")
        ->check(CLI::IsMember({"renderer", "shaders"}));
    bench.add_option("--bunny", o.bunny, "Suite: the Stanford bunny OBJ (default: " + o.bunny + ")");
    bench.add_option("--runs", o.runs, "Suite: timed renders per scene, median taken (default: 5)")->check(CLI::Range(1, 1000));
    bench.add_option("--convergence-size", o.convergenceSize, "Suite: square image size of the convergence study (default: 128)")
        ->check(CLI::Range(8, 4096));
    bench.add_option("--curve-spp", o.curveSpp, "Suite: convergence renders of 1, 2, 4, ... samples up to this (default: 64)")
        ->check(CLI::Range(1, 1 << 16));
    bench.add_option("--cycles-csv", o.cyclesCsv, "Suite: cycles_convergence.csv to chart beside Glint's (default: none)");
    bench.add_flag("--lambert", o.lambert,
                   "Suite: convergence study with every material pure Lambert (specular 0), to compare with "
                   "cornell_cycles.py --materials diffuse (default: off, the materials as stored)");
    ShaderSuiteOptions& sh = o.shaders;
    bench.add_option("--variants", sh.variants, "Suite shaders: path-tracer variants, comma-separated: " +
                                                    shaderSuiteVariantNames() + " (default: accumulate)")
        ->delimiter(',');
    bench.add_option("--compiles", sh.compiles, "Suite shaders: builds of each variant, each from a fresh program cache (default: 1)")
        ->check(CLI::Range(1, 100));
    bench.add_option("--shader-prelude", sh.prelude,
                     "Suite shaders: a GLSL line after the variant's defines, e.g. '#pragma optionNV(unroll none)' "
                     "(repeatable; default: none)");
    bench.add_option("--shader-dir", sh.shaderDir,
                     "Suite shaders: read GLSL files from this copy of shaders/ before the embedded ones (default: none)");
    bench.add_flag("!--no-throughput", o.throughput, "Suite: skip the throughput scenes");
    bench.add_flag("!--no-convergence", o.convergence, "Suite: skip the convergence study");
    bench.add_flag("--write-scenes", o.writeScenes,
                   "Suite: also write each throughput scene as OUT/<name>.glb, to render it with Cycles (default: off)");
    return cli;
}

SuiteOptions suiteOptions(const SuiteCli& cli, const CLI::App& bench, const std::string& scene, const std::string& out,
                          int width, int height, std::optional<int> spp, std::optional<int> bounces, int referenceSpp) {
    SuiteOptions o = cli.options;
    o.suite = cli.suite;
    o.cornellBox = scene;
    o.shaders.scene = scene;
    o.shaders.out = out;
    if (bounces) o.shaders.bounces = *bounces;
    o.out = out;
    if (bench.count("--size") > 0) o.width = width, o.height = height;
    if (spp) o.spp = *spp;
    if (bounces) o.bounces = *bounces;
    if (bench.count("--reference-spp") > 0) o.referenceSpp = referenceSpp;
    return o;
}

int runRendererSuiteCommand(const SuiteOptions& options) {
    try {
        return options.suite == "shaders" ? runShaderSuite(options.shaders) : runRendererSuite(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint: %s: %s\n", options.cornellBox.c_str(), e.what());
        return 1;
    }
}

} // namespace glint::bench
