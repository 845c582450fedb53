#include "renderer/gl/egl_device_order.h"

#include <algorithm>
#include <charconv>
#include <cstring>

namespace glint::gl {

namespace {

constexpr EGLint kCudaDeviceAttribute = 0x323A; // EGL_CUDA_DEVICE_NV (EGL_NV_device_cuda)

std::optional<int> cudaIndexOf(EGLDeviceEXT device) {
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    if (!extensions || !std::strstr(extensions, "EGL_NV_device_cuda")) return std::nullopt;
    EGLAttrib index = -1;
    if (eglQueryDeviceAttribEXT(device, kCudaDeviceAttribute, &index) != EGL_TRUE) return std::nullopt;
    return int(index);
}

} // namespace

std::optional<int> assignedCudaDevice(const char* value) {
    if (!value) return std::nullopt;
    const char* end = value + std::strlen(value);
    const char* comma = std::find(value, end, ',');
    int index = -1;
    auto [stop, ec] = std::from_chars(value, comma, index);
    if (ec != std::errc() || stop != comma || index < 0) return std::nullopt;
    return index;
}

std::vector<EGLDeviceEXT> assignedDeviceFirst(std::vector<EGLDeviceEXT> devices, std::optional<int> cudaDevice) {
    if (!cudaDevice) return devices;
    auto assigned = std::find_if(devices.begin(), devices.end(), [&](EGLDeviceEXT d) { return cudaIndexOf(d) == cudaDevice; });
    if (assigned != devices.end()) std::rotate(devices.begin(), assigned, assigned + 1);
    return devices;
}

} // namespace glint::gl
