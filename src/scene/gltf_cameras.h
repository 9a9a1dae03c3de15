// glTF cameras: converting a perspective or orthographic camera at its node, and which
// camera the --camera flag names.
#pragma once

#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// Whether `selection` (empty: any camera) names camera `camera` placed by node `node`: its
// index in the file written as a number, or the name of the camera or of the node.
bool cameraSelected(const Context& ctx, const std::string& selection, size_t camera, size_t node);

// The file's cameras for a message: "0 'Main', 1 'Top'" (or "the file has no cameras").
std::string cameraList(const Context& ctx);

// Camera `camera` of the file seen from the node with world transform `world` (`nodeWhere`
// names that node in messages): perspective (yfov, aspectRatio, the optics of its extras) or
// orthographic (ymag, and xmag / ymag as its aspect ratio). Throws, naming the camera, on
// another type, values out of range, or a transform that collapses the view.
Camera convertCamera(const Context& ctx, size_t camera, const std::string& nodeWhere, const glm::mat4& world);

}  // namespace wp::gltf
