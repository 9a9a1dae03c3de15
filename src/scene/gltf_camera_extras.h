// Physical camera settings read from a glTF camera's extras (the schema is in gltf_loader.cpp).
#pragma once

#include <cstddef>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// The optics in camera `index`'s extras.wavepath (defaults where absent). Throws, naming the
// camera, when a value is not a number in its range.
CameraOptics readCameraOptics(const Context& ctx, size_t index);

}  // namespace wp::gltf
