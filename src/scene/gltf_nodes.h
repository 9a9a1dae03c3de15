// The depth-first walk over the default scene's node hierarchy, composing transforms.
#pragma once

#include <cstddef>
#include <functional>

#include <glm/glm.hpp>

#include "scene/gltf_context.h"

namespace wp::gltf {

// Visits every node of the default scene (model.scene, else scene 0, else every root node
// when the file has no scenes) depth-first, a parent before its children and children in
// file order, with its world transform (parent * matrix, or parent * T * R * S). Throws,
// naming the node, on a missing scene or node, a malformed or non-finite transform, a cycle,
// or a node reached twice (a glTF node has at most one parent). Never recurses, so no
// hierarchy is too deep.
void walkDefaultScene(const Context& ctx, const std::function<void(size_t node, const glm::mat4& world)>& visit);

}  // namespace wp::gltf
