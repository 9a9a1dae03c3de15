// The depth-first walk over the default scene's node hierarchy, composing transforms.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "scene/gltf_context.h"

namespace wp::gltf {

// The scene loadScene shows: `chosen` (the --scene flag) when given, else the default scene
// (model.scene, else scene 0); nothing when the file has no scenes. Throws, saying how many
// scenes there are, when the index is not one of the file's.
std::optional<size_t> sceneToWalk(const Context& ctx, std::optional<size_t> chosen);

// Visits every node of scene `scene` (sceneToWalk; without one, every root node) depth-first,
// a parent before its children and children in file order, with its world transform (parent
// * matrix, or parent * T * R * S). Throws, naming the node, on a missing node, a malformed
// or non-finite transform, a cycle, or a node reached twice (a glTF node has at most one
// parent). Never recurses, so no hierarchy is too deep.
void walkScene(const Context& ctx, std::optional<size_t> scene,
               const std::function<void(size_t node, const glm::mat4& world)>& visit);

}  // namespace wp::gltf
