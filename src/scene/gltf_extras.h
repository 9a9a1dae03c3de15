// wavepath's analytic shapes, read from node extras (the schema is in gltf_loader.cpp).
#pragma once

#include <cstddef>
#include <optional>

#include "scene/gltf_context.h"

namespace wp::gltf {

struct ShapeSpec {
  enum class Kind { Sphere, Plane };
  Kind kind = Kind::Sphere;
  double radius = 0.0;  // spheres only, in node-local units
  int material = -1;    // a glTF material index; -1: the default material
};

// The shape in node `index`'s extras.wavepath, or nothing when the node has none. Throws,
// naming the node, on an unknown shape, a radius that is not a number > 0, or a material
// that is not an index of the file's materials array.
std::optional<ShapeSpec> readShape(const Context& ctx, size_t index);

}  // namespace wp::gltf
