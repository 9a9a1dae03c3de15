// Motion keys of moving instances and their swept bounds.
#include "bvh/instance_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "shaders/common/motion.h"

namespace wp {
namespace {

struct Trs {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

// Translation, rotation and scale of an invertible affine m, or nothing when its 3x3 part
// shears (its columns are not orthogonal to 1e-4 after removing their lengths). A mirror
// goes into a negative x scale.
std::optional<Trs> decompose(const glm::mat4& m) {
  glm::mat3 a(m);
  Trs trs;
  trs.translation = glm::vec3(m[3]);
  for (int c = 0; c < 3; ++c) {
    trs.scale[c] = glm::length(a[c]);
    a[c] /= trs.scale[c];
  }
  if (glm::determinant(a) < 0.0f) {
    trs.scale.x = -trs.scale.x;
    a[0] = -a[0];
  }
  glm::mat3 gram = glm::transpose(a) * a;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(gram[c][r] - (r == c ? 1.0f : 0.0f)) > 1e-4f) {
        return std::nullopt;
      }
    }
  }
  trs.rotation = glm::normalize(glm::quat_cast(a));
  return trs;
}

gpu::GpuInstance trsKey(const Trs& trs) {
  const glm::quat& q = trs.rotation;
  return gpu::makeTrsMotionKey(trs.translation, glm::vec4(q.x, q.y, q.z, q.w), trs.scale);
}

gpu::GpuInstance matrixKey(const glm::mat4& m) {
  glm::mat4 rows = glm::transpose(m);
  return gpu::makeMatrixMotionKey(rows[0], rows[1], rows[2]);
}

glm::mat4 toMat4(const gpu::AffineRows& m) {
  return glm::transpose(glm::mat4(m.row0, m.row1, m.row2, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
}

}  // namespace

std::optional<MotionKeys> makeMotionKeys(const glm::mat4& open, const glm::mat4& close) {
  if (open == close) {
    return std::nullopt;
  }
  std::optional<Trs> a = decompose(open);
  std::optional<Trs> b = decompose(close);
  if (!a || !b) {
    return MotionKeys{matrixKey(open), matrixKey(close)};
  }
  if (glm::dot(a->rotation, b->rotation) < 0.0f) {
    b->rotation = -b->rotation;  // q and -q are the same rotation; this one is the shorter arc
  }
  return MotionKeys{trsKey(*a), trsKey(*b)};
}

glm::mat4 objectToWorldAt(const MotionKeys& keys, float u) {
  return toMat4(gpu::objectToWorldAt(keys.open, keys.close, u));
}

// A point p of the object is at M(u) p. With matrix keys M(u) is a lerp, and with TRS keys
// of equal rotation T(u) + R S(u) p is too: p moves on a segment, so the box over both ends
// holds it throughout. With a rotation the path curves and may leave both end boxes; then
// |R(u) S(u) p| = |S(u) p| <= r, where r bounds |S p| over the box's corners (|S p|^2 is
// convex in p) with each squared scale at its larger end value (s_i(u) is linear, so s_i^2 is
// convex in u): the object stays within r of T(u), which runs along the segment T0 T1.
Aabb sweptBounds(const MotionKeys& keys, const Aabb& objectBounds) {
  bool curved = gpu::motionKeyKind(keys.open) == WP_MOTION_KEY_TRS &&
                gpu::motionKeyRotation(keys.open) != gpu::motionKeyRotation(keys.close);
  if (!curved) {
    Aabb box = transformBox(objectToWorldAt(keys, 0.0f), objectBounds);
    box.grow(transformBox(objectToWorldAt(keys, 1.0f), objectBounds));
    return box;
  }
  glm::vec3 s0(gpu::motionKeyScale(keys.open)), s1(gpu::motionKeyScale(keys.close));
  glm::vec3 scaleSquared = glm::max(s0 * s0, s1 * s1);
  float radiusSquared = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 p((corner & 1) ? objectBounds.max.x : objectBounds.min.x,
                (corner & 2) ? objectBounds.max.y : objectBounds.min.y,
                (corner & 4) ? objectBounds.max.z : objectBounds.min.z);
    radiusSquared = std::max(radiusSquared, glm::dot(scaleSquared, p * p));
  }
  // A relative 1e-5 covers the float rounding of the GPU's interpolated transform.
  float radius = std::sqrt(radiusSquared) * (1.0f + 1e-5f);
  glm::vec3 t0(gpu::motionKeyTranslation(keys.open)), t1(gpu::motionKeyTranslation(keys.close));
  return Aabb{glm::min(t0, t1) - radius, glm::max(t0, t1) + radius};
}

}  // namespace wp
