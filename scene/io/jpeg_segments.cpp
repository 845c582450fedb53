#include "jpeg_segments.h"

namespace glint {

namespace {

bool carriesNoSegment(std::uint8_t marker) { return marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8); }

bool isMetadata(std::uint8_t marker) { return (marker >= 0xE1 && marker <= 0xEF && marker != 0xEE) || marker == 0xFE; }

// Past a scan's entropy-coded data from `at`: where the first 0xFF followed (after fill bytes) by
// neither 0x00 (a stuffed 0xFF) nor a restart marker stands, as libjpeg's entropy decoder stops.
std::size_t scanDataEnd(std::span<const std::uint8_t> b, std::size_t at)
{
    while (at < b.size()) {
        if (b[at] != 0xFF) {
            ++at;
            continue;
        }
        std::size_t next = at + 1;
        while (next < b.size() && b[next] == 0xFF) ++next;
        if (next < b.size() && (b[next] == 0x00 || (b[next] >= 0xD0 && b[next] <= 0xD7))) {
            at = next + 1;
            continue;
        }
        return at;
    }
    return at;
}

} // namespace

JpegLayout jpegSegments(std::span<const std::uint8_t> b, JpegWalk walk)
{
    JpegLayout layout;
    std::size_t at = 2;
    while (true) {
        while (at < b.size() && b[at] != 0xFF) ++at;
        while (at < b.size() && b[at] == 0xFF) ++at;
        if (at >= b.size()) break;
        const std::size_t begin = at - 1;
        const std::uint8_t marker = b[at++]; // `at` is now at the segment's length
        if (carriesNoSegment(marker)) continue;
        // The end, a length cut short, or the first scan where the walk stops there.
        if (marker == 0xD9 || at + 2 > b.size() || (marker == 0xDA && walk == JpegWalk::ToTheFirstScan)) {
            layout.unwalked = begin;
            return layout;
        }
        // A length shorter than its own field: libjpeg refuses a table, frame or scan so, and reads
        // on after the field for anything else (the next marker is found as ever).
        const std::size_t length = std::max<std::size_t>(2, std::size_t(b[at]) << 8 | b[at + 1]);
        const std::size_t end = std::min(b.size(), at + length);
        layout.segments.push_back({marker, begin, marker == 0xDA ? scanDataEnd(b, end) : end});
        at = layout.segments.back().end;
    }
    layout.unwalked = b.size();
    return layout;
}

std::vector<std::uint8_t> jpegWithoutMetadata(std::span<const std::uint8_t> bytes)
{
    const JpegLayout layout = jpegSegments(bytes, JpegWalk::WholeFile);
    std::vector<std::uint8_t> kept(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(2, bytes.size())));
    kept.reserve(bytes.size());
    for (const JpegSegment& segment : layout.segments)
        if (!isMetadata(segment.marker))
            kept.insert(kept.end(), bytes.begin() + static_cast<std::ptrdiff_t>(segment.begin), bytes.begin() + static_cast<std::ptrdiff_t>(segment.end));
    kept.insert(kept.end(), bytes.begin() + static_cast<std::ptrdiff_t>(layout.unwalked), bytes.end());
    return kept;
}

} // namespace glint
