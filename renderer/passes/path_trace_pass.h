#pragma once
// One path-traced sample per pixel into a seven-target G-buffer: radiance, albedo (base colour),
// normal + depth, object id, diffuse albedo, specular albedo + roughness, and the part of the
// radiance that the first hit's specular lobes carried (GBufferAttachment).
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/gpu_scene.h"

#include <cstdint>

namespace glint::renderer {

// BvhCost: the camera ray's BVH work per pixel in radiance (nodes + primitives, nodes, primitives),
// a shader variant of its own (shaders/pathtrace/bvh_cost.glsl).
// DiffuseRadiance: radiance holds only the part the first hit's diffuse lobe carried (its
// specular part stays in specularRadianceAttachment): a view of the lobe split, and its check.
enum class DebugView { None, AmbientOcclusion, BvhCost, DiffuseRadiance };

// Which strategies find the light of area emitters (emissive triangles, emissive shapes, area
// lights): both, weighted by MIS (what renders use), or one alone: a shader variant
// (AREA_LIGHT_STRATEGY 1 or 2) for the tests that check the strategies agree.
enum class AreaLightStrategy { Mis, LightOnly, BsdfOnly };

struct PathTraceSettings {
    std::uint32_t seed = 0;
    int bounces = 4;        // docs/CLI.md: 0 = emitters and direct light only
    float clamp = 0.0f;     // radiance clamp per sample; 0 = off
    bool independentSampler = false; // hashed uniforms instead of R2 for the pixel jitter
    DebugView view = DebugView::None;
    float aoDistance = 1.0f; // metres: the AO view's rays and the ambient term's
    // Write specularRadianceAttachment (the SVGF configurations); off, it holds 0 and the
    // radiance is computed by the same code without the split (a shader variant).
    bool splitLobes = false;
    // Baseline's ambient term (shaders/pathtrace/ambient_term.glsl), a shader variant: only for
    // configurations that cut paths short (ConfigurationTraits::ao).
    bool ambientTerm = false;
    AreaLightStrategy areaLightStrategy = AreaLightStrategy::Mis;
    // The EXR's render passes (shaders/pathtrace/render_passes.glsl), a shader variant that writes
    // them over targets 4-6 and an eighth (renderPassesAttachmentCount): offline Accumulate and
    // Reference only, where nothing reads the denoiser's targets. Off: the shader is unchanged.
    bool renderPasses = false;
    int sampleBlock = 1; // the low-discrepancy sequence is keyed on pixel / sampleBlock (RenderSettings)
};

enum GBufferAttachment {
    radianceAttachment = 0,
    albedoAttachment = 1,
    normalDepthAttachment = 2,
    objectIdAttachment = 3,
    diffuseAlbedoAttachment = 4,
    specularAlbedoAttachment = 5, // a: roughness
    specularRadianceAttachment = 6, // rgb <= radiance; radiance - this is the diffuse lobe's part
    gBufferAttachmentCount = 7
};

// The RENDER_PASSES variant's targets (render_passes_pass.h reads them): objectId.yzw = Env,
// diffuse albedo = DiffDir, specular albedo = DiffInd, specular radiance = GlossDir (their a:
// Emit's r, g, b), and one more, GlossInd.
inline constexpr int glossyIndirectAttachment = 7;
inline constexpr int renderPassesAttachmentCount = 8;
// `stopTexture`: adaptive sampling's stops (adaptive_sampling.h), attached as the depth buffer; 0: none.
gl::RenderTarget makeRenderPassesGBuffer(int width, int height, GLuint stopTexture = 0);

gl::RenderTarget makeGBuffer(int width, int height, GLuint stopTexture = 0);

class PathTracePass {
public:
    explicit PathTracePass(gl::ProgramCache& programs) : programs_(programs) {}
    void render(const GpuScene& scene, const CameraSetup& camera, const PathTraceSettings& settings,
                std::uint32_t sampleIndex, const gl::RenderTarget& target);

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
};

} // namespace glint::renderer
