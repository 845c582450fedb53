#include "shader_suite.h"

#include "renderer/gl/headless_context.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/gpu_scene/mesh_data.h"
#include "renderer/offline_render.h"
#include "renderer/passes/path_trace_pass.h"
#include "scene/io/scene_io.h"
#include "shaders/embedded_shaders.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace glint::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

struct Variant {
    const char* name;
    renderer::PathTraceSettings settings;
};

std::vector<Variant> allVariants() {
    renderer::PathTraceSettings plain, svgf, baseline, passes, ao;
    svgf.splitLobes = true;
    baseline.ambientTerm = true;
    passes.renderPasses = true;
    ao.view = renderer::DebugView::AmbientOcclusion;
    return {{"accumulate", plain}, {"svgf", svgf}, {"baseline", baseline}, {"passes", passes}, {"ao", ao}};
}

struct Row {
    std::string variant;
    int compile = 0;
    std::string defines;
    gl::ProgramBuildTimes times;
    double firstDrawMs = 0.0;  // the first render call less the build: uniforms, the draw, glFinish
    double secondDrawMs = 0.0; // the same call again
    double totalMs = 0.0;      // the first render call: build and first draw
};

std::string joinDefines(const gl::Defines& defines) {
    std::string s;
    for (const auto& [name, value] : defines) s += (s.empty() ? "" : " ") + name + (value.empty() ? "" : "=" + value);
    return s;
}

// Files under `dir` (by their names relative to it) before the embedded copies.
gl::ShaderLookup directoryLookup(const std::filesystem::path& dir) {
    if (!std::filesystem::is_directory(dir)) throw std::runtime_error("--shader-dir: not a folder: " + dir.string());
    auto files = std::make_shared<std::map<std::string, std::string, std::less<>>>();
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        (*files)[std::filesystem::relative(entry.path(), dir).generic_string()] = text.str();
    }
    return [files](std::string_view name) -> std::optional<std::string_view> {
        if (auto it = files->find(name); it != files->end()) return std::string_view(it->second);
        return shaders::find(name);
    };
}

bool hasExtension(const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (std::string_view(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)))) == name) return true;
    return false;
}

std::string csvQuoted(const std::string& s) { return "\"" + s + "\""; }

std::string jsonQuoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

void writeFiles(const std::filesystem::path& dir, const std::vector<Row>& rows, const std::string& glRenderer,
                const std::string& glVersion, const ShaderSuiteOptions& o, bool parallelCompile) {
    std::string prelude;
    for (const std::string& line : o.prelude) prelude += line + "\n";
    std::ofstream csv(dir / "shader_bench.csv");
    csv << "variant,compile,fragment_bytes,vertex_compile_ms,fragment_compile_ms,link_ms,first_draw_ms,second_draw_ms,"
           "total_ms,defines\n";
    char line[512];
    for (const Row& r : rows) {
        std::snprintf(line, sizeof line, "%s,%d,%zu,%.1f,%.1f,%.1f,%.1f,%.2f,%.1f,", r.variant.c_str(), r.compile,
                      r.times.fragmentBytes, r.times.vertexCompileMs, r.times.fragmentCompileMs, r.times.linkMs,
                      r.firstDrawMs, r.secondDrawMs, r.totalMs);
        csv << line << csvQuoted(r.defines) << "\n";
    }
    std::ofstream json(dir / "shader_bench.json");
    json << "{\n  \"gl_renderer\": " << jsonQuoted(glRenderer) << ",\n  \"gl_version\": " << jsonQuoted(glVersion)
         << ",\n  \"scene\": " << jsonQuoted(o.scene) << ",\n  \"prelude\": " << jsonQuoted(prelude)
         << ",\n  \"shader_dir\": " << jsonQuoted(o.shaderDir)
         << ",\n  \"parallel_shader_compile\": " << (parallelCompile ? "true" : "false") << ",\n  \"programs\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        std::snprintf(line, sizeof line,
                      "\"compile\": %d, \"fragment_bytes\": %zu, \"vertex_compile_ms\": %.1f, \"fragment_compile_ms\": "
                      "%.1f, \"link_ms\": %.1f, \"first_draw_ms\": %.1f, \"second_draw_ms\": %.2f, \"total_ms\": %.1f",
                      r.compile, r.times.fragmentBytes, r.times.vertexCompileMs, r.times.fragmentCompileMs,
                      r.times.linkMs, r.firstDrawMs, r.secondDrawMs, r.totalMs);
        json << "    {\"variant\": " << jsonQuoted(r.variant) << ", " << line << ", \"defines\": " << jsonQuoted(r.defines)
             << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
    }
    json << "  ]\n}\n";
}

} // namespace

std::string shaderSuiteVariantNames() {
    std::string names;
    for (const Variant& v : allVariants()) {
        if (!names.empty()) names += ',';
        names += v.name;
    }
    return names;
}

int runShaderSuite(const ShaderSuiteOptions& o) {
    std::vector<Variant> chosen;
    const std::vector<Variant> known = allVariants();
    for (const std::string& name : o.variants) {
        auto it = std::find_if(known.begin(), known.end(), [&](const Variant& v) { return name == v.name; });
        if (it == known.end()) throw std::runtime_error("--variants: unknown variant '" + name + "' (" + shaderSuiteVariantNames() + ")");
        chosen.push_back(*it);
    }
    gl::ShaderSourceOptions sourceOptions;
    for (const std::string& line : o.prelude) sourceOptions.prelude += line + "\n";
    if (!o.shaderDir.empty()) sourceOptions.lookup = directoryLookup(o.shaderDir);

    const LoadResult loaded = loadScene(o.scene);
    gl::HeadlessContext context;
    const bool parallelCompile = hasExtension("GL_KHR_parallel_shader_compile") || hasExtension("GL_ARB_parallel_shader_compile");
    std::fprintf(stderr, "glint: GL_RENDERER: %s\nglint: GL_VERSION: %s\nglint: parallel shader compile: %s\n",
                 context.renderer().c_str(), context.version().c_str(), parallelCompile ? "yes" : "no");
    renderer::MeshBvhCache meshCache;
    const renderer::GpuScene scene(loaded.scene, renderer::environmentPath(loaded.scene, renderer::RenderRequest{}), meshCache);
    renderer::CameraSetup camera; // a scene without a camera: the default view (one pixel either way)
    try {
        camera = renderer::resolveCamera(loaded.scene, "", 1, 1);
    } catch (const std::runtime_error&) {
    }
    const gl::RenderTarget gBuffer = renderer::makeGBuffer(1, 1);
    const gl::RenderTarget passesBuffer = renderer::makeRenderPassesGBuffer(1, 1);
    glFinish();
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);

    std::vector<Row> rows;
    std::printf("%-10s %3s %9s %11s %11s %9s %11s %11s %10s  %s\n", "variant", "#", "bytes", "vert ms", "frag ms",
                "link ms", "1st draw", "2nd draw", "total ms", "defines");
    for (const Variant& variant : chosen) {
        renderer::PathTraceSettings settings = variant.settings;
        settings.bounces = o.bounces;
        const gl::RenderTarget& target = settings.renderPasses ? passesBuffer : gBuffer;
        for (int k = 1; k <= o.compiles; ++k) {
            gl::ProgramCache programs;
            programs.setSourceOptions(sourceOptions);
            renderer::PathTracePass pass(programs);
            Row row;
            row.variant = variant.name;
            row.compile = k;
            auto start = Clock::now();
            pass.render(scene, camera, settings, 0, target);
            glFinish();
            row.totalMs = msSince(start);
            if (programs.built().empty()) throw std::runtime_error("the path tracer built no program");
            const gl::ShaderProgram& program = *programs.built().back();
            row.times = program.buildTimes();
            row.defines = joinDefines(program.source().defines);
            row.firstDrawMs = row.totalMs - row.times.vertexCompileMs - row.times.fragmentCompileMs - row.times.linkMs;
            start = Clock::now();
            pass.render(scene, camera, settings, 1, target);
            glFinish();
            row.secondDrawMs = msSince(start);
            std::printf("%-10s %3d %9zu %11.1f %11.1f %9.1f %11.1f %11.2f %10.1f  %s\n", row.variant.c_str(), k,
                        row.times.fragmentBytes, row.times.vertexCompileMs, row.times.fragmentCompileMs, row.times.linkMs,
                        row.firstDrawMs, row.secondDrawMs, row.totalMs, row.defines.c_str());
            std::fflush(stdout);
            rows.push_back(row);
            writeFiles(dir, rows, context.renderer(), context.version(), o, parallelCompile); // so far, row by row
        }
    }
    std::fprintf(stderr, "glint: wrote %s\n", (dir / "shader_bench.csv").string().c_str());
    return 0;
}

} // namespace glint::bench
