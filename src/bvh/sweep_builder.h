// Reference BVH builder: exact SAH over every split position of the sorted centroids on all
// three axes. Slow (O(n log n) per level); the quality yardstick for the binned builder.
#pragma once

#include <span>

#include "bvh/bvh_builder.h"

namespace wp {

// Builds a BVH by a full SAH sweep, with the same leaf rule, costs and depth budget as
// buildBvh (options.threads is ignored). Same requirements as buildBvh.
Bvh buildBvhSweep(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
                  const BvhBuildOptions& options = {});

}  // namespace wp
