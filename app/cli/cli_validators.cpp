#include "cli_validators.h"

namespace glint::cli {

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

void addFrameOptions(CLI::App& cmd, std::optional<FrameRange>& frames, std::optional<Fps>& fps) {
    cmd.add_option_function<std::string>("--frames", [&frames](const std::string& v) { frames = parseFrameRange(v); },
                                         "Frames A-B, inclusive, 0-based (default: the animation's span / all on disk)")
        ->check(CLI::Validator(rejection([](const std::string& v) { parseFrameRange(v); }), "A-B", "frames"));
    cmd.add_option_function<std::string>("--fps", [&fps](const std::string& v) { fps = parseFps(v); },
                                         "Frames per second, N or N/D such as 24000/1001 (default: the project's, "
                                         "or the frames' recorded fps; else 24)")
        ->check(CLI::Validator(rejection([](const std::string& v) { parseFps(v); }), "FPS", "fps"));
}

} // namespace glint::cli
