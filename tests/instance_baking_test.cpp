// Baking single-use meshes into world space changes the BVH layout, never what a ray hits.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "bvh/device_buffers.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "shaders/common/surface.h"
#include "shaders/common/traverse.h"

namespace wp {
namespace {

Mesh randomMesh(std::mt19937& rng, int triangles, uint32_t material) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Mesh mesh;
  for (int t = 0; t < triangles; ++t) {
    glm::vec3 c(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) {
      mesh.positions.push_back(c + 0.3f * glm::vec3(u(rng), u(rng), u(rng)));
      mesh.indices.push_back(uint32_t(mesh.positions.size() - 1));
    }
    mesh.materials.push_back(material);
  }
  return mesh;
}

// A mesh placed once (rotated), a mesh placed twice, a mirrored mesh placed once.
Scene testScene() {
  std::mt19937 rng(5);
  Scene scene;
  scene.materials.resize(3);
  scene.meshes = {randomMesh(rng, 50, 0), randomMesh(rng, 40, 1), randomMesh(rng, 30, 2)};
  glm::mat4 rotated = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)), 0.7f, glm::vec3(0, 1, 1));
  glm::mat4 mirrored = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 2, 0)), glm::vec3(-1, 1, 1));
  scene.instances = {{0, rotated},
                     {1, glm::translate(glm::mat4(1.0f), glm::vec3(-2, 0, 0))},
                     {1, glm::translate(glm::mat4(1.0f), glm::vec3(0, -2, 0))},
                     {2, mirrored}};
  return scene;
}

// Vertex normals go through the inverse transpose (a non-uniform scale tilts them the other
// way than positions), stay unit length, and a mesh without normals placed before one with
// gets zeros (flat) for its vertices.
TEST(InstanceBaking, TransformsVertexNormalsWithTheInverseTranspose) {
  Scene scene;
  scene.materials.resize(1);
  Mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.indices = {0, 1, 2};
  flat.materials = {0};
  Mesh smooth = flat;
  smooth.normals = {glm::normalize(glm::vec3(1, 1, 0)), {0, 0, 1}, {0, 0, 0}};
  scene.meshes = {flat, smooth};
  glm::mat4 stretch = glm::scale(glm::mat4(1.0f), glm::vec3(2, 1, 1));
  scene.instances = {{0, glm::mat4(1.0f)}, {1, stretch}};
  Scene baked = bakeSingleUseMeshes(scene);
  ASSERT_EQ(baked.meshes.size(), 1u);
  const std::vector<glm::vec3>& normals = baked.meshes[0].normals;
  ASSERT_EQ(normals.size(), 6u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(normals[i], glm::vec3(0.0f));
  glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 1.0f, 0.0f));
  EXPECT_NEAR(glm::length(normals[3] - expected), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(normals[4] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_EQ(normals[5], glm::vec3(0.0f));
}

// Random triangles, each with a random unit vertex normal and tangent (not along its uv
// gradient) at all three corners, bitangent signs +1 and -1 alternating, and uvs.
Mesh randomTangentMesh(std::mt19937& rng, int triangles) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Mesh mesh = randomMesh(rng, triangles, 0);
  for (int t = 0; t < triangles; ++t) {
    glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    glm::vec3 tangent = glm::normalize(glm::cross(n, glm::vec3(u(rng), u(rng), u(rng))));
    for (int k = 0; k < 3; ++k) {
      mesh.normals.push_back(n);
      mesh.tangents.push_back(glm::vec4(tangent, t % 2 ? -1.0f : 1.0f));
      mesh.uvs.push_back(glm::vec2(u(rng), u(rng)));
    }
  }
  return mesh;
}

// The normal-mapping frame at a hit, as normalMapped (integrator.h) orthogonalizes it.
// The closest hit of a ray in `g` (no planes, at shutter time 0).
gpu::Hit traceClosest(const GpuScene& g, glm::vec3 origin, glm::vec3 direction) {
  return gpu::traceClosest(sceneBuffers(g), g.topLevelEntry(), 0u, origin, direction, WP_FLT_MAX, 0.0f);
}

struct TangentFrame {
  glm::vec3 normal, tangent, bitangent;
};

TangentFrame frameAt(const GpuScene& g, const gpu::Hit& hit, glm::vec3 position) {
  gpu::SurfaceHit s = gpu::surfaceAt(sceneBuffers(g), hit.instance, hit.primitive, position, 0.0f);
  glm::vec3 n = s.shadingNormal;
  glm::vec3 t = glm::normalize(s.tangent - n * glm::dot(n, s.tangent));
  glm::vec3 b = s.bitangent - n * glm::dot(n, s.bitangent) - t * glm::dot(t, s.bitangent);
  return {n, t, glm::normalize(b)};
}

// Baked tangents take the transform itself, and a mirroring transform flips their
// bitangent sign: the shading frame at every hit is the one the instance's transform gives
// the mesh's own frame (tangent M t, bitangent M (w cross(n, t)) as surfaceAt computes it
// for instances), for a mirrored and a sheared, rotated placement. (Without the flip every
// bitangent on the mirrored mesh comes out reversed.)
TEST(InstanceBaking, TransformsTangentsAndFlipsTheSignWhenMirrored) {
  std::mt19937 rng(7);
  Scene scene;
  scene.materials.resize(1);
  scene.meshes = {randomTangentMesh(rng, 40), randomTangentMesh(rng, 40)};
  glm::mat4 mirrored = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)), glm::vec3(-1.5f, 1, 0.5f));
  glm::mat4 sheared = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-2, 0, 0)), 0.7f, glm::vec3(0, 1, 1)) *
                      glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0.6f, 1, 0, 0), glm::vec4(0, 0, 2, 0), glm::vec4(0, 0, 0, 1));
  scene.instances = {{0, mirrored}, {1, sheared}};
  Scene bakedScene = bakeSingleUseMeshes(scene);
  ASSERT_EQ(bakedScene.meshes.size(), 1u);
  const std::vector<glm::vec4>& tangents = bakedScene.meshes[0].tangents;
  ASSERT_EQ(tangents.size(), 240u);
  for (size_t v = 0; v < 120; ++v) {
    glm::vec4 t = scene.meshes[0].tangents[v];
    glm::vec3 expected = glm::normalize(glm::mat3(mirrored) * glm::vec3(t));
    EXPECT_NEAR(glm::length(glm::vec3(tangents[v]) - expected), 0.0f, 1e-5f) << v;
    EXPECT_EQ(tangents[v].w, -t.w) << v;                               // mirrored: flipped
    EXPECT_EQ(tangents[120 + v].w, scene.meshes[1].tangents[v].w) << v;  // det > 0: kept
  }

  GpuScene instanced = packScene(scene);
  GpuScene baked = packScene(bakedScene);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    glm::vec3 origin(3.0f * u(rng), 3.0f, 1.5f * u(rng));
    glm::vec3 direction = glm::normalize(glm::vec3(u(rng), -1.5f, u(rng)));
    auto trace = [&](const GpuScene& g) { return traceClosest(g, origin, direction); };
    gpu::Hit a = trace(instanced);
    gpu::Hit b = trace(baked);
    ASSERT_EQ(a.instance == WP_INVALID, b.instance == WP_INVALID) << "ray " << i;
    if (a.instance == WP_INVALID) {
      continue;
    }
    ++hits;
    TangentFrame fa = frameAt(instanced, a, origin + direction * a.t);
    TangentFrame fb = frameAt(baked, b, origin + direction * b.t);
    // Float rounding of the baked vertices and a recomputed hit point: 1e-3 in direction.
    EXPECT_GT(glm::dot(fa.normal, fb.normal), 0.999f) << "ray " << i;
    EXPECT_GT(glm::dot(fa.tangent, fb.tangent), 0.999f) << "ray " << i;
    EXPECT_GT(glm::dot(fa.bitangent, fb.bitangent), 0.999f) << "ray " << i;
  }
  EXPECT_GT(hits, 500);
}

TEST(InstanceBaking, MergesSingleUseMeshesAndKeepsSharedOnesInstanced) {
  Scene baked = bakeSingleUseMeshes(testScene());
  ASSERT_EQ(baked.meshes.size(), 2u);
  ASSERT_EQ(baked.instances.size(), 3u);
  EXPECT_EQ(baked.meshes[0].triangleCount(), 40u);  // the shared mesh
  EXPECT_EQ(baked.meshes[1].triangleCount(), 80u);  // the two single-use meshes
  EXPECT_EQ(baked.instances[2].objectToWorld, glm::mat4(1.0f));
}

TEST(InstanceBaking, AnimatedInstancesAndDeformingMeshesStayApart) {
  Scene scene = testScene();
  scene.instances[0].animated = true;  // mesh 0 moves rigidly
  scene.meshes[2].deforming = true;    // mesh 2's vertices move
  Scene baked = bakeSingleUseMeshes(scene);
  ASSERT_EQ(baked.meshes.size(), 3u);  // nothing left to bake: no merged mesh
  ASSERT_EQ(baked.instances.size(), 4u);
  EXPECT_TRUE(baked.instances[0].animated);
  EXPECT_EQ(baked.instances[0].objectToWorld, scene.instances[0].objectToWorld);
  EXPECT_EQ(baked.meshes[baked.instances[0].mesh].triangleCount(), 50u);
  EXPECT_TRUE(baked.meshes[baked.instances[3].mesh].deforming);
}

TEST(InstanceBaking, MirroredMeshKeepsItsFrontFace) {
  Scene scene = testScene();
  Scene baked = bakeSingleUseMeshes(scene);
  const Mesh& original = scene.meshes[2];
  const Mesh& merged = baked.meshes[1];
  glm::mat4 m = scene.instances[3].objectToWorld;
  glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
  size_t offset = 50;  // mesh 0's triangles come first
  for (size_t t = 0; t < original.triangleCount(); ++t) {
    auto corner = [](const Mesh& mesh, size_t tri, int k) { return mesh.positions[mesh.indices[3 * tri + k]]; };
    glm::vec3 n = glm::cross(corner(original, t, 1) - corner(original, t, 0), corner(original, t, 2) - corner(original, t, 0));
    glm::vec3 expected = glm::normalize(normalMatrix * n);
    size_t w = offset + t;
    glm::vec3 world = glm::normalize(
        glm::cross(corner(merged, w, 1) - corner(merged, w, 0), corner(merged, w, 2) - corner(merged, w, 0)));
    EXPECT_GT(glm::dot(world, expected), 0.999f) << "triangle " << t;
  }
}

TEST(InstanceBaking, RaysHitTheSameSurfacesBeforeAndAfter) {
  Scene scene = testScene();
  GpuScene instanced = packScene(scene);
  GpuScene baked = packScene(bakeSingleUseMeshes(scene));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    glm::vec3 origin(4.0f * u(rng), 4.0f * u(rng), 4.0f * u(rng));
    glm::vec3 direction = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    auto trace = [&](const GpuScene& g) { return traceClosest(g, origin, direction); };
    gpu::Hit a = trace(instanced);
    gpu::Hit b = trace(baked);
    ASSERT_EQ(a.instance == WP_INVALID, b.instance == WP_INVALID) << "ray " << i;
    if (a.instance == WP_INVALID) {
      continue;
    }
    ++hits;
    EXPECT_NEAR(a.t, b.t, 1e-4f * a.t) << "ray " << i;
    EXPECT_EQ(instanced.triangles[a.primitive].info.x, baked.triangles[b.primitive].info.x) << "material, ray " << i;
  }
  EXPECT_GT(hits, 500);  // enough hits for the comparison to mean something
}

}  // namespace
}  // namespace wp
