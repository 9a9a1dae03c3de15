// Tests of the BVH builders, the GPU scene packer and the portable traversal (traverse.h
// compiled as C++) against brute force.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "bvh/bvh_refit.h"
#include "bvh/device_buffers.h"
#include "bvh/gpu_scene.h"
#include "bvh/scene_update.h"
#include "bvh/sweep_builder.h"
#include "bvh/wide_nodes.h"
#include "core/error.h"
#include "shaders/common/traverse.h"

namespace {

using wp::Aabb;
using wp::Bvh;
using wp::gpu::Hit;

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Rng {
  std::mt19937 engine;
  explicit Rng(uint32_t seed) : engine(seed) {}
  float uniform(float lo = 0.0f, float hi = 1.0f) {
    return std::uniform_real_distribution<float>(lo, hi)(engine);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
  glm::vec3 inBox(glm::vec3 lo, glm::vec3 hi) {
    return {uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z)};
  }
  glm::vec3 unitVector() {
    std::normal_distribution<float> n;
    glm::vec3 v;
    do {
      v = {n(engine), n(engine), n(engine)};
    } while (glm::dot(v, v) < 1e-6f);
    return glm::normalize(v);
  }
};

// ---- geometry generators --------------------------------------------------------------

using Triangles = std::vector<glm::vec3>;  // 3 vertices per triangle

// Random triangles in [-1, 1]^3 whose sizes span two orders of magnitude.
Triangles randomSoup(Rng& rng, int count) {
  Triangles t;
  for (int i = 0; i < count; ++i) {
    glm::vec3 c = rng.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
    float size = 0.005f * std::pow(100.0f, rng.uniform());
    for (int k = 0; k < 3; ++k) {
      t.push_back(c + size * rng.unitVector());
    }
  }
  return t;
}

// An n x n height field over [-1, 1]^2 in the xz plane, gently displaced.
Triangles gridMesh(int n) {
  Triangles t;
  auto p = [n](int i, int j) {
    float x = -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n);
    float z = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(n);
    return glm::vec3(x, 0.1f * std::sin(3.0f * x) * std::cos(2.0f * z), z);
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      t.insert(t.end(), {p(i, j), p(i + 1, j), p(i, j + 1), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)});
    }
  }
  return t;
}

// Small triangles gathered in a few tight, unevenly populated clusters.
Triangles clustered(Rng& rng, int count) {
  std::vector<glm::vec3> centers;
  for (int i = 0; i < 6; ++i) {
    centers.push_back(rng.inBox(glm::vec3(-1.0f), glm::vec3(1.0f)));
  }
  Triangles t;
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    int cluster = std::min(rng.integer(0, 15), 5) == 5 ? 5 : rng.integer(0, 4);
    glm::vec3 c = centers[cluster] + 0.05f * glm::vec3(n(rng.engine), n(rng.engine), n(rng.engine));
    for (int k = 0; k < 3; ++k) {
      t.push_back(c + 0.01f * rng.unitVector());
    }
  }
  return t;
}

struct Prims {
  std::vector<Aabb> bounds;
  std::vector<glm::vec3> centroids;
};

Prims primsOf(const Triangles& t) {
  Prims p;
  for (size_t i = 0; i < t.size(); i += 3) {
    Aabb b;
    b.grow(t[i]);
    b.grow(t[i + 1]);
    b.grow(t[i + 2]);
    p.bounds.push_back(b);
    p.centroids.push_back((t[i] + t[i + 1] + t[i + 2]) / 3.0f);
  }
  return p;
}

wp::Mesh meshOf(const Triangles& t, uint32_t material) {
  wp::Mesh m;
  for (size_t i = 0; i < t.size(); ++i) {
    m.positions.push_back(t[i]);
    m.indices.push_back(static_cast<uint32_t>(i));
  }
  m.materials.assign(t.size() / 3, material);
  return m;
}

glm::mat4 randomTransform(Rng& rng, float spread) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), rng.inBox(glm::vec3(-spread), glm::vec3(spread)));
  m = glm::rotate(m, rng.uniform(0.0f, 6.2831853f), rng.unitVector());
  return glm::scale(m, glm::vec3(rng.uniform(0.3f, 2.0f), rng.uniform(0.3f, 2.0f), rng.uniform(0.3f, 2.0f)));
}

// ---- structural checks ----------------------------------------------------------------

// Checks the tree invariants; returns the depth of the deepest leaf.
uint32_t checkTree(const Bvh& bvh, const Prims& p, const wp::BvhBuildOptions& options) {
  size_t n = p.bounds.size();
  if (n == 0) {
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.primIndices.empty());
    return 0;
  }
  EXPECT_EQ(bvh.primIndices.size(), n);
  std::vector<int> seenInOrder(n, 0), seenInLeaf(n, 0);
  for (uint32_t prim : bvh.primIndices) {
    EXPECT_LT(prim, n);
    if (prim < n) {
      ++seenInOrder[prim];
    }
  }
  uint32_t maxDepth = 0;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  size_t visited = 0;
  while (!stack.empty()) {
    auto [index, depth] = stack.back();
    stack.pop_back();
    ++visited;
    const Bvh::Node& node = bvh.nodes.at(index);
    maxDepth = std::max(maxDepth, depth);
    if (node.isLeaf()) {
      EXPECT_LE(node.count, options.maxLeafSize);
      for (uint32_t i = node.index; i < node.index + node.count; ++i) {
        uint32_t prim = bvh.primIndices.at(i);
        ++seenInLeaf[prim];
        EXPECT_TRUE(node.bounds.contains(p.bounds[prim])) << "leaf " << index << " prim " << prim;
      }
      continue;
    }
    for (uint32_t c = node.index; c < node.index + 2; ++c) {
      EXPECT_TRUE(node.bounds.contains(bvh.nodes.at(c).bounds)) << "node " << index << " child " << c;
      stack.emplace_back(c, depth + 1);
    }
  }
  EXPECT_EQ(visited, bvh.nodes.size()) << "unreachable nodes";
  for (size_t i = 0; i < n; ++i) {
    EXPECT_EQ(seenInOrder[i], 1) << "primitive " << i << " in primIndices";
    EXPECT_EQ(seenInLeaf[i], 1) << "primitive " << i << " in leaves";
  }
  EXPECT_LE(maxDepth, options.maxDepth);
  return maxDepth;
}

using BuildFn = std::function<Bvh(const Prims&, const wp::BvhBuildOptions&)>;
const BuildFn kBinned = [](const Prims& p, const wp::BvhBuildOptions& o) {
  return wp::buildBvh(p.bounds, p.centroids, o);
};
const BuildFn kSweep = [](const Prims& p, const wp::BvhBuildOptions& o) {
  return wp::buildBvhSweep(p.bounds, p.centroids, o);
};

TEST(BvhBuild, StructureOnRandomAndDegenerateInputs) {
  Rng rng(1);
  std::vector<Prims> inputs = {primsOf(randomSoup(rng, 3000)), primsOf(gridMesh(30)),
                               primsOf(clustered(rng, 2000)), Prims{}, primsOf(randomSoup(rng, 1))};
  Prims same;  // every centroid equal: only the median split can divide them
  for (int i = 0; i < 100; ++i) {
    Aabb b{glm::vec3(-1.0f - 0.01f * i), glm::vec3(1.0f + 0.01f * i)};
    same.bounds.push_back(b);
    same.centroids.push_back(glm::vec3(0.0f));
  }
  inputs.push_back(same);
  for (const BuildFn& build : {kBinned, kSweep}) {
    for (const Prims& p : inputs) {
      wp::BvhBuildOptions options;
      Bvh bvh = build(p, options);
      checkTree(bvh, p, options);
      if (p.bounds.size() == 1) {
        ASSERT_EQ(bvh.nodes.size(), 1u);
        EXPECT_EQ(bvh.nodes[0].count, 1u);
      }
    }
    Bvh sameTree = build(same, {});
    EXPECT_GT(sameTree.nodes.size(), 1u) << "equal centroids must still be split into small leaves";
  }
}

TEST(BvhBuild, DepthBudgetHoldsOnExponentialSpacing) {
  // Primitives at x = 2^i make the SAH peel one off per level; the budget must cut in.
  Prims p;
  for (int i = 0; i < 120; ++i) {
    float x = std::ldexp(1.0f, i - 60);
    p.bounds.push_back(Aabb{glm::vec3(x, 0.0f, 0.0f), glm::vec3(x * 1.5f, 1.0f, 1.0f)});
    p.centroids.push_back(p.bounds.back().center());
  }
  wp::BvhBuildOptions options;
  options.maxLeafSize = 1;
  options.maxDepth = 8;
  for (const BuildFn& build : {kBinned, kSweep}) {
    EXPECT_LE(checkTree(build(p, options), p, options), 8u);
  }
  options.maxDepth = 6;  // 120 > 2^6 leaves of one
  EXPECT_THROW(wp::buildBvh(p.bounds, p.centroids, options), wp::Error);
}

TEST(BvhBuild, ThreadCountDoesNotChangeTheTree) {
  Rng rng(2);
  Prims p = primsOf(randomSoup(rng, 50000));
  wp::BvhBuildOptions one, four;
  one.threads = 1;
  four.threads = 4;
  Bvh a = wp::buildBvh(p.bounds, p.centroids, one);
  Bvh b = wp::buildBvh(p.bounds, p.centroids, four);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(a.primIndices, b.primIndices);
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    ASSERT_EQ(a.nodes[i].index, b.nodes[i].index) << i;
    ASSERT_EQ(a.nodes[i].count, b.nodes[i].count) << i;
  }
}

TEST(BvhBuild, BinnedSahWithinTenPercentOfSweep) {
  Rng rng(3);
  struct Case {
    const char* name;
    Triangles triangles;
  };
  std::vector<Case> cases = {{"soup 2000", randomSoup(rng, 2000)},
                             {"soup 5000", randomSoup(rng, 5000)},
                             {"grid 40x40", gridMesh(40)},
                             {"clusters 4000", clustered(rng, 4000)}};
  for (const Case& c : cases) {
    Prims p = primsOf(c.triangles);
    float binned = wp::sahCost(wp::buildBvh(p.bounds, p.centroids));
    float sweep = wp::sahCost(wp::buildBvhSweep(p.bounds, p.centroids));
    std::printf("%-14s SAH binned %.3f, sweep %.3f, ratio %.4f\n", c.name, binned, sweep, binned / sweep);
    EXPECT_GT(sweep, 1.0f) << c.name;
    EXPECT_LE(binned, 1.10f * sweep) << c.name << ": binned " << binned << " sweep " << sweep;
  }
}

TEST(BvhBuild, SahCostOfHandBuiltTree) {
  // Root [0,2]^3 (area 24) with leaves [0,1]^3 (area 6, 1 prim) and [0,2]^3 (area 24, 2 prims).
  Bvh bvh;
  bvh.nodes = {{Aabb{glm::vec3(0.0f), glm::vec3(2.0f)}, 1, 0},
               {Aabb{glm::vec3(0.0f), glm::vec3(1.0f)}, 0, 1},
               {Aabb{glm::vec3(0.0f), glm::vec3(2.0f)}, 1, 2}};
  bvh.primIndices = {0, 1, 2};
  EXPECT_FLOAT_EQ(wp::sahCost(bvh, {1.0f, 1.0f}), 1.0f + 0.25f + 2.0f);
  EXPECT_FLOAT_EQ(wp::sahCost(bvh, {2.0f, 3.0f}), 2.0f + 0.75f + 6.0f);
  EXPECT_EQ(wp::sahCost(Bvh{}), 0.0f);
}

// ---- intersection routines ------------------------------------------------------------

TEST(Intersect, UnitSphereRoots) {
  using wp::gpu::intersectUnitSphere;
  EXPECT_FLOAT_EQ(intersectUnitSphere(glm::vec3(0, 0, -3), glm::vec3(0, 0, 1), kInf), 2.0f);
  // Inside: the far root; a direction of length 2 halves t.
  EXPECT_FLOAT_EQ(intersectUnitSphere(glm::vec3(0.0f), glm::vec3(0, 0, 2), kInf), 0.5f);
  EXPECT_EQ(intersectUnitSphere(glm::vec3(0, 0, -3), glm::vec3(0, 0, 1), 1.5f), 1.5f);
  EXPECT_EQ(intersectUnitSphere(glm::vec3(0, 2, -3), glm::vec3(0, 0, 1), kInf), kInf);
  EXPECT_EQ(intersectUnitSphere(glm::vec3(0, 0, 3), glm::vec3(0, 0, 1), 10.0f), 10.0f);
}

TEST(Intersect, TriangleBothFacesAndEdges) {
  using wp::gpu::intersectTriangle;
  glm::vec3 v0(0, 0, 0), e1(1, 0, 0), e2(0, 1, 0);
  EXPECT_FLOAT_EQ(intersectTriangle(glm::vec3(0.25f, 0.25f, 1), glm::vec3(0, 0, -1), v0, e1, e2, kInf), 1.0f);
  EXPECT_FLOAT_EQ(intersectTriangle(glm::vec3(0.25f, 0.25f, -2), glm::vec3(0, 0, 1), v0, e1, e2, kInf), 2.0f);
  EXPECT_EQ(intersectTriangle(glm::vec3(0.75f, 0.75f, 1), glm::vec3(0, 0, -1), v0, e1, e2, 5.0f), 5.0f);
  EXPECT_EQ(intersectTriangle(glm::vec3(0.25f, 0.25f, 1), glm::vec3(0, 0, 1), v0, e1, e2, 5.0f), 5.0f);
  EXPECT_EQ(intersectTriangle(glm::vec3(0.25f, 0.25f, 1), glm::vec3(0, 0, -1), v0, e1, e2, 1.0f), 1.0f);
  // In the triangle's plane, and a degenerate triangle: never a hit, never NaN.
  EXPECT_EQ(intersectTriangle(glm::vec3(-1, 0.25f, 0), glm::vec3(1, 0, 0), v0, e1, e2, 7.0f), 7.0f);
  EXPECT_EQ(intersectTriangle(glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), v0, e1, 2.0f * e1, 7.0f), 7.0f);
}

TEST(Intersect, PlaneAndSlabs) {
  using wp::gpu::intersectPlane;
  using wp::gpu::rayInverseDirection;
  glm::vec3 up(0, 1, 0);
  EXPECT_FLOAT_EQ(intersectPlane(up, -1.0f, glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), kInf), 2.0f);
  EXPECT_EQ(intersectPlane(up, -1.0f, glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), kInf), kInf);
  EXPECT_EQ(intersectPlane(up, 1.0f, glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), 3.0f), 3.0f);
  // The slab test (a wide node's, with the box in slot 0). Zero direction components: inside
  // the slab on those axes is a hit, outside a miss, no NaN.
  auto reaches = [](const Aabb& box, glm::vec3 origin, glm::vec3 invDir, float tMax) {
    wp::gpu::BvhNode node = wp::emptyWideNode();
    wp::setWideChild(node, 0, box, 0, 1);
    return wp::gpu::intersectChildren(node, origin, invDir, tMax).count == 1u;
  };
  Aabb box{glm::vec3(-1.0f), glm::vec3(1.0f)};
  glm::vec3 inv = rayInverseDirection(glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_TRUE(std::isfinite(inv.x) && std::isfinite(inv.y));
  EXPECT_TRUE(reaches(box, glm::vec3(0.5f, -0.5f, -5.0f), inv, kInf));
  // Entered at t = 4: reached with tMax just past 4, not with tMax just short of it.
  EXPECT_TRUE(reaches(box, glm::vec3(0.5f, -0.5f, -5.0f), inv, 4.0001f));
  EXPECT_FALSE(reaches(box, glm::vec3(0.5f, -0.5f, -5.0f), inv, 3.999f));
  EXPECT_FALSE(reaches(box, glm::vec3(1.5f, 0.0f, -5.0f), inv, kInf));
  EXPECT_FALSE(reaches(box, glm::vec3(0.0f, 0.0f, -5.0f), inv, 3.0f)) << "the box lies beyond tMax";
  EXPECT_FALSE(reaches(box, glm::vec3(0.0f, 0.0f, 5.0f), inv, kInf)) << "the box lies behind the origin";
}

// ---- packed scenes: traversal against brute force ---------------------------------------

Hit traceClosest(const wp::GpuScene& g, glm::vec3 o, glm::vec3 d, float tMax) {
  return wp::gpu::traceClosest(wp::sceneBuffers(g), g.topLevelEntry(), static_cast<uint32_t>(g.planes.size()), o, d,
                               tMax, 0.0f);
}

bool traceAny(const wp::GpuScene& g, glm::vec3 o, glm::vec3 d, float tMax) {
  return wp::gpu::traceAny(wp::sceneBuffers(g), g.topLevelEntry(), static_cast<uint32_t>(g.planes.size()), o, d, tMax,
                           0.0f);
}

// Every plane, every instance, every triangle, with the same object-space rays as traverse.h.
Hit bruteForce(const wp::GpuScene& g, glm::vec3 o, glm::vec3 d, float tMax) {
  Hit best{tMax, WP_INVALID, WP_INVALID};
  for (uint32_t i = 0; i < g.planes.size(); ++i) {
    glm::vec4 p = g.planes[i].normalDistance;
    float t = wp::gpu::intersectPlane(glm::vec3(p), p.w, o, d, tMax);
    if (t < best.t) {
      best = {t, i | WP_HIT_PLANE, WP_INVALID};
    }
  }
  for (uint32_t i = 0; i < g.instances.size(); ++i) {
    const wp::gpu::GpuInstance& inst = g.instances[i];
    glm::vec3 oo = wp::gpu::pointToObject(inst, o);
    glm::vec3 od = wp::gpu::directionToObject(inst, d);
    if (inst.info.x == WP_INSTANCE_SPHERE) {
      float t = wp::gpu::intersectUnitSphere(oo, od, tMax);
      if (t < best.t) {
        best = {t, i, WP_INVALID};
      }
      continue;
    }
    auto mesh = std::find_if(g.meshes.begin(), g.meshes.end(),
                             [&](const wp::GpuMeshRange& m) { return m.rootNode == inst.info.y; });
    EXPECT_NE(mesh, g.meshes.end());
    for (uint32_t j = mesh->firstTriangle; j < mesh->firstTriangle + mesh->triangleCount; ++j) {
      const wp::gpu::GpuTriangle& tri = g.triangles[j];
      float t = wp::gpu::intersectTriangle(oo, od, glm::vec3(tri.v0), glm::vec3(tri.edge1),
                                           glm::vec3(tri.edge2), tMax);
      if (t < best.t) {
        best = {t, i, j};
      }
    }
  }
  return best;
}

wp::Scene randomScene(Rng& rng) {
  wp::Scene s;
  s.materials.resize(3);
  s.materials[1].emission = glm::vec3(2.0f, 1.0f, 0.5f);
  s.meshes.push_back(meshOf(randomSoup(rng, 300), 0));
  s.meshes.push_back(meshOf(gridMesh(10), 1));
  s.meshes.push_back(meshOf(clustered(rng, 200), 2));
  s.meshes.push_back(meshOf(randomSoup(rng, 1), 0));  // a single leaf
  Triangles degenerate = {glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(2.0f),
                          glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  Triangles withDegenerate = randomSoup(rng, 40);
  withDegenerate.insert(withDegenerate.end(), degenerate.begin(), degenerate.end());
  s.meshes.push_back(meshOf(withDegenerate, 1));
  s.meshes.push_back(wp::Mesh{});  // no triangles: its instance is left out
  for (uint32_t mesh = 0; mesh < s.meshes.size(); ++mesh) {
    int copies = mesh == 5 ? 1 : rng.integer(1, 3);
    for (int i = 0; i < copies; ++i) {
      s.instances.push_back({mesh, randomTransform(rng, 3.0f)});
    }
  }
  for (int i = 0; i < 6; ++i) {
    s.spheres.push_back({randomTransform(rng, 4.0f), 2});
  }
  s.planes.push_back({glm::vec3(0, 1, 0), -9.0f, 0});
  s.planes.push_back({glm::normalize(glm::vec3(1, 0.2f, -0.5f)), 14.0f, 1});
  return s;
}

struct RayStats {
  int rays = 0, hits = 0, triangleHits = 0, sphereHits = 0, planeHits = 0, failures = 0, ties = 0;
};

glm::mat4 objectToWorld(const wp::gpu::GpuInstance& inst) {
  return glm::inverse(glm::transpose(
      glm::mat4(inst.worldToObject0, inst.worldToObject1, inst.worldToObject2, glm::vec4(0, 0, 0, 1))));
}

// A random world-space point on a random triangle of a random mesh instance.
glm::vec3 pointOnSomeTriangle(const wp::GpuScene& g, Rng& rng) {
  for (;;) {
    const wp::gpu::GpuInstance& inst = g.instances[rng.integer(0, static_cast<int>(g.instances.size()) - 1)];
    if (inst.info.x == WP_INSTANCE_SPHERE) {
      continue;
    }
    const wp::GpuMeshRange& mesh = *std::find_if(g.meshes.begin(), g.meshes.end(),
                                                 [&](const wp::GpuMeshRange& m) { return m.rootNode == inst.info.y; });
    const wp::gpu::GpuTriangle& tri =
        g.triangles[mesh.firstTriangle + rng.integer(0, static_cast<int>(mesh.triangleCount) - 1)];
    float u = rng.uniform(), v = rng.uniform();
    if (u + v > 1.0f) {
      u = 1.0f - u;
      v = 1.0f - v;
    }
    glm::vec3 p = glm::vec3(tri.v0) + u * glm::vec3(tri.edge1) + v * glm::vec3(tri.edge2);
    return glm::vec3(objectToWorld(inst) * glm::vec4(p, 1.0f));
  }
}

void compareRays(const wp::GpuScene& g, Rng& rng, int rayCount, RayStats& stats) {
  glm::vec3 lo = g.boundsMin, hi = g.boundsMax;
  glm::vec3 center = 0.5f * (lo + hi);
  float diagonal = glm::length(hi - lo);
  for (int r = 0; r < rayCount; ++r) {
    // Origins inside the bounds or outside them; half the rays aim at a triangle.
    glm::vec3 o = rng.uniform() < 0.5f ? rng.inBox(lo, hi) : center + diagonal * rng.unitVector();
    glm::vec3 target = rng.uniform() < 0.5f ? pointOnSomeTriangle(g, rng) : rng.inBox(lo, hi);
    glm::vec3 d = glm::normalize(target - o);
    float kind = rng.uniform();
    if (kind < 0.1f) {  // along an axis: two zero components
      d = glm::vec3(0.0f);
      d[rng.integer(0, 2)] = rng.uniform() < 0.5f ? -1.0f : 1.0f;
    } else if (kind < 0.2f) {  // one zero component
      d[rng.integer(0, 2)] = 0.0f;
      d = glm::normalize(d);
    } else if (kind < 0.3f) {  // not unit length: t is in units of the direction
      d *= rng.uniform(0.25f, 4.0f);
    }
    float limit = rng.uniform();
    float tMax = limit < 0.4f ? WP_FLT_MAX : (limit < 0.6f ? kInf : rng.uniform(0.01f, 1.5f) * diagonal);

    Hit ref = bruteForce(g, o, d, tMax);
    Hit got = traceClosest(g, o, d, tMax);
    ++stats.rays;
    bool ok = (ref.instance == WP_INVALID) == (got.instance == WP_INVALID);
    if (ok && ref.instance != WP_INVALID) {
      ++stats.hits;
      stats.planeHits += (ref.instance & WP_HIT_PLANE) != 0;
      stats.triangleHits += ref.primitive != WP_INVALID;
      stats.sphereHits += (ref.instance & WP_HIT_PLANE) == 0 && ref.primitive == WP_INVALID;
      ok = std::fabs(got.t - ref.t) <= 1e-5f * ref.t;
      if (ok && (got.instance != ref.instance || got.primitive != ref.primitive)) {
        ok = std::fabs(got.t - ref.t) <= 1e-6f * ref.t;  // a genuine tie
        stats.ties += ok;
      }
    }
    bool nearLimit = ref.instance != WP_INVALID && std::fabs(ref.t - tMax) <= 1e-4f * tMax;
    bool any = traceAny(g, o, d, tMax);
    if (!nearLimit && any != (ref.instance != WP_INVALID)) {
      ok = false;
    }
    if (!ok && ++stats.failures <= 10) {
      ADD_FAILURE() << "ray o=(" << o.x << "," << o.y << "," << o.z << ") d=(" << d.x << "," << d.y << ","
                    << d.z << ") tMax=" << tMax << ": brute force t=" << ref.t << " inst=" << ref.instance
                    << " prim=" << ref.primitive << ", traversal t=" << got.t << " inst=" << got.instance
                    << " prim=" << got.primitive << ", any=" << any;
    }
  }
}

TEST(Traversal, MatchesBruteForceOnRandomScenes) {
  RayStats stats;
  for (uint32_t seed = 10; seed < 14; ++seed) {
    Rng rng(seed);
    wp::GpuScene g = wp::packScene(randomScene(rng));
    compareRays(g, rng, 25000, stats);
  }
  std::printf("%d rays, %d hits (%d triangles, %d spheres, %d planes), %d ties\n", stats.rays, stats.hits,
              stats.triangleHits, stats.sphereHits, stats.planeHits, stats.ties);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_EQ(stats.rays, 100000);
  // The comparison only means something if every kind of hit and plenty of misses occur.
  EXPECT_GT(stats.hits, stats.rays / 4);
  EXPECT_LT(stats.hits, stats.rays * 9 / 10);
  EXPECT_GT(stats.triangleHits, stats.rays / 10);
  EXPECT_GT(stats.sphereHits, stats.rays / 100);
  EXPECT_GT(stats.planeHits, stats.rays / 100);
}

// A top level of one instance (placed off the origin, turned and scaled) is entered at the
// instance's leaf (GpuScene::topLevelEntry), not its root node: the same hits.
TEST(Traversal, MatchesBruteForceWhereTheTopLevelIsOneInstance) {
  RayStats stats;
  for (uint32_t seed = 20; seed < 22; ++seed) {
    Rng rng(seed);
    wp::Scene s;
    s.materials.resize(2);
    s.meshes.push_back(meshOf(clustered(rng, 400), 0));
    s.instances.push_back({0, randomTransform(rng, 3.0f)});
    s.planes.push_back({glm::vec3(0, 1, 0), -9.0f, 1});
    wp::GpuScene g = wp::packScene(s);
    ASSERT_EQ(g.topLevelEntry(), wp::gpu::packEntry(0u, 1u)) << "the instance's leaf";
    compareRays(g, rng, 20000, stats);
  }
  EXPECT_EQ(stats.failures, 0);
  EXPECT_GT(stats.triangleHits, stats.rays / 10);
  EXPECT_GT(stats.planeHits, stats.rays / 100);
  EXPECT_GT(stats.rays - stats.hits, stats.rays / 10) << "misses too";
}

TEST(Traversal, EmptyAndPlaneOnlyScenes) {
  wp::Scene s;
  s.materials.resize(1);
  wp::GpuScene empty = wp::packScene(s);
  ASSERT_EQ(empty.nodes.size(), 1u);
  EXPECT_EQ(empty.tlasRoot, 0u);
  EXPECT_EQ(empty.nodes[0].childIndex, glm::uvec4(WP_INVALID));
  EXPECT_EQ(empty.nodes[0].childCount, glm::uvec4(0u));
  EXPECT_EQ(traceClosest(empty, glm::vec3(0.0f), glm::vec3(0, 0, 1), WP_FLT_MAX).instance, WP_INVALID);
  EXPECT_FALSE(traceAny(empty, glm::vec3(0.0f), glm::vec3(0, 0, 1), WP_FLT_MAX));

  s.planes.push_back({glm::vec3(0, 1, 0), -1.0f, 0});
  wp::GpuScene plane = wp::packScene(s);
  Hit h = traceClosest(plane, glm::vec3(0.0f), glm::vec3(0, -1, 0), WP_FLT_MAX);
  EXPECT_EQ(h.instance, 0u | WP_HIT_PLANE);
  EXPECT_EQ(h.primitive, WP_INVALID);
  EXPECT_FLOAT_EQ(h.t, 1.0f);
  EXPECT_FALSE(traceAny(plane, glm::vec3(0.0f), glm::vec3(0, -1, 0), 0.5f));
}

TEST(Traversal, SingleTriangleMeshIsOneNodeWithThreeEmptySlots) {
  wp::Scene s;
  s.materials.resize(1);
  s.meshes.push_back(meshOf({glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}, 0));
  s.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -2))});
  wp::GpuScene g = wp::packScene(s);
  const wp::gpu::BvhNode& root = g.nodes[g.meshes[0].rootNode];
  EXPECT_EQ(root.childIndex, glm::uvec4(0u, WP_INVALID, WP_INVALID, WP_INVALID));
  EXPECT_EQ(root.childCount, glm::uvec4(1u, 0u, 0u, 0u));
  Hit h = traceClosest(g, glm::vec3(0.2f, 0.2f, 0.0f), glm::vec3(0, 0, -1), WP_FLT_MAX);
  EXPECT_FLOAT_EQ(h.t, 2.0f);
  EXPECT_EQ(h.instance, 0u);
  EXPECT_EQ(h.primitive, 0u);
}

// Triangles at x = 2^-i, each half the size of the one before: the SAH peels one off per
// level, so the tree is as deep as the build allows and its stacks as full as they get.
Triangles exponentialRow(int count) {
  Triangles t;
  for (int i = 0; i < count; ++i) {
    float x = std::ldexp(1.0f, -i);
    t.insert(t.end(), {glm::vec3(x, 0.0f, 0.0f), glm::vec3(1.5f * x, 1.0f, 0.0f), glm::vec3(x, 0.0f, 1.0f)});
  }
  return t;
}

TEST(Traversal, StacksHoldNoMoreThanTheirTreesNeed) {
  // traversalStackEntries is what Vulkan sizes the stacks in workgroup memory by: a ray that
  // pushed past it would overwrite another invocation's entries. The C++ traversal counts the
  // most entries each level held (prelude_cpp.h) over the random scenes' rays, and over a
  // scene of deep trees: an exponential row (as deep as the build allows) in 40 instances.
  std::vector<wp::GpuScene> scenes;
  for (uint32_t seed = 20; seed < 23; ++seed) {
    Rng rng(seed);
    scenes.push_back(wp::packScene(randomScene(rng)));
  }
  Rng rng(23);
  wp::Scene deep;
  deep.materials.resize(1);
  deep.meshes.push_back(meshOf(exponentialRow(48), 0));
  deep.meshes.push_back(meshOf(randomSoup(rng, 3000), 0));
  for (int i = 0; i < 40; ++i) deep.instances.push_back({uint32_t(i % 2), randomTransform(rng, 3.0f)});
  scenes.push_back(wp::packScene(deep));
  for (const wp::GpuScene& g : scenes) {
    const wp::TraversalStackNeeds needs = g.stackNeeds();
    wp::gpu::deepestStacks = {};
    for (int r = 0; r < 20000; ++r) {  // half of them at a triangle, so that they reach leaves
      glm::vec3 o = rng.inBox(g.boundsMin, g.boundsMax);
      glm::vec3 target = r % 2 ? pointOnSomeTriangle(g, rng) : rng.inBox(g.boundsMin, g.boundsMax);
      if (target == o) continue;
      traceClosest(g, o, glm::normalize(target - o), WP_FLT_MAX);
      traceAny(g, o, glm::normalize(target - o), WP_FLT_MAX);
    }
    EXPECT_LE(wp::gpu::deepestStacks.topLevelStack, needs.topLevel);
    EXPECT_LE(wp::gpu::deepestStacks.bottomLevelStack, needs.bottomLevel);
    // And the rays went deep enough for that to mean something (the most is for a ray that
    // enters every child of every node on a path: no ray need do that).
    EXPECT_GE(3 * wp::gpu::deepestStacks.bottomLevelStack, needs.bottomLevel);
    EXPECT_GE(3 * wp::gpu::deepestStacks.topLevelStack, needs.topLevel);
    std::printf("stacks: top level %u of %u, bottom level %u of %u entries\n", wp::gpu::deepestStacks.topLevelStack,
                needs.topLevel, wp::gpu::deepestStacks.bottomLevelStack, needs.bottomLevel);
  }
  // The deep scene needs more than any random one, and the invocations' own arrays hold it.
  EXPECT_GT(scenes.back().stackNeeds().bottomLevel, scenes.front().stackNeeds().bottomLevel);
  EXPECT_LE(scenes.back().stackNeeds().bottomLevel, WP_LEVEL_STACK_SIZE);
}

// ---- 4-wide nodes -----------------------------------------------------------------------

// Boxes along the ray's axis at known entry distances, in shuffled slots: the reached ones
// come nearest first, ties by slot, and the missed box and the empty slot after them.
TEST(WideBvh, ChildrenAreOrderedByEntryDistance) {
  auto boxAt = [](float z) { return Aabb{glm::vec3(-1.0f, -1.0f, z), glm::vec3(1.0f, 1.0f, z + 0.5f)}; };
  using wp::gpu::packEntry;
  glm::vec3 origin(0.0f), direction(0.0f, 0.0f, 1.0f);
  glm::vec3 invDir = wp::gpu::rayInverseDirection(direction);
  wp::gpu::BvhNode node = wp::emptyWideNode();
  wp::setWideChild(node, 0, boxAt(5.0f), 10, 0);
  wp::setWideChild(node, 1, boxAt(2.0f), 11, 3);
  wp::setWideChild(node, 2, Aabb{glm::vec3(4.0f), glm::vec3(5.0f)}, 12, 0);  // off the ray
  wp::setWideChild(node, 3, boxAt(3.0f), 13, 1);
  wp::gpu::ChildHits c = wp::gpu::intersectChildren(node, origin, invDir, 100.0f);
  EXPECT_EQ(c.count, 3u);
  EXPECT_EQ(c.nearestFirst, glm::uvec4(packEntry(11, 3), packEntry(13, 1), packEntry(10, 0), packEntry(12, 0)));
  // tMax in front of the farthest box leaves it out.
  c = wp::gpu::intersectChildren(node, origin, invDir, 4.0f);
  EXPECT_EQ(c.count, 2u);
  EXPECT_EQ(c.nearestFirst.x, packEntry(11, 3));
  EXPECT_EQ(c.nearestFirst.y, packEntry(13, 1));
  // Equal entry distances go by slot, also when the later slot comes first in the network's
  // pairs; an empty slot is never reached, whatever its bounds.
  wp::setWideChild(node, 3, boxAt(2.0f), 13, 1);
  wp::setWideChild(node, 2, boxAt(3.0f), 12, 0);
  wp::setWideChild(node, 1, boxAt(2.0f), 11, 3);
  wp::setWideChild(node, 0, boxAt(2.0f), WP_INVALID, 0);
  c = wp::gpu::intersectChildren(node, origin, invDir, 100.0f);
  EXPECT_EQ(c.count, 3u);
  EXPECT_EQ(c.nearestFirst.x, packEntry(11, 3));
  EXPECT_EQ(c.nearestFirst.y, packEntry(13, 1));
  EXPECT_EQ(c.nearestFirst.z, packEntry(12, 0));
  EXPECT_EQ(c.nearestFirst.w, packEntry(WP_INVALID, 0));
  // Four reached boxes in every order of their slots.
  std::array<uint32_t, 4> slotOfRank = {0, 1, 2, 3};
  do {
    for (uint32_t rank = 0; rank < 4; ++rank) {
      wp::setWideChild(node, slotOfRank[rank], boxAt(2.0f + float(rank)), 20 + rank, 0);
    }
    c = wp::gpu::intersectChildren(node, origin, invDir, 100.0f);
    EXPECT_EQ(c.count, 4u);
    EXPECT_EQ(c.nearestFirst, glm::uvec4(20, 21, 22, 23))
        << "slots by rank " << slotOfRank[0] << slotOfRank[1] << slotOfRank[2] << slotOfRank[3];
  } while (std::next_permutation(slotOfRank.begin(), slotOfRank.end()));
  // One reached box in each slot (where work-items are threads, as here, the network is
  // skipped for it): it comes first; none reached gives count 0.
  for (uint32_t reached = 0; reached < 4; ++reached) {
    for (uint32_t slot = 0; slot < 4; ++slot) {
      wp::setWideChild(node, slot, slot == reached ? boxAt(2.0f) : Aabb{glm::vec3(4.0f), glm::vec3(5.0f)}, 30 + slot,
                       slot);
    }
    c = wp::gpu::intersectChildren(node, origin, invDir, 100.0f);
    EXPECT_EQ(c.count, 1u);
    EXPECT_EQ(c.nearestFirst.x, packEntry(30 + reached, reached)) << "reached slot " << reached;
  }
  c = wp::gpu::intersectChildren(node, origin, invDir, 1.0f);
  EXPECT_EQ(c.count, 0u);
}

// The collapse keeps every leaf once, fills nodes while interior children are left to open,
// and has at most half the binary tree's interior nodes.
TEST(WideBvh, StackEntriesAreTheMostAPathLeavesWaitingPlusOne) {
  // A root of three leaves and node A; A of two leaves and nodes B and C; B of two leaves, C
  // of three. Under the root 3 entries wait, under A 3 + 3, under B 6 + 1 and under C 6 + 2:
  // 8 at most, and one for a leaf pushed back.
  auto nodeOf = [](std::vector<std::pair<uint32_t, uint32_t>> children) {  // (index, count)
    wp::gpu::BvhNode n = wp::emptyWideNode();
    for (uint32_t k = 0; k < children.size(); ++k) {
      wp::setWideChild(n, k, Aabb{glm::vec3(0.0f), glm::vec3(1.0f)}, children[k].first, children[k].second);
    }
    return n;
  };
  std::vector<wp::gpu::BvhNode> nodes = {
      nodeOf({{0, 1}, {1, 1}, {1, 0}, {2, 1}}),  // 0: root
      nodeOf({{3, 1}, {2, 0}, {4, 1}, {3, 0}}),  // 1: A
      nodeOf({{5, 1}, {6, 1}}),                  // 2: B
      nodeOf({{7, 1}, {8, 1}, {9, 1}}),          // 3: C
  };
  EXPECT_EQ(wp::traversalStackEntries(nodes, 0), 9u);
  EXPECT_EQ(wp::traversalStackEntries(nodes, 1), 6u);  // A alone: 3 under A, 5 under C
  EXPECT_EQ(wp::traversalStackEntries(nodes, 2), 2u);
  EXPECT_EQ(wp::traversalStackEntries({wp::emptyWideNode()}, 0), 1u);
}

TEST(WideBvh, CollapseKeepsEveryLeafOnceAndFillsNodes) {
  Rng rng(7);
  for (const Triangles& t : {gridMesh(30), clustered(rng, 2000), randomSoup(rng, 3000)}) {
    Prims p = primsOf(t);
    Bvh bvh = kBinned(p, {});
    wp::WideLayout wide = wp::collapseToWide(bvh);
    std::vector<int> leafSeen(bvh.nodes.size(), 0);
    size_t referenced = 0;
    for (const wp::WideLayout::Node& node : wide.nodes) {
      bool interiorLeft = false;
      for (uint32_t k = 0; k < node.count; ++k) {
        const Bvh::Node& child = bvh.nodes[node.children[k]];
        EXPECT_EQ(child.isLeaf(), node.wide[k] == WP_INVALID);
        if (child.isLeaf()) {
          ++leafSeen[node.children[k]];
        } else {
          interiorLeft = true;
          ++referenced;
          ASSERT_LT(node.wide[k], wide.nodes.size());
        }
      }
      EXPECT_TRUE(node.count == WP_BVH_WIDTH || !interiorLeft) << "a node with room kept an interior child";
    }
    EXPECT_EQ(referenced + 1, wide.nodes.size()) << "every wide node but the root is some node's child";
    size_t interior = 0;
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
      EXPECT_EQ(leafSeen[i], bvh.nodes[i].isLeaf() ? 1 : 0) << "binary node " << i;
      interior += !bvh.nodes[i].isLeaf();
    }
    EXPECT_LE(wide.nodes.size(), interior / 2 + 1);
  }
}

TEST(PackScene, GpuNodesCoverEveryTriangleOnceWithinChildBounds) {
  Rng rng(20);
  wp::Scene s = randomScene(rng);
  wp::GpuScene g = wp::packScene(s);
  EXPECT_EQ(g.triangleCount, g.triangles.size());
  for (const wp::GpuMeshRange& mesh : g.meshes) {
    std::vector<int> seen(mesh.triangleCount, 0);
    std::vector<uint32_t> stack{mesh.rootNode};
    while (!stack.empty()) {
      const wp::gpu::BvhNode& n = g.nodes.at(stack.back());
      stack.pop_back();
      for (int c = 0; c < 4; ++c) {
        uint32_t index = n.childIndex[c], count = n.childCount[c];
        glm::vec3 childMin(n.childMinX[c], n.childMinY[c], n.childMinZ[c]);
        glm::vec3 childMax(n.childMaxX[c], n.childMaxY[c], n.childMaxZ[c]);
        if (index == WP_INVALID) {
          EXPECT_EQ(count, 0u);
          continue;
        }
        if (count == 0) {
          EXPECT_LT(index, g.tlasRoot) << "bottom-level children stay below the top level";
          stack.push_back(index);
          continue;
        }
        for (uint32_t t = index; t < index + count; ++t) {
          ASSERT_GE(t, mesh.firstTriangle);
          ASSERT_LT(t, mesh.firstTriangle + mesh.triangleCount);
          ++seen[t - mesh.firstTriangle];
          const wp::gpu::GpuTriangle& tri = g.triangles[t];
          for (glm::vec3 v : {glm::vec3(tri.v0), glm::vec3(tri.v0 + tri.edge1), glm::vec3(tri.v0 + tri.edge2)}) {
            // Edges are stored relative to v0, so v0 + edge may round by an ulp.
            EXPECT_TRUE(glm::all(glm::lessThanEqual(childMin - 1e-6f, v)) &&
                        glm::all(glm::lessThanEqual(v, childMax + 1e-6f)));
          }
        }
      }
    }
    for (int count : seen) {
      EXPECT_EQ(count, 1);
    }
  }
  // Mesh 5 has no triangles and its instance is left out; the rest all appear.
  size_t expected = s.spheres.size();
  for (const wp::MeshInstance& inst : s.instances) {
    expected += !s.meshes[inst.mesh].indices.empty();
  }
  EXPECT_EQ(g.instances.size(), expected);
}

// ---- light table ------------------------------------------------------------------------

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TEST(PackScene, LightTableIsPowerProportionalWithAnExactAliasTable) {
  Rng rng(30);
  wp::Scene s;
  s.materials.resize(4);
  s.materials[1].emission = glm::vec3(5.0f, 4.0f, 3.0f);
  s.materials[2].emission = glm::vec3(0.1f, 0.0f, 0.0f);
  s.materials[2].doubleSided = true;
  s.materials[3].emission = glm::vec3(20.0f);
  wp::Mesh a = meshOf(randomSoup(rng, 300), 0);
  for (size_t t = 0; t < a.materials.size(); ++t) {
    a.materials[t] = static_cast<uint32_t>(t % 4);
  }
  // A degenerate emissive triangle: no light, no NaN.
  for (int k = 0; k < 3; ++k) {
    a.positions.push_back(glm::vec3(1.0f));
    a.indices.push_back(static_cast<uint32_t>(a.positions.size() - 1));
  }
  a.materials.push_back(3);
  s.meshes.push_back(a);
  s.meshes.push_back(meshOf(gridMesh(5), 2));
  for (int i = 0; i < 3; ++i) {
    s.instances.push_back({0, randomTransform(rng, 3.0f)});
    s.instances.push_back({1, randomTransform(rng, 3.0f)});
  }
  s.spheres.push_back({glm::mat4(1.0f), 1});
  wp::GpuScene g = wp::packScene(s);

  size_t emissivePerMesh0 = 300 / 4 * 3, emissivePerMesh1 = 50;
  ASSERT_EQ(g.lights.size(), 3 * (emissivePerMesh0 + emissivePerMesh1));
  size_t n = g.lights.size();
  double pmfSum = 0.0, powerSum = 0.0;
  std::vector<double> power(n), implied(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const wp::gpu::GpuLight& l = g.lights[i];
    ASSERT_TRUE(std::isfinite(l.v0.w) && l.v0.w > 0.0f);
    EXPECT_NEAR(l.v0.w, 0.5f * glm::length(glm::cross(glm::vec3(l.edge1), glm::vec3(l.edge2))), 1e-5f * l.v0.w);
    power[i] = luminance(glm::vec3(l.emission)) * l.v0.w * ((l.info.y & WP_LIGHT_DOUBLE_SIDED) ? 2.0 : 1.0);
    EXPECT_NEAR(l.emission.w, luminance(glm::vec3(l.emission)), 1e-6f * l.emission.w);  // untextured: the factor's
    EXPECT_EQ(l.info.w, WP_INVALID);
    powerSum += power[i];
    pmfSum += l.edge1.w;
    ASSERT_GE(l.edge2.w, 0.0f);
    ASSERT_LE(l.edge2.w, 1.0f);
    ASSERT_LT(l.info.x, n);
    implied[i] += l.edge2.w / static_cast<double>(n);
    implied[l.info.x] += (1.0 - l.edge2.w) / static_cast<double>(n);
  }
  EXPECT_NEAR(pmfSum, 1.0, 1e-5);
  for (size_t i = 0; i < n; ++i) {
    double expected = power[i] / powerSum;
    EXPECT_NEAR(g.lights[i].edge1.w, expected, 1e-5 * expected) << i;
    EXPECT_NEAR(implied[i], g.lights[i].edge1.w, 1e-6 / static_cast<double>(n) + 1e-5 * expected) << i;
  }

  // Each emissive triangle finds its world-space light at instance.info.z + triangle.info.y.
  size_t checked = 0;
  for (const wp::gpu::GpuInstance& inst : g.instances) {
    if (inst.info.x == WP_INSTANCE_SPHERE) {
      EXPECT_EQ(inst.info.z, WP_INVALID);
      continue;
    }
    const wp::GpuMeshRange& mesh =
        *std::find_if(g.meshes.begin(), g.meshes.end(), [&](const wp::GpuMeshRange& m) { return m.rootNode == inst.info.y; });
    glm::mat4 toWorld = objectToWorld(inst);
    for (uint32_t t = mesh.firstTriangle; t < mesh.firstTriangle + mesh.triangleCount; ++t) {
      const wp::gpu::GpuTriangle& tri = g.triangles[t];
      bool emissive = glm::length(glm::vec3(g.materials[tri.info.x].emission)) > 0.0f &&
                      glm::length(glm::cross(glm::vec3(tri.edge1), glm::vec3(tri.edge2))) > 0.0f;
      ASSERT_EQ(tri.info.y != WP_INVALID, emissive);
      if (!emissive) {
        continue;
      }
      const wp::gpu::GpuLight& l = g.lights.at(inst.info.z + tri.info.y);
      glm::vec3 v0 = glm::vec3(toWorld * glm::vec4(glm::vec3(tri.v0), 1.0f));
      EXPECT_NEAR(glm::length(v0 - glm::vec3(l.v0)), 0.0f, 1e-4f);
      EXPECT_EQ(glm::vec3(l.emission), glm::vec3(g.materials[tri.info.x].emission));
      EXPECT_EQ(l.info.y, g.materials[tri.info.x].emission.w > 0.5f ? WP_LIGHT_DOUBLE_SIDED : WP_LIGHT_TRIANGLE);
      EXPECT_EQ(l.info.z, t);  // its shading record
      ++checked;
    }
  }
  EXPECT_EQ(checked, n);
  // Emitter ordinals follow the mesh's original triangle order.
  const wp::GpuMeshRange& mesh0 = g.meshes[0];
  std::vector<uint32_t> ordinals;
  for (uint32_t t = mesh0.firstTriangle; t < mesh0.firstTriangle + mesh0.triangleCount; ++t) {
    if (g.triangles[t].info.y != WP_INVALID) {
      ordinals.push_back(g.triangles[t].info.y);
    }
  }
  std::sort(ordinals.begin(), ordinals.end());
  for (size_t i = 0; i < ordinals.size(); ++i) {
    ASSERT_EQ(ordinals[i], i);
  }
}

// An emissive texture weighs each triangle by its mean emission over its uv footprint: a
// 2x1 nearest texture, white then black (sRGB), under two triangles over the white texel,
// one straddling both (a quarter of its area over the black one) and one over the black
// texel, which keeps a thousandth of its factor's weight so that light sampling can still
// find it. Lights name their shading record and texture.
TEST(PackScene, EmissiveTextureWeighsLightsByTheirMeanEmission) {
  wp::Scene s;
  s.materials.resize(1);
  s.materials[0].emission = glm::vec3(2.0f);
  s.materials[0].emissiveTexture = 0;
  wp::Texture texture;
  texture.width = 2;
  texture.height = 1;
  texture.rgba = {0xffffffffu, 0xff000000u};
  texture.nearest = true;
  texture.srgb = true;
  s.textures = {texture};
  wp::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {0.5f, 0, 0}, {0.5f, 1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  for (const glm::vec3& p : mesh.positions) mesh.uvs.push_back(glm::vec2(p));  // uv = (x, y)
  mesh.indices = {0, 1, 2, 0, 2, 3, 0, 4, 5, 6, 7, 8};
  mesh.materials = {0, 0, 0, 0};
  s.meshes = {mesh};
  s.instances = {{0, glm::mat4(1.0f)}};
  wp::GpuScene g = wp::packScene(s);
  ASSERT_EQ(g.lights.size(), 4u);
  // The straddling triangle's estimate is exact: its sub-triangles (4 per edge) do not cross
  // u = 0.5. Everything else is exact too, so 1e-5 covers float rounding.
  const double expectedMean[] = {1.0, 1.0, 0.75, 1e-3};
  double total = 0.0;
  for (size_t i = 0; i < 4; ++i) total += expectedMean[i] * g.lights[i].v0.w;  // times the area
  for (size_t i = 0; i < 4; ++i) {
    const wp::gpu::GpuLight& l = g.lights[i];
    double pmf = expectedMean[i] * l.v0.w / total;
    EXPECT_NEAR(l.emission.w, 2.0 * expectedMean[i], 1e-5) << i;
    EXPECT_NEAR(l.edge1.w, pmf, 1e-5 * pmf) << i;
    EXPECT_EQ(glm::vec3(l.emission), glm::vec3(2.0f));
    EXPECT_EQ(l.info.w, 0u);
    EXPECT_EQ(glm::vec3(g.triangles.at(l.info.z).v0), glm::vec3(l.v0)) << i;
  }
}

TEST(PackScene, MaterialsPlanesAndSingularInstances) {
  wp::Scene s;
  s.materials.resize(2);
  s.materials[0].baseColor = glm::vec3(0.1f, 0.2f, 0.3f);
  s.materials[0].alpha = 0.5f;
  s.materials[1].emission = glm::vec3(1.0f, 2.0f, 3.0f);
  s.materials[1].doubleSided = true;
  s.planes.push_back({glm::vec3(0, 0, 1), 2.0f, 1});
  s.spheres.push_back({glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f)), 0});  // singular
  s.spheres.push_back({glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)), 1});
  wp::GpuScene g = wp::packScene(s);
  ASSERT_EQ(g.materials.size(), 2u);
  EXPECT_EQ(g.materials[0].baseColor, glm::vec4(0.1f, 0.2f, 0.3f, 0.5f));
  EXPECT_EQ(g.materials[1].emission, glm::vec4(1.0f, 2.0f, 3.0f, 1.0f));
  EXPECT_EQ(g.materials[0].emission.w, 0.0f);
  ASSERT_EQ(g.planes.size(), 1u);
  EXPECT_EQ(g.planes[0].normalDistance, glm::vec4(0, 0, 1, 2));
  EXPECT_EQ(g.planes[0].info.x, 1u);
  ASSERT_EQ(g.instances.size(), 1u);
  // No lights of its own (z), and no motion keys (w): it stands still.
  EXPECT_EQ(g.instances[0].info, glm::uvec4(WP_INSTANCE_SPHERE, 1u, WP_INVALID, WP_INVALID));
  EXPECT_EQ(g.boundsMin, glm::vec3(-2.0f));
  EXPECT_EQ(g.boundsMax, glm::vec3(2.0f));
}

// ---- refit and the per-frame scene update ------------------------------------------------

// A travelling wave plus a swirl about +y that turns points near the axis further than the
// rim: neighbours stay neighbours, but boxes grouped for t = 0 shear and stretch as t grows,
// as under a skinned twist.
glm::vec3 deformed(glm::vec3 p, float t) {
  float angle = 2.0f * t * std::max(0.0f, 1.2f - glm::length(glm::vec2(p.x, p.z)));
  float c = std::cos(angle), s = std::sin(angle);
  glm::vec3 q(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
  q.y += 0.15f * std::sin(4.0f * p.x - 6.0f * t) * std::cos(3.0f * p.z);
  return q;
}

wp::Mesh deformedMesh(const wp::Mesh& rest, float t) {
  wp::Mesh m = rest;
  for (glm::vec3& p : m.positions) {
    p = deformed(p, t);
  }
  return m;
}

// A deforming wave grid (mesh 0, placed twice and moving), then static meshes and spheres, so
// that a bottom-level rebuild that changes mesh 0's node count moves every later block.
struct AnimatedScene {
  wp::Scene rest;
  std::vector<glm::mat4> start;  // the instances' transforms at t = 0

  explicit AnimatedScene(Rng& rng) {
    rest.materials.resize(3);
    rest.materials[1].emission = glm::vec3(2.0f, 1.0f, 0.5f);
    wp::Mesh grid = meshOf(gridMesh(24), 1);  // emissive: the lights move with the pose
    grid.deforming = true;
    rest.meshes.push_back(grid);
    rest.meshes.push_back(meshOf(randomSoup(rng, 300), 0));
    rest.meshes.push_back(meshOf(clustered(rng, 200), 2));
    for (uint32_t mesh : {0u, 0u, 1u, 2u, 1u}) {
      rest.instances.push_back({mesh, randomTransform(rng, 3.0f), mesh == 0});
    }
    for (int i = 0; i < 4; ++i) {
      rest.spheres.push_back({randomTransform(rng, 4.0f), 2});
    }
    rest.planes.push_back({glm::vec3(0, 1, 0), -9.0f, 0});
    for (const wp::MeshInstance& inst : rest.instances) {
      start.push_back(inst.objectToWorld);
    }
  }

  // The pose at time t: mesh 0 deformed, its instances and the first sphere moving.
  wp::Scene at(float t) const {
    wp::Scene s = rest;
    s.meshes[0] = deformedMesh(rest.meshes[0], t);
    glm::mat4 motion = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * t, 0.0f, -t)), t,
                                   glm::vec3(0.0f, 1.0f, 0.0f));
    for (size_t i = 0; i < s.instances.size(); ++i) {
      if (s.instances[i].animated) {
        s.instances[i].objectToWorld = motion * start[i];
      }
    }
    s.spheres[0].objectToWorld = motion * rest.spheres[0].objectToWorld;
    return s;
  }
};

TEST(Refit, TreeStaysValidAndRefitsBackToTheBuildExactly) {
  wp::Mesh rest = meshOf(gridMesh(40), 0);
  Prims start = primsOf(rest.positions);
  wp::BvhBuildOptions options;
  Bvh built = wp::buildBvh(start.bounds, start.centroids, options);
  Bvh bvh = built;
  for (float t : {0.3f, 0.7f, 1.0f}) {
    Prims moved = primsOf(deformedMesh(rest, t).positions);
    wp::refitBvh(bvh, moved.bounds);
    checkTree(bvh, moved, options);  // every leaf holds its triangles, every parent its children
  }
  // Bounds are a function of the positions alone: back at t = 0 the boxes are the built ones.
  wp::refitBvh(bvh, start.bounds);
  ASSERT_EQ(bvh.nodes.size(), built.nodes.size());
  for (size_t i = 0; i < bvh.nodes.size(); ++i) {
    EXPECT_EQ(bvh.nodes[i].bounds.min, built.nodes[i].bounds.min) << "node " << i;
    EXPECT_EQ(bvh.nodes[i].bounds.max, built.nodes[i].bounds.max) << "node " << i;
  }
  EXPECT_THROW(wp::refitBvh(bvh, std::span(start.bounds).first(10)), wp::Error);
}

// Refit only (no rebuild) to poses along the animation: closest-hit and any-hit traversal of
// the refitted scene against brute force, as for packed scenes.
TEST(Refit, TraversalMatchesBruteForceAfterDeformation) {
  Rng rng(40);
  AnimatedScene anim(rng);
  wp::SceneUpdater updater(anim.at(0.0f), std::numeric_limits<float>::infinity());
  RayStats stats;
  for (float t : {0.25f, 0.5f, 1.0f}) {
    const wp::GpuScene& g = updater.update(anim.at(t));
    EXPECT_EQ(updater.times().refits, 1u);
    EXPECT_EQ(updater.times().rebuilds, 0u);
    compareRays(g, rng, 20000, stats);
  }
  std::printf("%d rays, %d hits (%d triangles), %d ties\n", stats.rays, stats.hits, stats.triangleHits,
              stats.ties);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_GT(stats.triangleHits, stats.rays / 10);  // the comparison must see triangles
  EXPECT_GT(updater.sahGrowth(0), 1.0f) << "the swirl must have stretched the refitted boxes";
}

bool sameBytes(const auto& a, const auto& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

size_t meshWithRoot(const wp::GpuScene& g, uint32_t root) {
  return std::find_if(g.meshes.begin(), g.meshes.end(), [&](const wp::GpuMeshRange& m) { return m.rootNode == root; }) -
         g.meshes.begin();
}

// The updater against packScene of the same pose, refitting only and rebuilding at every
// growth (ratio 1, which also re-lays out the static meshes' nodes behind mesh 0).
TEST(SceneUpdater, MatchesPackSceneOfThePose) {
  for (float ratio : {std::numeric_limits<float>::infinity(), 1.0f}) {
    Rng rng(41);
    AnimatedScene anim(rng);
    wp::SceneUpdater updater(anim.at(0.0f), ratio);
    uint32_t rebuilds = 0;
    int failures = 0, hits = 0;
    const uint32_t staticRoot = updater.scene().meshes[1].rootNode;
    bool relaidOut = false;
    for (float t : {0.1f, 0.5f, 0.9f}) {
      wp::Scene posed = anim.at(t);
      const wp::GpuScene& got = updater.update(posed);
      rebuilds += updater.times().rebuilds;
      relaidOut = relaidOut || got.meshes[1].rootNode != staticRoot;
      wp::GpuScene want = wp::packScene(posed);
      // The top level is built from the same boxes, so instances and lights agree bit for bit
      // (up to the mesh roots in the instance records when a rebuild moved them).
      ASSERT_EQ(got.instances.size(), want.instances.size());
      for (size_t i = 0; i < got.instances.size(); ++i) {
        wp::gpu::GpuInstance a = got.instances[i], b = want.instances[i];
        if (a.info.x == WP_INSTANCE_MESH) {
          EXPECT_EQ(meshWithRoot(got, a.info.y), meshWithRoot(want, b.info.y)) << "instance " << i;
          a.info.y = b.info.y = 0;
        }
        EXPECT_TRUE(sameBytes(std::vector{a}, std::vector{b})) << "instance " << i << " at t=" << t;
      }
      // Lights agree bit for bit too, up to the index of their triangle record (info.z), which
      // a refitted tree places elsewhere: that record must be the same triangle.
      ASSERT_EQ(got.lights.size(), want.lights.size());
      EXPECT_GT(got.lights.size(), 0u);
      for (size_t l = 0; l < got.lights.size(); ++l) {
        wp::gpu::GpuLight a = got.lights[l], b = want.lights[l];
        EXPECT_TRUE(sameBytes(std::vector{got.triangles[a.info.z]}, std::vector{want.triangles[b.info.z]}))
            << "light " << l << " at t=" << t;
        a.info.z = b.info.z = 0;
        EXPECT_TRUE(sameBytes(std::vector{a}, std::vector{b})) << "light " << l << " at t=" << t;
      }
      EXPECT_EQ(got.boundsMin, want.boundsMin);
      EXPECT_EQ(got.boundsMax, want.boundsMax);
      EXPECT_EQ(got.sky.intensity, want.sky.intensity);
      EXPECT_EQ(got.sky.rotation, want.sky.rotation);
      EXPECT_EQ(got.sky.selectionProbability, want.sky.selectionProbability);
      EXPECT_EQ(got.triangles.size(), want.triangles.size());
      for (size_t m = 1; m < got.meshes.size(); ++m) {  // static meshes keep their triangles
        EXPECT_TRUE(std::equal(got.triangles.begin() + got.meshes[m].firstTriangle,
                               got.triangles.begin() + got.meshes[m].firstTriangle + got.meshes[m].triangleCount,
                               want.triangles.begin() + want.meshes[m].firstTriangle, [](auto& x, auto& y) {
                                 return sameBytes(std::vector{x}, std::vector{y});
                               }));
      }
      // The deforming mesh holds the same triangle and shading records in another order.
      auto recordsOfMesh0 = [](const wp::GpuScene& g, const auto& records) {
        auto first = records.begin() + g.meshes[0].firstTriangle;
        std::vector sorted(first, first + g.meshes[0].triangleCount);
        std::sort(sorted.begin(), sorted.end(),
                  [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof(x)) < 0; });
        return sorted;
      };
      EXPECT_TRUE(sameBytes(recordsOfMesh0(got, got.triangles), recordsOfMesh0(want, want.triangles)));
      EXPECT_TRUE(sameBytes(recordsOfMesh0(got, got.triangleShading), recordsOfMesh0(want, want.triangleShading)));
      // Same hits: the same triangle records under the same transforms give the same t, bit
      // for bit, unless two surfaces tie (then either may win).
      for (int r = 0; r < 5000; ++r) {
        glm::vec3 o = rng.inBox(want.boundsMin, want.boundsMax);
        glm::vec3 d = glm::normalize(pointOnSomeTriangle(want, rng) - o);
        Hit a = traceClosest(got, o, d, WP_FLT_MAX), b = traceClosest(want, o, d, WP_FLT_MAX);
        hits += b.instance != WP_INVALID;
        bool same = a.t == b.t;
        if (a.primitive != WP_INVALID && b.primitive != WP_INVALID && a.instance == b.instance) {
          same = same && sameBytes(std::vector{got.triangles[a.primitive]}, std::vector{want.triangles[b.primitive]});
        }
        same = same && traceAny(got, o, d, WP_FLT_MAX) == traceAny(want, o, d, WP_FLT_MAX);
        if (!same && ++failures <= 5) {
          ADD_FAILURE() << "t=" << t << " ray " << r << ": updater t=" << a.t << " inst=" << a.instance
                        << ", packScene t=" << b.t << " inst=" << b.instance;
        }
      }
    }
    EXPECT_EQ(failures, 0) << "ratio " << ratio;
    EXPECT_GT(hits, 3 * 5000 / 2);
    EXPECT_EQ(rebuilds > 0, ratio == 1.0f) << "ratio " << ratio;
    // A rebuild of mesh 0 with another node count must have moved the static meshes' nodes.
    EXPECT_EQ(relaidOut, ratio == 1.0f) << "ratio " << ratio;
  }
}

TEST(SceneUpdater, RebuildsOnceSahGrowthPassesTheThreshold) {
  Rng rng(42);
  wp::Scene s;
  s.materials.resize(1);
  s.meshes.push_back(meshOf(clustered(rng, 2000), 0));
  s.meshes[0].deforming = true;
  s.instances.push_back({0, glm::mat4(1.0f)});
  wp::SceneUpdater updater(s);

  // A small jitter keeps the grouping good: refit only.
  wp::Scene jittered = s;
  for (glm::vec3& p : jittered.meshes[0].positions) {
    p += 0.002f * rng.unitVector();
  }
  updater.update(jittered);
  EXPECT_EQ(updater.times().rebuilds, 0u);
  EXPECT_LT(updater.sahGrowth(0), wp::kRebuildSahRatio);

  // Shuffling the triangles far apart ruins it: the tree is rebuilt, and is then the tree
  // packScene builds for the pose (the build is deterministic).
  wp::Scene shuffled = s;
  std::vector<glm::vec3>& p = shuffled.meshes[0].positions;
  for (size_t t = 0; t < p.size(); t += 3) {
    glm::vec3 offset = rng.inBox(glm::vec3(-5.0f), glm::vec3(5.0f)) - p[t];
    for (size_t k = t; k < t + 3; ++k) {
      p[k] += offset;
    }
  }
  const wp::GpuScene& g = updater.update(shuffled);
  EXPECT_EQ(updater.times().rebuilds, 1u);
  EXPECT_EQ(updater.sahGrowth(0), 1.0f);
  EXPECT_EQ(g.sahCost, wp::packScene(shuffled).sahCost);

  wp::Scene fewer = s;
  fewer.meshes[0].indices.resize(3);
  EXPECT_THROW(updater.update(fewer), wp::Error);
}

// The SAH cost of refitted trees against fresh builds over 100 frames of the deforming grid:
// refitting only, and rebuilding past each candidate threshold (printed for docs/animation.md, where
// kRebuildSahRatio is chosen from it).
TEST(Refit, SahCostOfRefitVersusRebuildOver100Frames) {
  constexpr int kFrames = 100;
  wp::Scene s;
  s.materials.resize(1);
  wp::Mesh rest = meshOf(gridMesh(100), 0);  // 20k triangles
  rest.deforming = true;
  s.meshes.push_back(rest);
  s.instances.push_back({0, glm::mat4(1.0f)});
  auto pose = [&](int frame) {
    wp::Scene posed = s;
    posed.meshes[0] = deformedMesh(rest, static_cast<float>(frame) / (kFrames - 1));
    return posed;
  };
  std::vector<double> rebuilt;
  for (int frame = 0; frame < kFrames; ++frame) {
    rebuilt.push_back(wp::packScene(pose(frame)).sahCost);
  }

  std::printf("refit only: frame, t, SAH refitted, its growth since the build, SAH rebuilt, refitted/rebuilt\n");
  const float kNever = std::numeric_limits<float>::infinity();
  uint32_t previousRebuilds = 0;
  double previousSum = std::numeric_limits<double>::infinity();
  for (float threshold : {kNever, 1.5f, 1.3f, 1.2f, 1.1f}) {
    wp::SceneUpdater updater(pose(0), threshold);
    EXPECT_EQ(updater.scene().sahCost, rebuilt[0]);  // the first pose is built, not refitted
    uint32_t rebuilds = 0;
    double sumRatio = 0.0, maxRatio = 0.0;
    for (int frame = 1; frame < kFrames; ++frame) {
      double sah = updater.update(pose(frame)).sahCost;
      rebuilds += updater.times().rebuilds;
      double ratio = sah / rebuilt[frame];
      sumRatio += ratio;
      maxRatio = std::max(maxRatio, ratio);
      if (threshold == kNever && (frame % 11 == 0 || frame == kFrames - 1)) {
        std::printf("%5d  %4.2f  %6.2f  %5.3f  %6.2f  %5.3f\n", frame, frame / (kFrames - 1.0), sah,
                    updater.sahGrowth(0), rebuilt[frame], ratio);
      }
      // Binned SAH is not optimal, so a refitted tree may beat a fresh build a little, but not
      // by much: 10% is the binned builder's own bound against the full sweep (BvhBuild tests).
      EXPECT_GT(ratio, 0.9) << "frame " << frame;
    }
    std::printf("threshold %4.1f: %2u rebuilds in %d frames, refitted/rebuilt SAH mean %5.3f max %5.3f\n",
                threshold, rebuilds, kFrames - 1, sumRatio / (kFrames - 1), maxRatio);
    // Lower thresholds rebuild more often and keep the trees closer to fresh builds. (They
    // bound the growth since the last build, which includes the deformation's own change of
    // cost, so they do not bound refitted/rebuilt exactly.)
    if (threshold == kNever) {
      EXPECT_EQ(rebuilds, 0u);
      EXPECT_GT(maxRatio, 1.2) << "the deformation must degrade the refitted tree";
    } else {
      EXPECT_GE(rebuilds, previousRebuilds) << "threshold " << threshold;
      EXPECT_LT(sumRatio, previousSum) << "threshold " << threshold;
    }
    previousRebuilds = rebuilds;
    previousSum = sumRatio;
  }
  EXPECT_GT(previousRebuilds, 0u);
}

}  // namespace
