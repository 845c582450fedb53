#pragma once
// Frame-name patterns live with the other output code (renderer/output/frame_pattern.h), so the
// editor's export names frames exactly as the command line does.
#include "renderer/output/frame_pattern.h"

namespace glint::cli {

using renderer::FramePattern;
using renderer::hasFramePlaceholder;
using renderer::parseFramePattern;

} // namespace glint::cli
