// Axis-aligned bounding box used by the BVH builders and the scene packer.
#pragma once

#include <limits>

#include <glm/glm.hpp>

namespace wp {

struct Aabb {
  // Default-constructed boxes are empty (min > max), so growing one by a point gives that point.
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};

  void grow(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void grow(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 extent() const { return max - min; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  // Surface area; 0 for an empty box so empty children never add SAH cost.
  float area() const {
    if (isEmpty()) {
      return 0.0f;
    }
    glm::vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  bool contains(const Aabb& b) const {
    return glm::all(glm::lessThanEqual(min, b.min)) && glm::all(glm::lessThanEqual(b.max, max));
  }
};

// The box around `b`'s eight corners mapped by the affine `m`.
inline Aabb transformBox(const glm::mat4& m, const Aabb& b) {
  Aabb out;
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                (corner & 4) ? b.max.z : b.min.z);
    out.grow(glm::vec3(m * glm::vec4(p, 1.0f)));
  }
  return out;
}

}  // namespace wp
