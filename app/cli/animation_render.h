#pragma once
// glint render --animation: the frames of this shard, each converged, written atomically,
// skipped when already complete with the same settings (--resume), stopped cleanly by a signal.
#include "render_options.h"
#include "scene/core/scene.h"

namespace glint::cli {

// Checks that only need the command line (exit code 2 when they fail); throws CLI::ValidationError.
void validateAnimationOptions(const RenderOptions& options);

// Returns the exit code. Throws FileError / std::runtime_error for failed inputs or renders.
int renderAnimation(const RenderOptions& options, const Scene& scene);

} // namespace glint::cli
