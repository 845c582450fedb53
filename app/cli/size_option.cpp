#include "size_option.h"

#include <charconv>
#include <stdexcept>
#include <string_view>

namespace glint::cli {

namespace {

int parseDimension(std::string_view text, const std::string& whole) {
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < 1 || value > kMaxImageDimension)
        throw std::invalid_argument("expected WxH with 1 <= W, H <= 16384, got '" + whole + "'");
    return value;
}

} // namespace

WidthHeight parseWidthHeight(const std::string& text) {
    auto x = text.find_first_of("xX");
    if (x == std::string::npos) throw std::invalid_argument("expected WxH, got '" + text + "'");
    return {parseDimension(std::string_view(text).substr(0, x), text),
            parseDimension(std::string_view(text).substr(x + 1), text)};
}

} // namespace glint::cli
