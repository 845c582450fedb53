// glint encode 'frames/shot_####.exr' out.mp4: frames on disk -> a video, headless.
#include "cli_validators.h"
#include "command.h"
#include "exit_codes.h"
#include "video_from_frames.h"

#include "renderer/output/image_files.h"
#include "renderer/output/video_settings.h"

#include <memory>

namespace glint::cli {

namespace {

struct EncodeOptions {
    std::string pattern;
    std::string out;
    std::optional<Fps> fps;
    std::optional<FrameRange> frames;
    std::optional<std::string> codec;
};

int runEncode(const EncodeOptions& o) {
    renderer::prepareOutputFolder(o.out);
    encodeFrames(parseFramePattern(o.pattern), o.frames, o.fps, o.out, o.codec);
    return kSuccess;
}

} // namespace

void addEncodeCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<EncodeOptions>();
    CLI::App* cmd = app.add_subcommand("encode", "Encode rendered frames into a video: H.264 in .mp4 (yuv420p, BT.709, "
                                                 "CRF 18), ProRes 422 HQ in .mov, FFV1 in .mkv. EXR frames are "
                                                 "tonemapped as the PNG of the same render.");
    cmd->add_option("FRAMES", o->pattern, "Frame pattern, e.g. 'frames/shot_####.exr'")
        ->required()
        ->check(CLI::Validator(rejection([](const std::string& v) { parseFramePattern(v); }), "PATTERN", "pattern"));
    cmd->add_option("OUT", o->out, "Video file: .mp4, .mov or .mkv")
        ->required()
        ->check(CLI::Validator(rejection([](const std::string& v) { video::defaultCodecFor(v); }), "FILE", "video"));
    addFrameOptions(*cmd, o->frames, o->fps);
    cmd->add_option("--codec", o->codec, "h264, prores or ffv1 (default: from the container: .mp4 h264, .mov prores, "
                                         ".mkv ffv1)")
        ->check(CLI::Validator(rejection([](const std::string& v) { video::parseCodec(v); }), "CODEC", "codec"));
    cmd->callback([o, &action] {
        if (o->codec) {
            try {
                video::checkContainer(o->out, video::parseCodec(*o->codec));
            } catch (const std::invalid_argument& e) {
                throw CLI::ValidationError("--codec", e.what());
            }
        }
        action = [o] { return runEncode(*o); };
    });
}

} // namespace glint::cli
