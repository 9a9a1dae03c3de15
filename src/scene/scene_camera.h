// Scene cameras: from a glTF camera node, or framed automatically around the scene.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wp {

// The camera of a glTF camera node with world transform `world`: at the node origin,
// looking down the node's -z, with the node's +y made orthogonal to that as up. Returns
// nothing when the transform collapses the view or the up direction.
std::optional<Camera> cameraFromNode(const glm::mat4& world, float yfov, float aspectRatio);

// The vertical field of view of an automatically framed camera, in radians (45 degrees).
inline constexpr float kFramingYfov = 0.7853982f;

// A camera that sees the whole scene: it looks down -z at the centre of the bounds of all
// triangles and spheres (planes are infinite and ignored), far enough back that their
// bounding sphere fits kFramingYfov with a small margin. aspectRatio is 0 (the image's).
// Without triangles or spheres it frames a unit sphere at the origin.
Camera frameScene(const Scene& scene);

}  // namespace wp
