#pragma once
// Frames on disk -> one video file: used by `glint encode` and by `glint render --video`.
#include "frame_pattern.h"
#include "frame_timing.h"

#include <optional>
#include <string>

namespace glint::cli {

// The frames of `pattern` on disk in `range` (default: all there are), in order. Throws FileError
// when there are none or a frame in between is missing: a video never silently skips one.
std::vector<std::pair<int, std::filesystem::path>> findFrames(const FramePattern& pattern,
                                                              const std::optional<FrameRange>& range);

// Encodes atomically (temporary name, then rename). fps: given, else the frames' recorded fps,
// else 24. codec: given, else the container's default. Throws FileError / std::invalid_argument.
void encodeFrames(const FramePattern& pattern, const std::optional<FrameRange>& range, const std::optional<Fps>& fps,
                  const std::string& out, const std::optional<std::string>& codec);

} // namespace glint::cli
