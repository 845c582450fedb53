// glint render SCENE --out FILE: a still, headless (no display, no Qt GUI).
#include "command.h"
#include "common_options.h"
#include "exit_codes.h"
#include "render_setup.h"
#include "report.h"
#include "scene_file.h"

#include "app/version.h"
#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "scene/anim/scene_at_time.h"

#include <cstdio>

namespace glint::cli {

namespace {

struct RenderOptions {
    std::string scene;
    std::string out;
    std::string aovs = "all";
    std::optional<double> time;
    CommonRenderOptions common;
};

// A CLI11 validator from a parser that throws std::invalid_argument: its message becomes the usage error.
std::function<std::string(std::string&)> rejection(std::function<void(const std::string&)> parse) {
    return [parse](std::string& value) -> std::string {
        try {
            parse(value);
            return {};
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
    };
}

// One line, rewritten in place, at most ~100 times per render.
void printProgress(int done, int total) {
    if (total < 100 || done % (total / 100) == 0 || done == total)
        std::fprintf(stderr, "\rglint: rendering %d/%d samples", done, total);
    if (done == total) std::fprintf(stderr, "\n");
}

int runRender(const RenderOptions& o) {
    LoadResult loaded = openSceneFile(o.scene);
    if (reportWarnings(loaded.warnings, o.common.strict)) return kFailure;
    const auto layers = renderer::parseAovList(o.aovs);
    renderer::checkOutputWritable(o.out); // before a long render, not after
    if (o.time) poseSceneAt(loaded.scene, *o.time);
    RenderPlan plan = planRender(loaded.scene, o.scene, o.common);
    if (o.time) plan.metadata["time"] = formatNumber(*o.time);
    plan.request.progress = printProgress;

    renderer::OfflineRenderer gpu(o.common.requireGpu);
    std::fprintf(stderr, "glint: GL_RENDERER: %s\n", gpu.glRenderer().c_str());
    renderer::RenderOutput image = gpu.render(loaded.scene, plan.request);
    renderer::ImageMetadata metadata = plan.metadata;
    metadata["version"] = kVersion;
    metadata["renderTimeMs"] = formatNumber(image.timings.setupMs + image.timings.renderMs);
    renderer::writeRenderImage(o.out, image, layers, metadata);
    std::fprintf(stderr, "glint: wrote %s (%dx%d, %d spp, %.1f ms/sample)\n", o.out.c_str(), image.width,
                 image.height, plan.request.spp, image.timings.msPerSample);
    return kSuccess;
}

} // namespace

void addRenderCommand(CLI::App& app, Action& action) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a still headless: EXR (linear radiance + AOVs) or "
                                                 "PNG/JPEG/TIFF (tonemapped sRGB).");
    cmd->add_option("SCENE", options->scene, "Scene: .gltf, .glb or .glint.json")->required();
    cmd->add_option("--out", options->out, "Output image: .exr, .png, .jpg or .tif")
        ->required()
        ->check(CLI::Validator(rejection([](const std::string& v) { renderer::imageFormatFor(v); }), "FILE", "image"));
    cmd->add_option("--aovs", options->aovs, "EXR layers: all, none, or a list of albedo,normal,depth,id (default: all)")
        ->check(CLI::Validator(rejection([](const std::string& v) { renderer::parseAovList(v); }), "LIST", "aovs"));
    cmd->add_option("--time", options->time, "Render the scene at this time in seconds: camera path and node "
                                             "animations (default: the scene as stored)");
    addCommonRenderOptions(*cmd, options->common);
    cmd->callback([options, &action] { action = [options] { return runRender(*options); }; });
}

} // namespace glint::cli
