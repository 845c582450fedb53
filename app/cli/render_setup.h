#pragma once
// The command line plans its renders through the planner it shares with the editor's export
// (renderer/output/render_plan.h), so both describe and hash the same settings alike.
#include "common_options.h"

#include "renderer/output/render_plan.h"

namespace glint::cli {

using renderer::formatNumber;
using renderer::planRender;
using renderer::RenderPlan;
using renderer::sealSettings;

} // namespace glint::cli
