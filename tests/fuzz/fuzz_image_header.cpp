// Fuzzes the image header probe (PNG, JPEG, Radiance HDR, OpenEXR dimensions from raw bytes, read
// before any image library sees a file so that a header claiming 65535x65535 is refused).
#include "scene/io/image_decoder.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto found = glint::probeImageHeader({data, size});
    if (found && (found->width < 0 || found->height < 0)) std::abort(); // sizes are never negative
    return 0;
}
