#include "region_option.h"

#include <charconv>
#include <stdexcept>
#include <string_view>

namespace glint::cli {

namespace {

constexpr const char* kForm = "expected X,Y,W,H in whole pixels from the top-left corner, such as 16,16,32,32";

// Four comma-separated integers, nothing else.
bool parseFour(std::string_view text, int (&values)[4]) {
    for (int i = 0; i < 4; ++i) {
        const char* end = text.data() + text.size();
        auto [next, ec] = std::from_chars(text.data(), end, values[i]);
        if (ec != std::errc() || next == text.data()) return false;
        text.remove_prefix(static_cast<std::size_t>(next - text.data()));
        if (i < 3) {
            if (text.empty() || text.front() != ',') return false;
            text.remove_prefix(1);
        }
    }
    return text.empty();
}

} // namespace

ImageWindow parseRegion(const std::string& text) {
    int v[4] = {0, 0, 0, 0};
    if (!parseFour(text, v)) throw std::invalid_argument(std::string(kForm) + ", got '" + text + "'");
    if (v[0] < 0 || v[1] < 0) throw std::invalid_argument("X and Y must be 0 or more, got '" + text + "'");
    if (v[2] < 1 || v[3] < 1) throw std::invalid_argument("the region is empty: W and H must be at least 1, got '" + text + "'");
    return {v[0], v[1], v[2], v[3]};
}

void checkRegionInside(const ImageWindow& r, int width, int height) {
    // In 64 bits: X + W may not fit an int.
    if (static_cast<long long>(r.x) + r.width > width || static_cast<long long>(r.y) + r.height > height)
        throw std::invalid_argument(formatRegion(r) + " reaches outside the " + std::to_string(width) + "x" +
                                    std::to_string(height) + " image (X + W <= " + std::to_string(width) +
                                    " and Y + H <= " + std::to_string(height) + " needed)");
}

std::string formatRegion(const ImageWindow& r) {
    return std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.width) + "," + std::to_string(r.height);
}

} // namespace glint::cli
