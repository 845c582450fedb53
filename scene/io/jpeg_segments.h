#pragma once
// A JPEG file's marker segments, found as libjpeg finds them.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

struct JpegSegment {
    std::uint8_t marker = 0;
    std::size_t begin = 0; // at the 0xFF before the marker
    std::size_t end = 0;   // past its data (a scan's: past its entropy-coded data), or the file's end where cut short
};

struct JpegLayout {
    std::vector<JpegSegment> segments;
    // Where the walk stopped: the end-of-image marker, a length cut short, the file's end, or
    // (JpegWalk::ToTheFirstScan) that scan's marker.
    std::size_t unwalked = 0;
};

enum class JpegWalk { ToTheFirstScan, WholeFile };

// Every segment after the start-of-image marker. Between segments anything before a 0xFF is
// skipped, then fill bytes, as libjpeg does; markers that carry no segment (restarts, TEM, a stray
// 0xFF00) are skipped too. A segment whose length is less than 2 ends after its length field. A
// scan's entropy-coded data runs to the next marker that is not a stuffed 0xFF00 or a restart.
// ToTheFirstScan stops at the first scan's marker (where the headers end: no need to read on).
JpegLayout jpegSegments(std::span<const std::uint8_t> bytes, JpegWalk walk);

// The same file without its metadata segments: Exif and XMP (APP1), ICC profiles (APP2), IPTC
// (APP13) and every other APPn but JFIF (APP0) and Adobe (APP14, which says how the colours are
// coded), and comments, wherever they are (libjpeg reads a progressive JPEG's markers between
// scans while OpenImageIO opens it). OpenImageIO 2.4 parses that metadata, and its IPTC parser
// reads past the end of a broken segment; Glint uses none of it (glTF has a texture's colour space
// ignore any profile). The rest is kept byte for byte, bar the garbage and fill bytes libjpeg skips.
std::vector<std::uint8_t> jpegWithoutMetadata(std::span<const std::uint8_t> bytes);

} // namespace glint
