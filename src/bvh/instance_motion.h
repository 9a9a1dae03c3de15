// Motion keys of a moving instance (its placement at shutter open and close, as the GPU
// interpolates them) and the bounds it sweeps during the shutter.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "bvh/aabb.h"
#include "shaders/common/layout.h"

namespace wp {

struct MotionKeys {
  gpu::GpuInstance open{};   // WP_MOTION_KEY_TRS or WP_MOTION_KEY_MATRIX records (layout.h)
  gpu::GpuInstance close{};
};

// The keys for an instance at `open` and `close` (object-to-world): both decomposed into
// translation, rotation and scale when they are free of shear (their rotations put in one
// hemisphere, so slerp takes the shorter arc), else both kept as matrices (lerped). Nothing
// when the two are equal, or when the orientation flips between them (the interpolation
// would pass through a singular transform).
std::optional<MotionKeys> makeMotionKeys(const glm::mat4& open, const glm::mat4& close);

// The object-to-world transform at normalized shutter time u in [0, 1], computed by the
// same code the GPU runs (shaders/common/motion.h).
glm::mat4 objectToWorldAt(const MotionKeys& keys, float u);

// A world box that holds `objectBounds` placed at every time in the shutter (see the .cpp).
Aabb sweptBounds(const MotionKeys& keys, const Aabb& objectBounds);

}  // namespace wp
