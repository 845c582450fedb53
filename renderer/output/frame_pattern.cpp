#include "renderer/output/frame_pattern.h"

#include <charconv>
#include <stdexcept>

namespace glint::renderer {

std::filesystem::path FramePattern::frame(int number) const {
    std::string digitsText = std::to_string(number);
    if (int(digitsText.size()) < digits) digitsText.insert(0, std::size_t(digits) - digitsText.size(), '0');
    return folder / (prefix + digitsText + suffix);
}

std::optional<int> FramePattern::match(const std::string& fileName) const {
    if (fileName.size() < prefix.size() + suffix.size() + std::size_t(digits)) return std::nullopt;
    if (fileName.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    if (fileName.compare(fileName.size() - suffix.size(), suffix.size(), suffix) != 0) return std::nullopt;
    const std::string_view number(fileName.data() + prefix.size(), fileName.size() - prefix.size() - suffix.size());
    for (char c : number)
        if (c < '0' || c > '9') return std::nullopt;
    // Wider than the padding only when the number needs the digits (no "00012" for "###").
    if (int(number.size()) > digits && number.front() == '0') return std::nullopt;
    int value = 0;
    auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec != std::errc() || end != number.data() + number.size()) return std::nullopt;
    return value;
}

bool hasFramePlaceholder(const std::filesystem::path& path) {
    return path.filename().string().find('#') != std::string::npos;
}

FramePattern parseFramePattern(const std::filesystem::path& pattern) {
    const std::string name = pattern.filename().string();
    const std::size_t first = name.find('#');
    if (first == std::string::npos)
        throw std::invalid_argument("the output name needs a '####' frame-number placeholder, e.g. frames/shot_####.exr");
    const std::size_t end = name.find_first_not_of('#', first);
    const std::size_t runEnd = end == std::string::npos ? name.size() : end;
    if (name.find('#', runEnd) != std::string::npos)
        throw std::invalid_argument("the output name may hold only one run of '#', got '" + name + "'");
    FramePattern p;
    p.folder = pattern.parent_path();
    p.prefix = name.substr(0, first);
    p.suffix = name.substr(runEnd);
    p.digits = int(runEnd - first);
    return p;
}

} // namespace glint::renderer
