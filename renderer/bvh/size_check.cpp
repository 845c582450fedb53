#include "renderer/bvh/size_check.h"

#include "renderer/bvh/bvh_layout.h"

#include <sstream>

namespace glint::bvh {
namespace {

struct BufferSize {
    const char* uniform;
    std::size_t texels;
    std::size_t items;
    const char* itemName;
};

} // namespace

std::optional<std::string> checkTextureBufferSizes(const FlatScene& scene, std::int64_t maxTexels)
{
    const BufferSize buffers[] = {
        {kNodesUniform, scene.nodes.size(), scene.nodes.size(), "nodes"},
        {kLevelsUniform, scene.levels.size(), scene.levels.size() / kLevelTexels, "meshes and the top level"},
        {kTrianglePositionsUniform, scene.trianglePositions.size(), scene.triangleVertices.size(), "triangles"},
        {kTriangleVerticesUniform, scene.triangleVertices.size(), scene.triangleVertices.size(), "triangles"},
        {kInstancesUniform, scene.instances.size(), scene.instances.size() / kInstanceTexels, "instances"},
    };
    for (const BufferSize& buffer : buffers) {
        if (static_cast<std::int64_t>(buffer.texels) <= maxTexels) continue;
        std::ostringstream out;
        out << "BVH buffer " << buffer.uniform << " needs " << buffer.texels << " texels but GL_MAX_TEXTURE_BUFFER_SIZE is "
            << maxTexels << " (" << buffer.items << ' ' << buffer.itemName << ")";
        return out.str();
    }
    return std::nullopt;
}

} // namespace glint::bvh
