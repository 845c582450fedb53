#include "renderer/gpu_scene/gpu_scene.h"

#include "renderer/cpu_twin/ggx_energy_tables.h"
#include "renderer/gpu_scene/texture_refs.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace glint::renderer {
namespace {

enum TextureUnit : GLuint { shapeUnit = 0, materialUnit = 1, lightUnit = 2, environmentUnit = 3, environmentCdfUnit = 4, firstMeshUnit = 5, firstTextureUnit = 13 };
constexpr GLuint ggxEnergyBinding = 0; // uniform-buffer binding point of the block GgxEnergyTables

gl::TextureBuffer vec4Buffer(const std::string& what, const std::vector<glm::vec4>& texels) {
    return gl::TextureBuffer(what, GL_RGBA32F, texels.data(), texels.size(), sizeof(glm::vec4));
}

// Rows go up in image order: row 0 (the top of the image) is t = 0, as equirectFromDirection expects.
gl::Texture uploadFloatTexture(GLenum internalFormat, GLenum format, int width, int height, const float* data, GLint filter) {
    gl::Texture texture = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT); // longitude wraps around
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

void bindTexture2D(const gl::Texture& texture, GLuint unit, GLint location) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glUniform1i(location, static_cast<GLint>(unit));
}

// media.glsl's fog uniforms; density 0 leaves the variant's paths in vacuum.
void bindFog(const gl::ShaderProgram& program, const Fog& fog) {
    glUniform4f(program.uniform("uFog"), fog.density, fog.heightFalloff, fog.baseHeight, 0.0f);
    glUniform3fv(program.uniform("uFogAlbedo"), 1, glm::value_ptr(glm::clamp(fog.color, 0.0f, 1.0f)));
    glUniform1f(program.uniform("uFogAnisotropy"), glm::clamp(fog.anisotropy, -0.99f, 0.99f));
}

} // namespace

gl::Buffer uploadGgxEnergyTables() {
    static constexpr std::array<float, twin::ggxEnergyBlockFloats> block = twin::ggxEnergyBlock();
    gl::Buffer buffer = gl::makeBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, buffer.get());
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(sizeof block), block.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    return buffer;
}

// A block of another size than the C++ side's would read other numbers than the twin's: an error.
void bindGgxEnergyTables(const gl::ShaderProgram& program, const gl::Buffer& tables) {
    const GLuint block = glGetUniformBlockIndex(program.id(), "GgxEnergyTables");
    if (block == GL_INVALID_INDEX) return; // not in this program (or optimised away)
    GLint bytes = 0;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &bytes);
    if (std::size_t(bytes) != twin::ggxEnergyBlockFloats * sizeof(float))
        throw std::logic_error("the shader's GgxEnergyTables block has " + std::to_string(bytes) + " bytes, the C++ tables " +
                               std::to_string(twin::ggxEnergyBlockFloats * sizeof(float)));
    glUniformBlockBinding(program.id(), block, ggxEnergyBinding);
    glBindBufferBase(GL_UNIFORM_BUFFER, ggxEnergyBinding, tables.get());
}

GpuScene::GpuScene(const Scene& scene, const std::filesystem::path& environmentFile, MeshBvhCache& meshCache, TextureCache* textureCache)
    : GpuScene(prepareScene(scene, environmentFile, queryTextureLimits(), meshCache, {}, textureCache)) {}

GpuScene::GpuScene(PreparedScene prepared)
    : features_(prepared.features),
      packed_(std::move(prepared.packed)),
      environment_(prepared.environment),
      fog_(prepared.fog),
      shapes_(vec4Buffer("the shape buffer", packed_.shapes)),
      materials_(vec4Buffer("the material buffer", packed_.materials)),
      lights_(vec4Buffer("the light buffer", packed_.lights)),
      ggxEnergyTables_(uploadGgxEnergyTables()),
      meshes_(std::move(prepared.meshes)),
      textureArrays_(prepared.textures),
      textureSlots_{{}, std::move(prepared.textures.slotOf), {}, std::move(prepared.textures.meanOf)},
      texturesUsed_(std::move(prepared.texturesUsed)),
      warnings_(std::move(prepared.warnings)) {
    if (const auto& env = prepared.environmentMap) {
        // Bilinear, wrapping in longitude: the sampling table weights each pixel as read this way.
        environmentMap_ = uploadFloatTexture(GL_RGB32F, GL_RGB, env->image.width, env->image.height, env->image.rgb.data(), GL_LINEAR);
        environmentCdf_ = uploadFloatTexture(GL_R32F, GL_RED, env->table.tableWidth, env->table.tableHeight, env->table.cdf.data(), GL_NEAREST);
        environmentSize_ = {env->image.width, env->image.height};
    }
}

void GpuScene::updateTransforms(const Scene& scene) {
    // Shapes and lights carry world transforms; materials (and so texture references) did not
    // change, so they are packed without the texture set and left out of the upload.
    PackedScene moved = packScene(scene);
    packed_.shapes = std::move(moved.shapes);
    packed_.lights = std::move(moved.lights);
    packed_.shapeCount = moved.shapeCount;
    packed_.lightCount = moved.lightCount;
    packed_.shapeEmitterPower = moved.shapeEmitterPower;
    packed_.sphereLamps = moved.sphereLamps;
    shapes_ = vec4Buffer("the shape buffer", packed_.shapes);
    lights_ = vec4Buffer("the light buffer", packed_.lights);
    // Area lights' own materials follow the scene's and change with the lights' power, colour and
    // size (world area): those records are replaced; the scene's, with their texture references, stay.
    const auto areaLightMaterials = moved.materials.begin() + std::ptrdiff_t(moved.sceneMaterialCount) * materialTexels;
    const std::size_t sceneTexels = std::size_t(packed_.sceneMaterialCount) * materialTexels;
    if (!std::equal(areaLightMaterials, moved.materials.end(), packed_.materials.begin() + std::ptrdiff_t(sceneTexels),
                    packed_.materials.end())) {
        packed_.materials.resize(sceneTexels);
        packed_.materials.insert(packed_.materials.end(), areaLightMaterials, moved.materials.end());
        materials_ = vec4Buffer("the material buffer", packed_.materials);
    }
    // The pass reads the variant from the features at each frame: a light change that adds the
    // first emissive shape compiles it in.
    features_.shapes = moved.shapeCount > 0;
    features_.punctualLights = moved.lightCount > 0;
    features_.emissiveShapes = moved.emissiveShapes;
    features_.portals = moved.portals;
    meshes_.updateTransforms(scene, packed_.materialIndex, &textureSlots_);
    noteAreaEmitters();
}

// Moving, showing or hiding an emissive mesh, or a material edit, can bring the first area emitter
// in or take the last one out: the variant follows at the next frame.
void GpuScene::noteAreaEmitters() {
    features_.areaEmitters = meshes_.data().lights.count() > 0 || features_.emissiveShapes;
}

bool GpuScene::updateMaterials(const Scene& scene) {
    const std::set<MaterialId> materials = texturedMaterials(scene);
    if (texturesUsed(scene, materials) != texturesUsed_) return false; // another texture set
    SceneFeatures features = features_;
    features.alpha = features.singleSided = false;
    addMeshMaterialFeatures(scene, features);
    features.extensionTextures = extensionTexturesUsed(scene, materials, textureSlots_);
    features.media = usesMedia(scene);
    features.indexMatched = usesIndexMatched(scene);
    features.transmission = usesTransmission(scene);
    if (features.alpha != features_.alpha || features.singleSided != features_.singleSided ||
        features.extensionTextures != features_.extensionTextures || features.media != features_.media ||
        features.indexMatched != features_.indexMatched || features.transmission != features_.transmission)
        return false; // another variant
    PackedScene repacked = packScene(scene, &textureSlots_);
    if (repacked.materialIndex != packed_.materialIndex || repacked.shapes != packed_.shapes) return false;
    packed_.materials = std::move(repacked.materials);
    materials_ = vec4Buffer("the material buffer", packed_.materials);
    meshes_.updateEmission(scene, packed_.materialIndex, &textureSlots_);
    features_.everyEmitterLightSampled = lightSamplingReachesEveryEmitter(scene, &textureSlots_, features_.environmentMap);
    noteAreaEmitters();
    return true;
}

void GpuScene::bind(const gl::ShaderProgram& program) const {
    shapes_.bind(shapeUnit, program.uniform("uShapes"));
    materials_.bind(materialUnit, program.uniform("uMaterials"));
    lights_.bind(lightUnit, program.uniform("uLights"));
    bindGgxEnergyTables(program, ggxEnergyTables_);
    glUniform1i(program.uniform("uShapeCount"), packed_.shapeCount);
    glUniform1i(program.uniform("uLightCount"), packed_.lightCount);
    if (features_.emissiveShapes) glUniform1f(program.uniform("uShapeEmitterPower"), packed_.shapeEmitterPower);
    meshes_.bind(program, firstMeshUnit);
    if (features_.textures) textureArrays_.bind(program, firstTextureUnit);
    if (features_.media) bindFog(program, fog_);
    const glm::vec3 colour = environment_.color * environment_.intensity;
    glUniform3fv(program.uniform("uEnvironmentColor"), 1, glm::value_ptr(colour));
    if (features_.environmentMap) {
        bindTexture2D(environmentMap_, environmentUnit, program.uniform("uEnvironmentMap"));
        bindTexture2D(environmentCdf_, environmentCdfUnit, program.uniform("uEnvironmentCdf"));
        glUniform2i(program.uniform("uEnvironmentSize"), environmentSize_.x, environmentSize_.y);
        glUniform1f(program.uniform("uEnvironmentIntensity"), environment_.intensity);
        glUniform1f(program.uniform("uEnvironmentRotation"), glm::radians(environment_.rotationDegrees));
    }
}

} // namespace glint::renderer
