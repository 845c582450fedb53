#include "renderer/gl/headless_context.h"

#include "renderer/gl/egl_device_order.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace glint::gl {

struct HeadlessContext::Egl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

bool hasClientExtension(const char* name) {
    return epoxy_has_egl_extension(EGL_NO_DISPLAY, name);
}

EGLDisplay initialised(EGLDisplay display) {
    if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
    EGLint major = 0, minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) return EGL_NO_DISPLAY;
    return display;
}

EGLDisplay deviceDisplay() {
    if (!hasClientExtension("EGL_EXT_platform_device") || !hasClientExtension("EGL_EXT_device_enumeration"))
        return EGL_NO_DISPLAY;
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (count == 0 || eglQueryDevicesEXT(count, devices.data(), &count) != EGL_TRUE) return EGL_NO_DISPLAY;
    devices = assignedDeviceFirst(std::move(devices), assignedCudaDevice(std::getenv("CUDA_VISIBLE_DEVICES")));
    // Mesa lists its software device too; a hardware device that initialises comes first.
    for (EGLDeviceEXT device : devices) {
        const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
        if (extensions && std::string(extensions).find("EGL_MESA_device_software") != std::string::npos) continue;
        if (EGLDisplay display = initialised(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr)))
            return display;
    }
    return EGL_NO_DISPLAY;
}

EGLDisplay surfacelessDisplay() {
    if (!hasClientExtension("EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
    return initialised(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
}

EGLDisplay openDisplay(std::string& platform) {
    if (EGLDisplay d = deviceDisplay()) return platform = "EGL_EXT_platform_device", d;
    if (EGLDisplay d = surfacelessDisplay()) return platform = "EGL_MESA_platform_surfaceless", d;
    platform = "default display";
    return initialised(eglGetDisplay(EGL_DEFAULT_DISPLAY));
}

EGLContext createCoreContext(EGLDisplay display) {
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw std::runtime_error("EGL: eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    // Surfaceless contexts need no config; pass one when the display offers it.
    if (eglChooseConfig(display, configAttributes, &config, 1, &configs) != EGL_TRUE || configs == 0)
        config = EGL_NO_CONFIG_KHR;
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 1,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error("EGL: cannot create an OpenGL 4.1 core context (error 0x" +
                                 std::to_string(eglGetError()) + ")");
    return context;
}

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

} // namespace

bool isSoftwareRenderer(const std::string& glRenderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "SwiftShader"})
        if (glRenderer.find(name) != std::string::npos) return true;
    return false;
}

HeadlessContext::HeadlessContext(const HeadlessContextOptions& options) : egl_(std::make_unique<Egl>()) {
    egl_->display = openDisplay(platform_);
    if (egl_->display == EGL_NO_DISPLAY) throw std::runtime_error("EGL: no display (device, surfaceless or default)");
    try {
        egl_->context = createCoreContext(egl_->display);
    } catch (...) {
        eglTerminate(egl_->display);
        throw;
    }
    if (eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context) != EGL_TRUE) {
        eglDestroyContext(egl_->display, egl_->context);
        eglTerminate(egl_->display);
        throw std::runtime_error("EGL: eglMakeCurrent without a surface failed");
    }
    renderer_ = glString(GL_RENDERER);
    version_ = glString(GL_VERSION);
    if (options.requireGpu && isSoftware()) {
        const std::string name = renderer_;
        eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(egl_->display, egl_->context);
        eglTerminate(egl_->display);
        egl_->context = EGL_NO_CONTEXT;
        throw std::runtime_error("a GPU is required but OpenGL runs on the software renderer " + name);
    }
}

HeadlessContext::~HeadlessContext() {
    if (egl_->context == EGL_NO_CONTEXT) return;
    eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(egl_->display, egl_->context);
    eglTerminate(egl_->display);
}

bool HeadlessContext::isSoftware() const { return isSoftwareRenderer(renderer_); }

} // namespace glint::gl
