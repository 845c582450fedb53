// glint render SCENE --out FILE: a still, or with --animation a numbered frame sequence (and
// optionally its video); headless (no display, no Qt GUI).
#include "animation_render.h"
#include "cli_validators.h"
#include "command.h"
#include "exit_codes.h"
#include "frame_pattern.h"
#include "frame_render.h"
#include "render_options.h"
#include "report.h"
#include "scene_defaults.h"
#include "scene_file.h"

#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "renderer/output/video_settings.h"
#include "scene/anim/scene_at_time.h"
#include "scene/io/files/confined_path.h"
#include "scene/io/project/project_file.h"

#include <cstdio>

namespace glint::cli {

namespace {

int renderStill(const RenderOptions& o, Scene& scene) {
    const StopSignal stop;
    renderer::prepareOutputFolder(o.out); // before a long render, not after
    if (o.time) poseSceneAt(scene, *o.time);
    FrameJob job;
    WarningsOnce warnings;
    job.scene = &scene;
    job.out = o.out;
    job.time = o.time;
    job.warnings = &warnings;
    RenderPlan plan = planImage(o, job);
    const int spp = plan.request.spp;
    renderer::OfflineRenderer gpu(o.common.requireGpu);
    std::fprintf(stderr, "glint: GL_RENDERER: %s\n", gpu.glRenderer().c_str());
    try {
        renderImage(gpu, o, job, std::move(plan), stop, true);
    } catch (const RenderStopped&) {
        std::fprintf(stderr, "\nglint: stopped by signal %d; nothing written\n", stop.signalNumber());
        return stop.exitCode();
    }
    std::fprintf(stderr, "glint: wrote %s (%d spp)\n", o.out.c_str(), spp);
    return kSuccess;
}

// The image size is known only with the scene (its project may set it): a region outside the
// image is still a usage error (exit 2), reported before anything is rendered.
bool regionFits(const RenderOptions& o, const Scene& scene) {
    if (!o.region) return true;
    const Size size = o.common.size.value_or(Size{scene.settings.render.width, scene.settings.render.height});
    try {
        checkRegionInside(*o.region, size.width, size.height);
    } catch (const std::invalid_argument& e) {
        printError(std::string("--region: ") + e.what());
        return false;
    }
    return true;
}

// The project's output block stands in for what the command line leaves out: output.path for
// --out (relative to the scene's folder and inside it; a '#' pattern renders the animation),
// output.aovs for --aovs, output.passes for --passes, output.codec for --codec. False: a usage
// error was printed.
bool applyProjectOutput(RenderOptions& o, const Scene& scene) {
    const OutputSettings& output = scene.settings.output;
    const std::string project = projectPathFor(o.scene).string();
    if (!o.aovsGiven && !output.aovs.empty()) o.aovs = output.aovs;
    if (!o.passesGiven && !output.passes.empty()) {
        try {
            renderer::parsePassList(output.passes);
        } catch (const std::exception& e) {
            printError(project, "key 'output.passes': " + std::string(e.what()));
            return false;
        }
        o.passes = output.passes;
    }
    if (o.video && !o.codec && !output.codec.empty()) o.codec = output.codec;
    if (!o.out.empty()) return true;
    if (output.path.empty()) {
        printError("--out is required: " + project + " sets no output.path");
        return false;
    }
    const std::filesystem::path folder = std::filesystem::absolute(o.scene).parent_path();
    if (const auto problem = confinementProblem(ConfinedFolder{folder}, output.path)) {
        printError(project, "key 'output.path': " + *problem);
        return false;
    }
    o.out = (folder / output.path).lexically_normal().string();
    o.animation = o.animation || hasFramePlaceholder(o.out);
    try {
        renderer::imageFormatFor(o.out);
        renderer::parseAovList(o.aovs);
        validateAnimationOptions(o);
    } catch (const std::exception& e) {
        printError(project, "key 'output': " + std::string(e.what()));
        return false;
    }
    return true;
}

// Render passes and the samples AOV come from the running mean: with a real-time configuration
// they are a usage error, named with where they were asked for. (8-bit formats ignore them, as
// they ignore --aovs.)
bool meanOutputsFitConfiguration(const RenderOptions& o, const Scene& scene) {
    if (renderer::imageFormatFor(o.out) != renderer::ImageFormat::Exr) return true;
    const bool passes = renderer::parsePassList(o.passes).any();
    if (!passes && !renderer::parseAovList(o.aovs).samples) return true;
    const std::string name = o.common.config.value_or(scene.settings.render.configuration);
    const auto configuration = renderer::parseConfiguration(name);
    if (!configuration || traitsOf(*configuration).accumulate) return true; // an unknown one is reported by the planner
    const std::string project = projectPathFor(o.scene).string();
    if (passes)
        printError(std::string(o.passesGiven ? "--passes" : project + ": key 'output.passes'") +
                   ": render passes need the accumulate or reference configuration, not '" + name + "'");
    else
        printError(std::string(o.aovsGiven ? "--aovs" : project + ": key 'output.aovs'") +
                   ": the samples AOV needs the accumulate or reference configuration, not '" + name + "'");
    return false;
}

int runRender(RenderOptions o) {
    LoadResult loaded = openSceneFile(o.scene);
    if (!applyProjectOutput(o, loaded.scene)) return kUsage;
    if (!meanOutputsFitConfiguration(o, loaded.scene)) return kUsage;
    completeForRender(loaded, o.scene, o.common.camera.value_or(""), o.common.env.has_value(), outputSize(o.common, loaded.scene));
    if (!regionFits(o, loaded.scene)) return kUsage;
    if (reportWarnings(loaded.warnings, o.common.strict)) return kFailure;
    return o.animation ? renderAnimation(o, loaded.scene) : renderStill(o, loaded.scene);
}

void addAnimationOptions(CLI::App& cmd, RenderOptions& o) {
    cmd.add_flag("--animation", o.animation, "Render the animation as numbered frames: --out needs a '####' "
                                             "placeholder (default: off, a still)");
    addFrameOptions(cmd, o.frames, o.fps);
    cmd.add_flag("--resume,!--no-resume", o.resume, "Keep frames already complete with the same settings hash "
                                                     "(default: on)");
    cmd.add_option_function<std::string>("--shard", [&o](const std::string& v) { o.shard = parseShard(v); },
                                         "Render shard I of N (0 <= I < N); default: from SLURM_ARRAY_TASK_ID/"
                                         "_MIN/_COUNT or JOB_COMPLETION_INDEX, else all frames")
        ->check(CLI::Validator(rejection([](const std::string& v) { parseShard(v); }), "I/N", "shard"));
    cmd.add_option("--shards", o.shards, "Shard count N with a Kubernetes indexed job's JOB_COMPLETION_INDEX (default: none)")
        ->check(CLI::Range(1, 1 << 20));
    cmd.add_option("--chunk", o.chunkFrames, "History configurations (TAA/SVGF): frames per chunk, history reset at "
                                              "each chunk start; shards take whole chunks (default: 24)")
        ->check(CLI::Range(1, 1 << 20));
    cmd.add_option("--warmup", o.warmupFrames, "History configurations: frames rendered and discarded before each "
                                               "chunk to fill its history (default: 8)")
        ->check(CLI::Range(0, 1 << 20));
    cmd.add_option("--video", o.video, "Also encode the frames into this video (.mp4, .mov, .mkv) (default: none)")
        ->check(CLI::Validator(rejection([](const std::string& v) { video::defaultCodecFor(v); }), "FILE", "video"));
    cmd.add_option("--codec", o.codec, "Codec for --video: h264, prores, ffv1 (default: from the container)")
        ->check(CLI::Validator(rejection([](const std::string& v) { video::parseCodec(v); }), "CODEC", "codec"));
}

} // namespace

void addRenderCommand(CLI::App& app, Action& action) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render headless: a still, or with --animation a frame sequence. EXR "
                                                 "(linear radiance + AOVs) or PNG/JPEG/TIFF (tonemapped sRGB).");
    cmd->add_option("SCENE", options->scene, "Scene: .gltf, .glb or .glint.json")->required();
    cmd->add_option("--out", options->out, "Output image: .exr, .png, .jpg or .tif; with --animation a pattern such as "
                                           "frames/shot_####.exr (default: the project file's output.path, relative "
                                           "to the scene's folder; a '#' pattern there renders the animation)")
        ->check(CLI::Validator(rejection([](const std::string& v) { renderer::imageFormatFor(v); }), "FILE", "image"));
    cmd->add_option("--aovs", options->aovs, "EXR layers: all, none, or a list of albedo,normal,depth,id,variance,"
                                             "bvh_cost,samples (default: all = every layer but variance, bvh_cost "
                                             "and samples; bvh_cost: BVH nodes visited + primitives tested by the "
                                             "camera rays, mean per pixel, stills and per-frame renders only; "
                                             "samples: each pixel's sample count, Accumulate and Reference only)")
        ->check(CLI::Validator(rejection([](const std::string& v) { renderer::parseAovList(v); }), "LIST", "aovs"));
    cmd->add_option("--passes", options->passes, "EXR render passes: all, none, light, or a list of DiffDir,DiffInd,"
                                                 "GlossDir,GlossInd,Emit,Env,Vector (any case). The light passes sum "
                                                 "to the beauty; Vector: motion in pixels since the previous frame. "
                                                 "Accumulate and reference only; ignored for 8-bit formats (default: "
                                                 "the project's output.passes, else none)")
        ->check(CLI::Validator(rejection([](const std::string& v) { renderer::parsePassList(v); }), "LIST", "passes"));
    cmd->add_option("--time", options->time, "Render the scene at this time in seconds: camera path and node "
                                             "animations (default: the scene as stored)")
        ->check(finiteIn(-1e5, 1e5));
    cmd->add_option_function<std::string>("--region", [o = options.get()](const std::string& v) { o->region = parseRegion(v); },
                                          "Render only pixels X,Y,W,H of the output image: whole pixels, origin at the "
                                          "top-left corner, inside the image. EXR: the region is the data window, the "
                                          "whole image the display window (every AOV alike); PNG/TIFF: the whole "
                                          "image, transparent (alpha 0) outside; JPEG: black outside. Accumulate/"
                                          "Reference: bit for bit a full render's pixels; real-time configurations "
                                          "path trace a margin as wide as their filters read (docs/FARM.md) "
                                          "(default: none, the whole image)")
        ->check(CLI::Validator(rejection([](const std::string& v) { parseRegion(v); }), "X,Y,W,H", "region"));
    addAnimationOptions(*cmd, *options);
    addCommonRenderOptions(*cmd, options->common);
    cmd->callback([options, cmd, &action] {
        options->aovsGiven = cmd->count("--aovs") > 0;
        options->passesGiven = cmd->count("--passes") > 0;
        if (!options->out.empty()) validateAnimationOptions(*options); // else once the project is read
        action = [options] { return runRender(*options); };
    });
}

} // namespace glint::cli
