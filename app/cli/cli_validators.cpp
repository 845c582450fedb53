#include "cli_validators.h"

#include <cmath>
#include <cstdio>

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

CLI::Validator finiteIn(double low, double high) {
    const auto text = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", v);
        return std::string(buffer);
    };
    const std::string range = text(low) + " to " + text(high);
    return CLI::Validator(
        [low, high, range](std::string& text) -> std::string {
            double value = 0.0;
            if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
            if (!(std::isfinite(value) && value >= low && value <= high)) return text + " is not in " + range;
            return {};
        },
        "NUMBER in " + range, "finite");
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
