#include "renderer/gpu_scene/gpu_scene.h"

#include "renderer/gpu_scene/environment_image.h"

#include <glm/gtc/type_ptr.hpp>

namespace glint::renderer {
namespace {

enum TextureUnit : GLuint { shapeUnit = 0, materialUnit = 1, lightUnit = 2, environmentUnit = 3 };

gl::TextureBuffer vec4Buffer(const std::string& what, const std::vector<glm::vec4>& texels) {
    return gl::TextureBuffer(what, GL_RGBA32F, texels.data(), texels.size(), sizeof(glm::vec4));
}

gl::Texture uploadEnvironment(const EnvironmentImage& image) {
    gl::Texture texture = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, image.width, image.height, 0, GL_RGB, GL_FLOAT, image.rgb.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT); // longitude wraps around
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

} // namespace

gl::Defines SceneFeatures::defines() const {
    gl::Defines defines;
    if (meshes) defines["HAS_MESHES"] = "";
    if (environmentMap) defines["HAS_ENV_MAP"] = "";
    return defines;
}

GpuScene::GpuScene(const Scene& scene, const std::filesystem::path& environmentFile)
    : packed_(packScene(scene)),
      environment_(scene.settings.environment),
      shapes_(vec4Buffer("the shape buffer", packed_.shapes)),
      materials_(vec4Buffer("the material buffer", packed_.materials)),
      lights_(vec4Buffer("the light buffer", packed_.lights)) {
    if (!environmentFile.empty()) {
        environmentMap_ = uploadEnvironment(loadEnvironmentImage(environmentFile));
        features_.environmentMap = true;
    }
}

void GpuScene::bind(const gl::ShaderProgram& program) const {
    shapes_.bind(shapeUnit, program.uniform("uShapes"));
    materials_.bind(materialUnit, program.uniform("uMaterials"));
    lights_.bind(lightUnit, program.uniform("uLights"));
    glUniform1i(program.uniform("uShapeCount"), packed_.shapeCount);
    glUniform1i(program.uniform("uLightCount"), packed_.lightCount);
    const glm::vec3 colour = environment_.color * environment_.intensity;
    glUniform3fv(program.uniform("uEnvironmentColor"), 1, glm::value_ptr(colour));
    if (features_.environmentMap) {
        glActiveTexture(GL_TEXTURE0 + environmentUnit);
        glBindTexture(GL_TEXTURE_2D, environmentMap_.get());
        glUniform1i(program.uniform("uEnvironmentMap"), environmentUnit);
        glUniform1f(program.uniform("uEnvironmentIntensity"), environment_.intensity);
        glUniform1f(program.uniform("uEnvironmentRotation"), glm::radians(environment_.rotationDegrees));
    }
}

} // namespace glint::renderer
