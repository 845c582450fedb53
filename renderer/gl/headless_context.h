#pragma once
// A headless OpenGL 4.1 core context through EGL: no window system, no X server. Tries
// EGL_EXT_platform_device (NVIDIA render nodes), then EGL_MESA_platform_surfaceless, then the
// default display. The context is current on the creating thread for its whole life.
#include <memory>
#include <string>

namespace glint::gl {

struct HeadlessContextOptions {
    bool requireGpu = false; // refuse software rasterisers (llvmpipe, softpipe, swrast)
};

class HeadlessContext {
public:
    // Throws std::runtime_error saying which step failed.
    explicit HeadlessContext(const HeadlessContextOptions& options = {});
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& renderer() const { return renderer_; } // GL_RENDERER
    const std::string& version() const { return version_; }   // GL_VERSION
    const std::string& platform() const { return platform_; } // which EGL display path worked
    bool isSoftware() const;

private:
    struct Egl;
    std::unique_ptr<Egl> egl_;
    std::string renderer_;
    std::string version_;
    std::string platform_;
};

// True for Mesa's CPU rasterisers, by GL_RENDERER.
bool isSoftwareRenderer(const std::string& glRenderer);

} // namespace glint::gl
