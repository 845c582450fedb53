#include "renderer/raster/preview_pass.h"

#include "renderer/gl/gl_objects.h"
#include "renderer/gl/program_cache.h"
#include "renderer/passes/selection_outline_pass.h"
#include "renderer/gpu_scene/visibility.h"
#include "scene/geometry/geometry.h"

#include <map>
#include <vector>

namespace glint::renderer::raster {

namespace {

constexpr float kGroundExtent = 50.0f;

// One mesh or shape as an indexed triangle list: position + normal interleaved.
struct GpuGeometry {
    gl::VertexArray vao;
    gl::Buffer vertices;
    gl::Buffer indices;
    GLsizei indexCount = 0;
};

void appendPrimitive(Primitive p, std::vector<float>& vertices, std::vector<std::uint32_t>& indices) {
    if (p.normals.size() != p.positions.size()) generateFlatNormals(p);
    const auto base = static_cast<std::uint32_t>(vertices.size() / 6);
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
        const glm::vec3 n = v < p.normals.size() ? p.normals[v] : glm::vec3(0.0f, 1.0f, 0.0f);
        vertices.insert(vertices.end(), {p.positions[v].x, p.positions[v].y, p.positions[v].z, n.x, n.y, n.z});
    }
    for (const std::uint32_t i : p.indices) indices.push_back(base + i);
}

std::unique_ptr<GpuGeometry> upload(const std::vector<float>& vertices, const std::vector<std::uint32_t>& indices) {
    auto g = std::make_unique<GpuGeometry>(GpuGeometry{gl::makeVertexArray(), gl::makeBuffer(), gl::makeBuffer(), 0});
    glBindVertexArray(g->vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, g->vertices.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->indices.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
    glBindVertexArray(0);
    g->indexCount = GLsizei(indices.size());
    return g;
}

// The caller's framebuffer, viewport and state, put back when a draw ends.
struct SavedState {
    GLint framebuffer = 0, vao = 0, program = 0;
    GLint viewport[4] = {};
    GLint polygonMode[2] = {GL_FILL, GL_FILL};
    GLboolean depthTest = GL_FALSE, cull = GL_FALSE, blend = GL_FALSE;
    SavedState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_POLYGON_MODE, polygonMode);
        depthTest = glIsEnabled(GL_DEPTH_TEST);
        cull = glIsEnabled(GL_CULL_FACE);
        blend = glIsEnabled(GL_BLEND);
    }
    ~SavedState() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(framebuffer));
        glBindVertexArray(GLuint(vao));
        glUseProgram(GLuint(program));
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygonMode[0]));
        depthTest ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
        cull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
        blend ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    }
};

} // namespace

struct PreviewPass::State {
    gl::ProgramCache programs;
    std::map<MeshId, std::unique_ptr<GpuGeometry>> meshes;
    std::map<NodeId, std::pair<Shape, std::unique_ptr<GpuGeometry>>> shapes;

    const GpuGeometry* meshGeometry(const Scene& scene, MeshId id) {
        auto& slot = meshes[id];
        if (!slot) {
            std::vector<float> vertices;
            std::vector<std::uint32_t> indices;
            for (const Primitive& p : scene.meshes.at(id).primitives) appendPrimitive(p, vertices, indices);
            slot = upload(vertices, indices);
        }
        return slot.get();
    }

    const GpuGeometry* shapeGeometry(NodeId node, const Shape& shape) {
        auto& slot = shapes[node];
        if (!slot.second || !(slot.first == shape)) {
            std::vector<float> vertices;
            std::vector<std::uint32_t> indices;
            appendPrimitive(tessellateShape(shape, 32, kGroundExtent), vertices, indices);
            slot = {shape, upload(vertices, indices)};
        }
        return slot.second.get();
    }
};

PreviewPass::PreviewPass() : state_(std::make_unique<State>()) {}
PreviewPass::~PreviewPass() = default;

void PreviewPass::invalidate() {
    state_->meshes.clear();
    state_->shapes.clear();
}

void PreviewPass::draw(const Scene& scene, unsigned int framebuffer, const PreviewView& view) {
    const SavedState saved;
    const gl::ShaderProgram& program = state_->programs.get({"raster/preview.vert.glsl", "raster/preview.frag.glsl", {}, {"fColor"}});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, view.width, view.height);
    glClearColor(0.22f, 0.22f, 0.24f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const bool wire = view.style == PreviewStyle::Wireframe;
    glPolygonMode(GL_FRONT_AND_BACK, wire ? GL_LINE : GL_FILL);
    program.use();
    glUniformMatrix4fv(program.uniform("uClipFromWorld"), 1, GL_FALSE, &view.clipFromWorld[0][0]);
    glUniform3fv(program.uniform("uEye"), 1, &view.eye[0]);
    glUniform1i(program.uniform("uShaded"), wire ? 0 : 1);
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (!visibleInWorld(scene, node)) continue;
        const GpuGeometry* geometry = nullptr;
        if (const auto* instance = node.get<MeshInstance>(); instance && scene.meshes.contains(instance->mesh))
            geometry = state_->meshGeometry(scene, instance->mesh);
        else if (const auto* shape = node.get<Shape>())
            geometry = state_->shapeGeometry(id, *shape);
        if (!geometry || geometry->indexCount == 0) continue;
        const glm::mat4 world = scene.worldFromNode(id);
        const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(world)));
        const glm::vec3 colour = id == view.highlight ? selectionColour : (wire ? glm::vec3(0.85f) : glm::vec3(0.75f));
        glUniformMatrix4fv(program.uniform("uWorldFromLocal"), 1, GL_FALSE, &world[0][0]);
        glUniformMatrix3fv(program.uniform("uNormalFromLocal"), 1, GL_FALSE, &normal[0][0]);
        glUniform3fv(program.uniform("uColor"), 1, &colour[0]);
        glBindVertexArray(geometry->vao.get());
        glDrawElements(GL_TRIANGLES, geometry->indexCount, GL_UNSIGNED_INT, nullptr);
    }
}

} // namespace glint::renderer::raster
