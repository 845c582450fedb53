#pragma once
// Internal to node reading: the graph checks and the components a glTF node can carry.
#include "gltf_reader.h"

#include <vector>

namespace glint {

// parent[i] of every glTF node (-1: none). Throws node-graph-cycle for a node with two parents,
// a node that is its own child, or any loop.
std::vector<int> nodeParents(const GltfReadContext& ctx);

// The glTF nodes of the default scene ("scene", else scene 0) in depth-first order, parents first;
// with no scene, every root (warning no-scene). Nodes outside are named as dropped.
std::vector<int> nodesToLoad(GltfReadContext& ctx, const std::vector<int>& parents);

// Ids from GLINT_node, else i + 1 for glTF node i; duplicates and clashes get the next free id.
std::vector<NodeId> assignNodeIds(GltfReadContext& ctx, const std::vector<int>& loaded);

Camera readCamera(GltfReadContext& ctx, int camera, const nlohmann::json& node, const std::string& where);
Light readLight(const GltfReadContext& ctx, int light);
Shape readShape(GltfReadContext& ctx, const nlohmann::json& extension, const std::string& where);
// GLINT_shape's `portal` as the id its index names (none, with a warning, when it names no loaded node).
NodeId readPortalLink(GltfReadContext& ctx, const nlohmann::json& extension, const std::string& where);
// After every node is read: drops each portal link that is not half of a pair of quads, named.
void checkPortalPairs(GltfReadContext& ctx);
// GLINT_area_light on a node: an area light (the node's emissive mesh is its fallback, dropped).
Light readAreaLight(GltfReadContext& ctx, const nlohmann::json& extension, const std::string& where);

} // namespace glint
