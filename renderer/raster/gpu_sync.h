#pragma once
// Waits for the current context's GL work, so that hosts can time-slice it (the viewport keeps
// each paint within its budget). A header without GL, so Qt code can call it.
namespace glint::renderer::raster {

void finishGpuWork();

} // namespace glint::renderer::raster
