#pragma once
// `glint bench --suite shaders`: what building the path tracer's program costs on this GL driver,
// per shader variant of the scene: the source size, glCompileShader per stage and glLinkProgram
// (each up to its status query) and the first draw of one pixel (glFinish after it: drivers may
// defer code generation to the first draw), then one more draw of the built program for comparison.
// Each compile starts from a fresh program cache; the driver's own shader cache is the caller's to
// disable (NVIDIA: __GL_SHADER_DISK_CACHE=0; Mesa: MESA_SHADER_CACHE_DISABLE=true) for cold figures.
// Writes shader_bench.csv and shader_bench.json into `out`; prints the table.
//
// For experiments without a rebuild, `prelude` lines go after the variant's defines (for example
// "#pragma optionNV(unroll none)" or "#undef HAS_MESHES"), and `shaderDir` reads the GLSL files
// from a copy of shaders/ (files missing there come from the embedded copies).
#include <string>
#include <vector>

namespace glint::bench {

struct ShaderSuiteOptions {
    std::string scene;
    std::string out = "bench";
    int bounces = 4;
    // accumulate (Accumulate, Reference), svgf (the SVGF configurations' lobe split), baseline (the
    // ambient term), passes (the EXR render passes), ao (the ambient-occlusion view).
    std::vector<std::string> variants{"accumulate"};
    int compiles = 1;                 // builds of each variant, each in a fresh program cache
    std::vector<std::string> prelude; // lines after the defines
    std::string shaderDir;            // empty: the embedded shaders
};

// The variant names, comma-separated, for --help and messages.
std::string shaderSuiteVariantNames();

// Returns an exit code; throws std::runtime_error on bad input or a failed compile.
int runShaderSuite(const ShaderSuiteOptions& options);

} // namespace glint::bench
