// Motion blur on the host: the interpolation of motion keys, the bounds a moving instance
// sweeps, the traversal at a time against a still scene posed at that time, and what the
// packer does with moving instances and their emitters.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "bvh/device_buffers.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "bvh/instance_motion.h"
#include "shaders/common/traverse.h"

namespace wp {
namespace {

glm::mat4 trs(glm::vec3 t, float angle, glm::vec3 axis, glm::vec3 s) {
  return glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), t), angle, glm::normalize(axis)), s);
}

// Float decomposition and recomposition round in the last bits of values of order 1.
void expectNear(const glm::mat4& a, const glm::mat4& b, float tolerance = 1e-5f) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "column " << c << ", row " << r;
    }
  }
}

TEST(MotionKeys, EndsAreTheTwoTransformsAndHalfwayIsTheHalfRotation) {
  glm::mat4 open = trs(glm::vec3(1, 2, 3), 0.0f, glm::vec3(0, 1, 0), glm::vec3(1.0f));
  glm::mat4 close = trs(glm::vec3(3, 2, -1), glm::radians(90.0f), glm::vec3(0, 1, 0), glm::vec3(3.0f, 2.0f, 1.0f));
  MotionKeys keys = *makeMotionKeys(open, close);
  EXPECT_EQ(keys.open.info.x, WP_MOTION_KEY_TRS);
  expectNear(objectToWorldAt(keys, 0.0f), open);
  expectNear(objectToWorldAt(keys, 1.0f), close);
  // Slerp halfway is 45 degrees about the same axis; translation and scale are halfway too.
  expectNear(objectToWorldAt(keys, 0.5f),
             trs(glm::vec3(2, 2, 1), glm::radians(45.0f), glm::vec3(0, 1, 0), glm::vec3(2.0f, 1.5f, 1.0f)));
}

TEST(MotionKeys, RotationTakesTheShorterArcAndMirrorsStayMirrored) {
  // 350 degrees is -10 degrees: halfway must be -5, not 175.
  glm::vec3 axis(1, 2, 0.5f);
  glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
  MotionKeys keys = *makeMotionKeys(mirror, trs(glm::vec3(0), glm::radians(350.0f), axis, glm::vec3(1)) * mirror);
  expectNear(objectToWorldAt(keys, 0.5f), trs(glm::vec3(0), glm::radians(-5.0f), axis, glm::vec3(1)) * mirror);
}

TEST(MotionKeys, ShearFallsBackToALerpOfTheMatricesAndStillnessIsNoMotion) {
  glm::mat4 shear(1.0f);
  shear[1][0] = 0.5f;  // x += 0.5 y
  glm::mat4 open = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)) * shear;
  glm::mat4 close = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 2));
  MotionKeys keys = *makeMotionKeys(open, close);
  EXPECT_EQ(keys.open.info.x, WP_MOTION_KEY_MATRIX);
  expectNear(objectToWorldAt(keys, 0.25f), open * 0.75f + close * 0.25f);
  EXPECT_FALSE(makeMotionKeys(open, open).has_value());
}

// Transformed corners of the object box at many times (the box's image is the convex hull of
// its corners') must lie in the swept bounds; so that the test can fail, a rotation must
// also carry some of them out of the box around the two ends, which the bounds must cover.
TEST(MotionKeys, SweptBoundsHoldTheObjectAtEveryTime) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Aabb object{glm::vec3(0.5f, -0.2f, -1.0f), glm::vec3(2.0f, 0.3f, 0.1f)};
  int outsideEnds = 0;
  for (int trial = 0; trial < 50; ++trial) {
    glm::vec3 axisA(u(rng), u(rng), u(rng)), axisB(u(rng), u(rng), u(rng));
    glm::mat4 open = trs(glm::vec3(u(rng), u(rng), u(rng)) * 3.0f, 3.0f * u(rng), axisA,
                         glm::vec3(1.5f) + glm::vec3(u(rng), u(rng), u(rng)));
    glm::mat4 close = trs(glm::vec3(u(rng), u(rng), u(rng)) * 3.0f, 3.0f * u(rng), axisB,
                          glm::vec3(1.5f) + glm::vec3(u(rng), u(rng), u(rng)));
    MotionKeys keys = *makeMotionKeys(open, close);
    Aabb swept = sweptBounds(keys, object);
    Aabb ends = transformBox(open, object);
    ends.grow(transformBox(close, object));
    // The GPU's interpolation and this host replay round alike, within 1e-5 of the extent.
    glm::vec3 slack(1e-5f * glm::length(swept.extent()));
    for (int step = 0; step <= 200; ++step) {
      Aabb box = transformBox(objectToWorldAt(keys, float(step) / 200.0f), object);
      EXPECT_TRUE(glm::all(glm::lessThanEqual(swept.min - slack, box.min)) &&
                  glm::all(glm::lessThanEqual(box.max, swept.max + slack)))
          << "trial " << trial << ", time " << float(step) / 200.0f;
      outsideEnds += !ends.contains(box);
    }
  }
  EXPECT_GT(outsideEnds, 0);
}

Mesh soup(std::mt19937& rng, int triangles, uint32_t material) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Mesh m;
  for (int t = 0; t < 3 * triangles; ++t) {
    m.positions.push_back(glm::vec3(u(rng), u(rng), u(rng)));
    m.indices.push_back(uint32_t(t));
  }
  m.materials.assign(triangles, material);
  return m;
}

// Closest-hit distance of a ray at shutter time `time`, or -1 for a miss.
float hitDistance(const GpuScene& g, glm::vec3 o, glm::vec3 d, float time) {
  gpu::Hit h = gpu::traceClosest(sceneBuffers(g), g.topLevelEntry(), uint32_t(g.planes.size()), o, d, WP_FLT_MAX, time);
  return h.instance == WP_INVALID ? -1.0f : h.t;
}

// The traversal of a scene with moving instances at time u sees what the traversal of the
// still scene posed at u (by the host replay of the same interpolation) sees. The two
// inverses differ in rounding (cofactors on the GPU path, glm::inverse for still ones), so
// distances agree to 1e-4 and a few grazing rays may hit or miss an edge differently.
TEST(MotionTraversal, SeesTheSceneWhereItIsAtTheRaysTime) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Scene moving;
  moving.materials.resize(2);
  moving.meshes.push_back(soup(rng, 60, 0));
  moving.meshes.push_back(soup(rng, 1, 1));
  moving.instances.push_back({0, trs(glm::vec3(-1, 0, 0), 0.3f, glm::vec3(1, 1, 0), glm::vec3(1.0f))});
  moving.instances[0].objectToWorldAtClose = trs(glm::vec3(1, 0.5f, 0), 2.0f, glm::vec3(0, 1, 1), glm::vec3(1.3f));
  moving.instances.push_back({1, trs(glm::vec3(0, 2, 0), 0.0f, glm::vec3(0, 1, 0), glm::vec3(2.0f))});  // still
  moving.spheres.push_back({trs(glm::vec3(0, -2, 0), 0.0f, glm::vec3(0, 1, 0), glm::vec3(0.5f, 0.7f, 0.5f)), 1});
  moving.spheres[0].objectToWorldAtClose = trs(glm::vec3(0.5f, -1.5f, 0), 1.0f, glm::vec3(1, 0, 0), glm::vec3(0.6f));
  GpuScene g = packScene(moving);
  ASSERT_EQ(g.placedInstances, 3u);
  ASSERT_EQ(g.instances.size(), 3u + 2u * 2u);

  int rays = 0, mismatches = 0, hits = 0;
  for (int k = 0; k < 16; ++k) {
    float time = (float(k) + 0.5f) / 16.0f;
    Scene posed = moving;
    for (MeshInstance& inst : posed.instances) {
      if (inst.objectToWorldAtClose) {
        inst.objectToWorld = objectToWorldAt(*makeMotionKeys(inst.objectToWorld, *inst.objectToWorldAtClose), time);
        inst.objectToWorldAtClose.reset();
      }
    }
    Sphere& sphere = posed.spheres[0];
    sphere.objectToWorld = objectToWorldAt(*makeMotionKeys(sphere.objectToWorld, *sphere.objectToWorldAtClose), time);
    sphere.objectToWorldAtClose.reset();
    GpuScene still = packScene(posed);
    for (int i = 0; i < 1000; ++i) {
      glm::vec3 o = glm::vec3(u(rng), u(rng), u(rng)) * 5.0f;
      glm::vec3 target = glm::vec3(u(rng), u(rng) * 2.5f, u(rng));
      glm::vec3 d = glm::normalize(target - o);
      float a = hitDistance(g, o, d, time);
      float b = hitDistance(still, o, d, time);
      ++rays;
      hits += b >= 0.0f;
      mismatches += (a < 0.0f) != (b < 0.0f) || std::abs(a - b) > 1e-4f * std::max(1.0f, b);
      bool anyA = gpu::traceAny(sceneBuffers(g), g.topLevelEntry(), 0u, o, d, WP_FLT_MAX, time);
      mismatches += anyA != (b >= 0.0f);
    }
  }
  EXPECT_GT(hits, rays / 4);  // the rays aim at the objects
  EXPECT_LE(mismatches, rays / 1000) << mismatches << " of " << rays;
}

// A moving instance's emitters leave the light table (it holds triangles at one time);
// a still copy of the same mesh keeps its lights. Baking keeps movers as instances.
TEST(MotionPacking, MovingEmittersAreNotLightSampledAndMoversAreNotBaked) {
  std::mt19937 rng(5);
  Scene s;
  s.materials.resize(1);
  s.materials[0].emission = glm::vec3(1.0f);
  s.meshes.push_back(soup(rng, 4, 0));
  s.meshes.push_back(soup(rng, 3, 0));
  s.instances.push_back({0, glm::mat4(1.0f)});
  s.instances[0].objectToWorldAtClose = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0));
  s.instances.push_back({1, glm::mat4(1.0f)});
  Scene baked = bakeSingleUseMeshes(s);
  ASSERT_EQ(baked.instances.size(), 2u);
  EXPECT_TRUE(baked.instances[0].objectToWorldAtClose.has_value());
  GpuScene g = packScene(baked);
  EXPECT_EQ(g.lights.size(), 3u);
  for (uint32_t i = 0; i < g.placedInstances; ++i) {
    bool moves = g.instances[i].info.w != WP_INVALID;
    EXPECT_EQ(g.instances[i].info.z == WP_INVALID, moves) << "instance " << i;
  }
}

}  // namespace
}  // namespace wp
