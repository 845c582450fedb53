#pragma once
// `glint bench --suite renderer`: the renderer's throughput on three scenes (Cornell box, Stanford
// bunny in the same room, 16 bunny instances = 1.1M triangles) as ms per sample, paths/s and rays/s,
// plus the Cornell box's convergence (relMSE against its own converged image over render time), with
// Blender Cycles' curve beside it when its CSV is given (app/bench/cycles/cornell_cycles.py).
// Writes renderer_bench.csv/.json, glint_convergence.csv, glint_reference.exr and the chart
// convergence.png/.svg into `out`, with --write-scenes also each throughput scene as <name>.glb (for
// app/bench/cycles/cornell_cycles.py --scene); prints the tables.
#include "shader_suite.h"

#include <string>

namespace glint::bench {

struct SuiteOptions {
    std::string suite = "renderer";                        // or "shaders" (shader_suite.h)
    ShaderSuiteOptions shaders;                            // --suite shaders: its own options
    std::string cornellBox;                                // the Cornell box glTF
    std::string bunny = "tests/data/meshes/stanford-bunny.obj";
    int width = 512, height = 512;                          // throughput image size
    int spp = 2;                                            // samples per timed render
    int runs = 5;                                           // timed renders per scene (median)
    int bounces = 4;
    std::string out = "bench";
    int convergenceSize = 128;                              // square image of the convergence study
    int referenceSpp = 1024;
    int curveSpp = 64;                                      // renders of 1, 2, 4, ... up to this
    std::string cyclesCsv;                                  // cycles_convergence.csv; empty: none
    bool lambert = false;                                   // convergence study with specularFactor 0 everywhere
    bool throughput = true;
    bool writeScenes = false;                               // each throughput scene as OUT/<name>.glb, for Cycles
    bool convergence = true;
};

// Returns an exit code; throws std::runtime_error on bad input.
int runRendererSuite(const SuiteOptions& options);

} // namespace glint::bench
