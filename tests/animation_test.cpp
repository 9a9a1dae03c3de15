// glTF animation: sampling against the specification's formulas (Appendix C), and the
// loader's node channels, morph targets and skins posed at known times.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/animation.h"
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"
#include "support/run_wavepath.h"

namespace wp {
namespace {

// Keyframes are stored as float, so values agree to float rounding of numbers near 1-20.
constexpr float kFloatTolerance = 1e-5f;

AnimationSampler sampler(Interpolation interpolation, std::vector<float> input, std::vector<float> output,
                         size_t width) {
  return {std::move(input), std::move(output), width, interpolation};
}

void expectNear(const std::vector<float>& actual, const std::vector<double>& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

TEST(AnimationSampling, LinearInterpolatesBetweenKeyframes) {
  const AnimationSampler s = sampler(Interpolation::Linear, {1, 3}, {0, 10, -2, 4, 20, 2}, 3);
  expectNear(sampleValues(s, 2.0), {2, 15, 0}, kFloatTolerance);
  expectNear(sampleValues(s, 1.5), {1, 12.5, -1}, kFloatTolerance);  // a quarter of the way
}

TEST(AnimationSampling, StepHoldsThePreviousKeyframe) {
  const AnimationSampler s = sampler(Interpolation::Step, {1, 3, 4}, {5, 7, 9}, 1);
  expectNear(sampleValues(s, 2.999), {5}, 0.0);
  expectNear(sampleValues(s, 3.0), {7}, 0.0);
  expectNear(sampleValues(s, 3.5), {7}, 0.0);
}

TEST(AnimationSampling, ClampsBeforeTheFirstAndAfterTheLastKeyframe) {
  const AnimationSampler linear = sampler(Interpolation::Linear, {1, 3}, {4, 8}, 1);
  expectNear(sampleValues(linear, -5.0), {4}, 0.0);
  expectNear(sampleValues(linear, 10.0), {8}, 0.0);
  // CUBICSPLINE clamps to the value, never to a tangent beside it.
  const AnimationSampler cubic = sampler(Interpolation::CubicSpline, {1, 3}, {100, 4, 200, 300, 8, 400}, 1);
  expectNear(sampleValues(cubic, 0.0), {4}, 0.0);
  expectNear(sampleValues(cubic, 3.5), {8}, 0.0);
}

TEST(AnimationSampling, CubicSplineIsTheHermiteSplineWithTangentsScaledByTheInterval) {
  const double t0 = 1.0;
  const double t1 = 3.0;  // an interval of 2 s, so unscaled tangents would be off by 2x
  const glm::dvec2 a0(9, 9), p0(1, -2), b0(0.5, 3), a1(-4, 1), p1(6, 2), b1(7, 7);
  const AnimationSampler s = sampler(Interpolation::CubicSpline, {float(t0), float(t1)},
                                     {float(a0.x), float(a0.y), float(p0.x), float(p0.y), float(b0.x), float(b0.y),
                                      float(a1.x), float(a1.y), float(p1.x), float(p1.y), float(b1.x), float(b1.y)},
                                     2);
  for (double t : {1.0, 1.6, 2.0, 2.9}) {
    const double u = (t - t0) / (t1 - t0);
    const double dt = t1 - t0;
    // glTF 2.0 Appendix C: p(u) = (2u^3 - 3u^2 + 1) p0 + (u^3 - 2u^2 + u) dt b0
    //                             + (-2u^3 + 3u^2) p1 + (u^3 - u^2) dt a1
    const glm::dvec2 expected = (2 * u * u * u - 3 * u * u + 1) * p0 + (u * u * u - 2 * u * u + u) * dt * b0 +
                                (-2 * u * u * u + 3 * u * u) * p1 + (u * u * u - u * u) * dt * a1;
    expectNear(sampleValues(s, t), {expected.x, expected.y}, 1e-4);  // float keyframes, values up to ~10
  }
}

std::vector<float> xyzw(const glm::dquat& q) { return {float(q.x), float(q.y), float(q.z), float(q.w)}; }

glm::dquat axisAngle(double degrees, glm::dvec3 axis) {
  return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

void expectSameRotation(const glm::dquat& actual, const glm::dquat& expected) {
  // q and -q are the same rotation; float keyframes give about 1e-7 per component.
  EXPECT_NEAR(std::abs(glm::dot(actual, expected)), 1.0, 1e-6) << "angle between them too large";
  EXPECT_NEAR(glm::length(actual), 1.0, 1e-9);
}

TEST(AnimationSampling, LinearRotationIsSlerpAlongTheShorterArc) {
  const glm::dquat q0 = axisAngle(20, {1, 2, 3});
  const glm::dquat q1 = axisAngle(100, {1, 2, 3});
  std::vector<float> output = xyzw(q0);
  for (float v : xyzw(q1)) output.push_back(v);
  const AnimationSampler s = sampler(Interpolation::Linear, {0, 1}, output, 4);
  // About one axis, slerp turns the angle at a constant rate: 20 + 0.25 * 80 degrees.
  expectSameRotation(sampleRotation(s, 0.25), axisAngle(40, {1, 2, 3}));

  // The end written as -q1 (the same rotation) must not send the interpolation the long way.
  std::vector<float> negated = xyzw(q0);
  for (float v : xyzw(-q1)) negated.push_back(v);
  const AnimationSampler flipped = sampler(Interpolation::Linear, {0, 1}, negated, 4);
  expectSameRotation(sampleRotation(flipped, 0.25), axisAngle(40, {1, 2, 3}));
}

TEST(AnimationSampling, SlerpOfDifferentAxesMatchesTheClosedForm) {
  const glm::dquat q0 = axisAngle(30, {0, 0, 1});
  const glm::dquat q1 = axisAngle(70, {1, 0, 0});
  std::vector<float> output = xyzw(q0);
  for (float v : xyzw(q1)) output.push_back(v);
  const AnimationSampler s = sampler(Interpolation::Linear, {2, 4}, output, 4);
  const double u = 0.35;
  // slerp(q0, q1, u) = sin((1 - u) theta) / sin(theta) q0 + sin(u theta) / sin(theta) q1, cos(theta) = q0 . q1 > 0
  const double theta = std::acos(glm::dot(q0, q1));
  const glm::dquat expected =
      q0 * (std::sin((1 - u) * theta) / std::sin(theta)) + q1 * (std::sin(u * theta) / std::sin(theta));
  expectSameRotation(sampleRotation(s, 2 + u * 2), expected);
}

TEST(AnimationSampling, CubicSplineRotationIsNormalised) {
  const glm::dquat q0 = axisAngle(0, {0, 1, 0});
  const glm::dquat q1 = axisAngle(90, {0, 1, 0});
  std::vector<float> output(4, 0.0f);  // in-tangent 0
  for (float v : xyzw(q0)) output.push_back(v);
  for (int i = 0; i < 8; ++i) output.push_back(0.0f);  // out-tangent of 0 and in-tangent of 1
  for (float v : xyzw(q1)) output.push_back(v);
  for (int i = 0; i < 4; ++i) output.push_back(0.0f);
  const AnimationSampler s = sampler(Interpolation::CubicSpline, {0, 1}, output, 4);
  // With zero tangents and u = 0.5 the spline is the plain average of the two quaternions,
  // which normalised is the 45 degree rotation.
  expectSameRotation(sampleRotation(s, 0.5), axisAngle(45, {0, 1, 0}));
}

std::filesystem::path data(const char* name) { return test::sourceDirectory() / "tests" / "data" / name; }

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

void expectVec3(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kFloatTolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(AnimatedScene, NodeChannelsMoveInstancesSpheresAndTheCamera) {
  const Scene scene = loadScene(data("anim_trs.gltf"));
  ASSERT_TRUE(scene.animation);
  EXPECT_DOUBLE_EQ(scene.animation->duration, 2.0);
  ASSERT_EQ(scene.instances.size(), 4u);  // mover, its child, spinner, static, in walk order
  EXPECT_TRUE(scene.instances[0].animated);
  EXPECT_TRUE(scene.instances[1].animated) << "an animated parent moves its child";
  EXPECT_TRUE(scene.instances[2].animated);
  EXPECT_FALSE(scene.instances[3].animated);
  for (const Mesh& mesh : scene.meshes) EXPECT_FALSE(mesh.deforming);

  const Scene half = poseScene(scene, 0.5);
  ASSERT_EQ(half.instances.size(), scene.instances.size());
  ASSERT_EQ(half.meshes.size(), scene.meshes.size());
  expectVec3(origin(half.instances[0].objectToWorld), {1, 0, 0});   // halfway from 0 to 2
  expectVec3(origin(half.instances[1].objectToWorld), {1, 0, -1});  // the parent's move plus its own offset
  expectVec3(origin(half.instances[3].objectToWorld), {5, 0, 0});
  // Sphere: radius 0.5 times the CUBICSPLINE scale p0 = 1, b0 = 1, p1 = 2, a1 = -1 at u = 0.5:
  // 0.5 * 1 + 0.125 * 1 + 0.5 * 2 - 0.125 * -1 = 1.75.
  EXPECT_NEAR(glm::length(glm::vec3(half.spheres[0].objectToWorld[0])), 0.5f * 1.75f, kFloatTolerance);
  expectVec3(origin(half.spheres[0].objectToWorld), {0, 3, 0});
  expectVec3(half.camera.position, {0, 0, 5});  // STEP holds the first keyframe until t = 1
  expectVec3(poseScene(scene, 1.0).camera.position, {0, 1, 5});

  // The spinner turns 120 degrees about +y over 2 s (its last keyframe written as -q), so
  // at 1 s its +x axis has turned 60 degrees towards -z.
  const glm::vec3 x = glm::vec3(poseScene(scene, 1.0).instances[2].objectToWorld * glm::vec4(1, 0, 0, 0));
  const float angle = std::numbers::pi_v<float> / 3;
  expectVec3(x, {std::cos(angle), 0, -std::sin(angle)});

  // Without a time: the rest pose of the file.
  expectVec3(origin(poseScene(scene, std::nullopt).instances[0].objectToWorld), {0, 0, 0});
}

TEST(AnimatedScene, AShutterIntervalGivesMovingObjectsTheirTransformAtClose) {
  const Scene scene = loadScene(data("anim_trs.gltf"));
  const Scene blurred = poseSceneOverShutter(scene, 0.5, 0.25);
  const Scene open = poseScene(scene, 0.5);
  const Scene close = poseScene(scene, 0.75);
  // The mover, its child and the spinner move between 0.5 and 0.75 s; the static one does not.
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(blurred.instances[i].objectToWorld, open.instances[i].objectToWorld) << i;
    ASSERT_TRUE(blurred.instances[i].objectToWorldAtClose) << i;
    EXPECT_EQ(*blurred.instances[i].objectToWorldAtClose, close.instances[i].objectToWorld) << i;
  }
  EXPECT_FALSE(blurred.instances[3].objectToWorldAtClose);
  ASSERT_TRUE(blurred.spheres[0].objectToWorldAtClose);  // its scale grows
  EXPECT_EQ(*blurred.spheres[0].objectToWorldAtClose, close.spheres[0].objectToWorld);
  // A closed shutter is an instant.
  for (const MeshInstance& instance : poseSceneOverShutter(scene, 0.5, 0.0).instances) {
    EXPECT_FALSE(instance.objectToWorldAtClose);
  }
}

TEST(AnimatedScene, MorphTargetsBlendPositionsAndNormalsByNodeAndMeshWeights) {
  const Scene scene = loadScene(data("anim_morph.gltf"));
  // Each node gets its own copy of the mesh, since each has its own weights.
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_TRUE(scene.meshes[0].deforming);
  EXPECT_TRUE(scene.meshes[1].deforming);
  // Loaded: the mesh's default weights (0.5, 0) on node 0, the node's own (0, 1) on node 1.
  expectVec3(scene.meshes[0].positions[0], {0, 0, 0.5f});
  expectVec3(scene.meshes[0].normals[0], glm::normalize(glm::vec3(0.5f, 0, 1)));
  expectVec3(scene.meshes[1].positions[1], {2, 0, 0});

  // The weights go (0, 0) -> (1, 1) over 2 s: (0.5, 0.5) at 1 s.
  const Scene posed = poseScene(scene, 1.0);
  expectVec3(posed.meshes[0].positions[0], {0, 0, 0.5f});
  expectVec3(posed.meshes[0].positions[1], {1.5f, 0, 0});
  expectVec3(posed.meshes[0].positions[2], {0, 1, 0});
  expectVec3(poseScene(scene, 2.0).meshes[0].positions[1], {2, 0, 0});
  expectVec3(posed.meshes[1].positions[1], {2, 0, 0});  // node 1 has no channel
}

TEST(AnimatedScene, SkinningBlendsTheJointsAndIgnoresTheMeshNodesTransform) {
  const Scene scene = loadScene(data("anim_skin.gltf"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_TRUE(scene.meshes[0].deforming);
  const std::vector<glm::vec3> rest = scene.meshes[0].positions;
  for (size_t v = 0; v < rest.size(); ++v) {
    EXPECT_LE(rest[v].x, 2.0f) << "the mesh node's translation by 10 must not move a skinned mesh";
  }
  for (double t : {0.5, 1.0}) {
    const Scene posed = poseScene(scene, t);
    EXPECT_EQ(posed.instances[0].objectToWorld, glm::mat4(1.0f));
    // The elbow at x = 1 turns 90 * t degrees about +z; vertices at x = 2 follow it, those
    // at x = 1 are half on the elbow and half on the still root joint.
    const glm::mat4 elbow = glm::rotate(glm::mat4(1.0f), float(t * std::numbers::pi / 2), glm::vec3(0, 0, 1));
    for (size_t v = 0; v < rest.size(); ++v) {
      const glm::vec3 p = rest[v];
      const glm::vec3 turned = glm::vec3(1, 0, 0) + glm::vec3(elbow * glm::vec4(p - glm::vec3(1, 0, 0), 1.0f));
      const float onElbow = p.x == 0.0f ? 0.0f : p.x == 1.0f ? 0.5f : 1.0f;
      expectVec3(posed.meshes[0].positions[v], (1 - onElbow) * p + onElbow * turned);
    }
  }
}

TEST(MeshDeformation, SkinningTurnsTangentsAndFlipsTheBitangentSignUnderAMirror) {
  MeshDeformation d;
  d.restPositions = {glm::vec3(1, 0, 0)};
  d.restNormals = {glm::vec3(0, 0, 1)};
  d.restTangents = {glm::vec4(1, 0, 0, 1)};
  d.joints = {glm::uvec4(0)};
  d.jointWeights = {glm::vec4(1, 0, 0, 0)};
  Mesh mesh;
  // A quarter turn about +z takes the tangent +x to +y and keeps the bitangent's side.
  deformMesh(d, {}, {glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1))}, mesh);
  ASSERT_EQ(mesh.tangents.size(), 1u);
  expectVec3(glm::vec3(mesh.tangents[0]), {0, 1, 0});
  EXPECT_EQ(mesh.tangents[0].w, 1.0f);
  // A mirror in x reverses the tangent and, since cross(n, t) no longer follows the mirrored
  // bitangent, its sign.
  deformMesh(d, {}, {glm::scale(glm::mat4(1.0f), glm::vec3(-2, 1, 1))}, mesh);
  expectVec3(glm::vec3(mesh.tangents[0]), {-1, 0, 0});
  EXPECT_EQ(mesh.tangents[0].w, -1.0f);
}

}  // namespace
}  // namespace wp
