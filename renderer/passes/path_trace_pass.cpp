#include "renderer/passes/path_trace_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace glint::renderer {
namespace {

void setCameraUniforms(const gl::ShaderProgram& program, const CameraSetup& camera, const gl::RenderTarget& target) {
    glUniformMatrix4fv(program.uniform("uWorldFromCamera"), 1, GL_FALSE, glm::value_ptr(camera.worldFromCamera));
    glUniform1i(program.uniform("uOrthographic"), camera.orthographic ? 1 : 0);
    glUniform2f(program.uniform("uHalfExtent"), camera.halfExtent.x, camera.halfExtent.y);
    glUniform1f(program.uniform("uLensRadius"), camera.lensRadius);
    glUniform1f(program.uniform("uFocusDistance"), camera.focusDistance);
    glUniform2f(program.uniform("uResolution"), static_cast<float>(target.width()), static_cast<float>(target.height()));
}

void setIntegratorUniforms(const gl::ShaderProgram& program, const PathTraceSettings& settings, std::uint32_t sampleIndex) {
    glUniform1ui(program.uniform("uSampleIndex"), sampleIndex);
    glUniform1ui(program.uniform("uSeed"), settings.seed);
    glUniform1i(program.uniform("uMaxBounces"), std::max(settings.bounces, 0));
    glUniform1f(program.uniform("uClamp"), settings.clamp);
    glUniform1ui(program.uniform("uSampleBlock"), static_cast<GLuint>(std::max(settings.sampleBlock, 1)));
    glUniform1i(program.uniform("uIndependentSampler"), settings.independentSampler ? 1 : 0);
    glUniform1f(program.uniform("uAoDistance"), settings.aoDistance);
    glUniform1f(program.uniform("uAmbientDistance"), settings.aoDistance);
}

} // namespace

gl::RenderTarget makeGBuffer(int width, int height, GLuint stopTexture) {
    return gl::RenderTarget(width, height, std::vector<GLenum>(gBufferAttachmentCount, GL_RGBA32F), stopTexture);
}

gl::RenderTarget makeRenderPassesGBuffer(int width, int height, GLuint stopTexture) {
    return gl::RenderTarget(width, height, std::vector<GLenum>(renderPassesAttachmentCount, GL_RGBA32F), stopTexture);
}

void PathTracePass::render(const GpuScene& scene, const CameraSetup& camera, const PathTraceSettings& settings,
                           std::uint32_t sampleIndex, const gl::RenderTarget& target) {
    gl::Defines defines = scene.features().defines();
    if (scene.packed().sphereLamps) defines["HAS_SPHERE_LAMPS"] = ""; // lamps that rays hit: a variant of their own
    if (settings.view == DebugView::AmbientOcclusion) defines["DEBUG_VIEW_AO"] = ""; // a variant of its own
    if (settings.view == DebugView::DiffuseRadiance) defines["DEBUG_VIEW_DIFFUSE"] = "";
    if (settings.splitLobes) defines["SPLIT_LOBES"] = "";
    if (settings.ambientTerm) defines["AMBIENT_TERM"] = "";
    if (settings.areaLightStrategy != AreaLightStrategy::Mis)
        defines["AREA_LIGHT_STRATEGY"] = settings.areaLightStrategy == AreaLightStrategy::LightOnly ? "1" : "2";
    if (settings.view == DebugView::BvhCost) defines["DEBUG_VIEW_BVH_COST"] = defines["BVH_COUNT_COST"] = "";
    std::vector<std::string> outputs = {"outRadiance", "outAlbedo", "outNormalDepth", "outObjectId",
                                        "outDiffuseAlbedo", "outSpecularAlbedo", "outSpecularRadiance"};
    if (settings.renderPasses) {
        defines["RENDER_PASSES"] = "";
        outputs.push_back("outGlossyIndirect");
    }
    const gl::ShaderProgram& program = programs_.get({"fullscreen.vert.glsl", "pathtrace/main.frag.glsl", defines, outputs});
    program.use();
    scene.bind(program);
    setCameraUniforms(program, camera, target);
    setIntegratorUniforms(program, settings, sampleIndex);
    // BSDF sampling alone (a test's debug variant) must trace the last bounce's ray.
    const bool lightSampled = settings.areaLightStrategy != AreaLightStrategy::BsdfOnly;
    glUniform1i(program.uniform("uEveryEmitterLightSampled"), lightSampled && scene.features().everyEmitterLightSampled ? 1 : 0);
    target.bindForDrawing();
    triangle_.draw();
}

} // namespace glint::renderer
