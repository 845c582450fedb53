#include "renderer/raster/gpu_sync.h"

#include <epoxy/gl.h>

namespace glint::renderer::raster {

void finishGpuWork() { glFinish(); }

} // namespace glint::renderer::raster
