// Nodes: ids, names, TRS transforms (a matrix is decomposed), visibility and the one component a
// Glint node carries. A glTF node holding a mesh and a camera or light keeps the mesh; the camera or
// light moves to a child node (warning split-node).
#include "gltf_read_json.h"
#include "gltf_read_nodes.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

bool nearlyEqual(const glm::mat4& a, const glm::mat4& b)
{
    float scale = 1.0f;
    for (int c = 0; c < 4; ++c) for (int r = 0; r < 4; ++r) scale = std::max(scale, std::abs(a[c][r]));
    for (int c = 0; c < 4; ++c) for (int r = 0; r < 4; ++r) if (std::abs(a[c][r] - b[c][r]) > 1e-4f * scale) return false;
    return true;
}

Transform matrixTransform(GltfReadContext& ctx, const Json& node, const std::string& where)
{
    const Json& values = node["matrix"];
    if (!values.is_array() || values.size() != 16) ctx.fail("wrong-type", where + ".matrix must be an array of 16 numbers");
    glm::mat4 m;
    for (std::size_t i = 0; i < 16; ++i) {
        if (!values[i].is_number()) ctx.fail("wrong-type", where + ".matrix must be an array of 16 numbers");
        glm::value_ptr(m)[i] = finiteFloat(values[i].get<double>(), ctx.file, where + ".matrix");
    }
    Transform t = fromMatrix(m);
    const bool finite = std::isfinite(t.rotation.x) && std::isfinite(t.rotation.y) && std::isfinite(t.rotation.z) && std::isfinite(t.rotation.w);
    if (!finite) t.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    if (!nearlyEqual(toMatrix(t), m) && t.scale != glm::vec3(0.0f))
        ctx.warn("matrix-shear", where + ".matrix has shear (or is not a rotation and scale): it is approximated by translation, rotation and scale");
    return t;
}

// glTF rotations are unit quaternions. A zero one has no rotation to recover (identity, named); a
// visibly non-unit one is normalised, named too; exporters' rounding (within 1e-3) passes quietly.
glm::quat unitRotation(GltfReadContext& ctx, const glm::vec4& q, const std::string& where)
{
    const double length = std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z + double(q.w) * q.w);
    const std::string text = "[" + floatText(q.x) + ", " + floatText(q.y) + ", " + floatText(q.z) + ", " + floatText(q.w) + "]";
    if (length < 1e-6) {
        ctx.warn("invalid-value", where + ".rotation is " + text + ", not a rotation (a unit quaternion): the identity is used");
        return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    }
    const glm::quat rotation(q.w, q.x, q.y, q.z);
    if (std::abs(length - 1.0) <= 1e-3) return rotation;
    ctx.warn("invalid-value", where + ".rotation is " + text + ", not a unit quaternion: normalised");
    return glm::normalize(rotation);
}

Transform readTransform(GltfReadContext& ctx, const Json& node, const std::string& where)
{
    const JsonReader json{ctx.file};
    Transform t;
    if (node.contains("matrix")) {
        t = matrixTransform(ctx, node, where);
    } else {
        t.translation = json.vec3(node, "translation", t.translation, where);
        const glm::vec4 q = json.vec4(node, "rotation", glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), where);
        t.rotation = unitRotation(ctx, q, where);
        t.scale = json.vec3(node, "scale", t.scale, where);
    }
    if (t.scale.x == 0.0f || t.scale.y == 0.0f || t.scale.z == 0.0f)
        ctx.warn("zero-scale", where + " has a zero scale: it and its children are invisible");
    return t;
}

// Whether a node's `weights` equal its mesh's (absent or missing entries count as 0).
bool sameMorphWeights(const Json& nodeWeights, const Json& mesh)
{
    const Json none = Json::array();
    const Json& meshWeights = mesh.is_object() && mesh.contains("weights") ? mesh["weights"] : none;
    if (!nodeWeights.is_array() || !meshWeights.is_array()) return false;
    const auto at = [](const Json& list, std::size_t k) { return k < list.size() && list[k].is_number() ? list[k].get<double>() : 0.0; };
    for (std::size_t k = 0; k < std::max(nodeWeights.size(), meshWeights.size()); ++k)
        if (at(nodeWeights, k) != at(meshWeights, k)) return false;
    return true;
}

struct NodeParts {
    Component primary;                  // mesh or shape, else the camera or light
    std::vector<Component> splitOff;    // a camera and/or light that moves to child nodes
};

NodeParts readComponents(GltfReadContext& ctx, const Json& node, const std::string& where)
{
    const JsonReader json{ctx.file};
    std::vector<Component> parts;
    if (const Json* area = json.extension(node, "GLINT_area_light", where)) {
        parts.emplace_back(readAreaLight(ctx, *area, where + ".extensions.GLINT_area_light"));
    } else if (const Json* shape = json.extension(node, "GLINT_shape", where)) {
        parts.emplace_back(readShape(ctx, *shape, where + ".extensions.GLINT_shape"));
    } else if (const int mesh = json.index(node, "mesh", where); mesh >= 0 && ctx.meshIds.at(static_cast<std::size_t>(mesh)).valid()) {
        parts.emplace_back(MeshInstance{ctx.meshIds[static_cast<std::size_t>(mesh)]});
    }
    if (const int camera = json.index(node, "camera", where); camera >= 0) parts.emplace_back(readCamera(ctx, camera, node, where));
    if (const Json* light = json.extension(node, "KHR_lights_punctual", where)) {
        const int index = json.index(*light, "light", where + ".extensions.KHR_lights_punctual");
        if (index >= 0) parts.emplace_back(readLight(ctx, index));
    }
    if (json.member(node, "skin")) ctx.drop("skin-dropped", where + " is skinned: loaded as static geometry in its bind pose");
    if (const Json* weights = json.member(node, "weights")) {
        const int mesh = json.index(node, "mesh", where);
        if (mesh >= 0 && !sameMorphWeights(*weights, ctx.doc["meshes"][static_cast<std::size_t>(mesh)]))
            ctx.warn("morph-weights-ignored", where + " sets morph weights of its own: its mesh is loaded at the mesh's default weights");
    }
    NodeParts out;
    if (parts.empty()) return out;
    out.primary = parts.front();
    out.splitOff.assign(parts.begin() + 1, parts.end());
    return out;
}

std::string splitName(const std::string& name, const Component& c)
{
    return (name.empty() ? std::string("node") : name) + (std::holds_alternative<Camera>(c) ? ".camera" : ".light");
}

void addSplitChildren(GltfReadContext& ctx, NodeId parent, const std::string& name, const std::vector<Component>& parts, const std::string& where)
{
    for (const Component& c : parts) {
        Node child;
        child.name = splitName(name, c);
        child.component = c;
        ctx.scene.addNode(std::move(child), parent);
        ctx.warn("split-node", where + " carries more than one of mesh, camera and light: the " +
                                   std::string(std::holds_alternative<Camera>(c) ? "camera" : "light") + " moves to the child node '" + splitName(name, c) + "'");
    }
}

struct PendingSplit {
    NodeId parent;
    std::string name;
    std::vector<Component> parts;
    std::string where;
};

PendingSplit addNode(GltfReadContext& ctx, int index, NodeId id, NodeId parent)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["nodes"][static_cast<std::size_t>(index)];
    const std::string where = "nodes[" + std::to_string(index) + "]";
    Node node;
    node.id = id;
    node.name = json.string(source, "name", where);
    node.local = readTransform(ctx, source, where);
    if (const Json* glint = json.extension(source, "GLINT_node", where)) node.visible = json.boolean(*glint, "visible", true, where + ".extensions.GLINT_node");
    NodeParts parts = readComponents(ctx, source, where);
    node.component = parts.primary;
    node.unknown = unknownMembers(source, {"GLINT_node", "GLINT_shape", "GLINT_area_light", "GLINT_camera_path", "KHR_lights_punctual"});
    const std::string name = node.name;
    ctx.scene.addNode(std::move(node), parent);
    return {id, name, std::move(parts.splitOff), where};
}

} // namespace

void readNodes(GltfReadContext& ctx)
{
    const std::vector<int> parents = nodeParents(ctx);
    const std::vector<int> order = nodesToLoad(ctx, parents);
    ctx.nodeIds = assignNodeIds(ctx, order);
    std::vector<PendingSplit> splits;
    for (int n : order) {
        const int parent = parents[static_cast<std::size_t>(n)];
        splits.push_back(addNode(ctx, n, ctx.nodeIds[static_cast<std::size_t>(n)], parent >= 0 ? ctx.nodeIds[static_cast<std::size_t>(parent)] : NodeId{}));
    }
    // Split-off cameras and lights get ids after every glTF node, so they never take a saved id.
    for (const PendingSplit& split : splits) addSplitChildren(ctx, split.parent, split.name, split.parts, split.where);
    checkPortalPairs(ctx);
}

} // namespace glint
