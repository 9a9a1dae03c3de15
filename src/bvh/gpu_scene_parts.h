// The pieces of packScene that the per-frame SceneUpdater repeats for a new pose: mesh
// primitives, bottom-level builds, node and triangle records, and the instance level.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/gpu_scene.h"

namespace wp::pack_detail {

// One mesh's triangles as the bottom-level build and the light table see them.
struct MeshPrimitives {
  std::vector<Aabb> bounds;  // per triangle, object space
  std::vector<glm::vec3> centroids;
  std::vector<uint32_t> emitters;  // original indices of its emissive non-degenerate triangles
  std::vector<uint32_t> ordinal;   // per triangle: its index in `emitters`, or WP_INVALID
};

// What the instance level needs of each packed mesh.
struct PackedMesh {
  Aabb bounds;                     // object space
  std::vector<uint32_t> emitters;  // as in MeshPrimitives
  float sah = 0.0f;                // sahCost of its bottom level
  Bvh bvh;  // kept by packSceneParts for deforming meshes only (refitted per frame)
};

// Requires valid material indices (as packScene).
MeshPrimitives meshPrimitives(const Scene& scene, const Mesh& mesh);

// The bottom-level build: leaves of at most WP_MAX_LEAF_TRIANGLES, depth WP_BVH_MAX_DEPTH.
Bvh buildMeshBvh(const MeshPrimitives& prims);

// GPU nodes that writeNodes fills for `bvh`: its interior nodes, or one for a single leaf
// (or none).
uint32_t gpuNodeCount(const Bvh& bvh);

// Writes `bvh` in the GPU layout to out[base, base + gpuNodeCount(bvh)), leaf ranges offset
// by primBase and child indices absolute. Requires out.size() >= base + gpuNodeCount(bvh).
void writeNodes(const Bvh& bvh, uint32_t primBase, uint32_t base, std::vector<gpu::BvhNode>& out);

// Writes the triangle and shading records of `mesh` in the leaf order of `bvh` (built over
// prims of this mesh) to out.triangles and out.triangleShading from firstTriangle on.
// Requires both arrays to hold firstTriangle + mesh.triangleCount() records.
void writeTriangles(const Mesh& mesh, const Bvh& bvh, const MeshPrimitives& prims, uint32_t firstTriangle,
                    GpuScene& out);

// Wall time of the instance level's parts.
struct InstanceLevelSeconds {
  double tlas = 0.0;    // instance bounds, top-level build, its nodes
  double lights = 0.0;  // instance records, world-space lights, alias table, sky choice
};

// Appends the top-level BVH to out.nodes and replaces out.instances, out.lights, the world
// bounds and the sky's selection probability for the transforms of `scene`. Requires
// out.meshes, out.sky and `meshes` (one per scene mesh) to describe the packed bottom levels.
InstanceLevelSeconds packInstances(const Scene& scene, std::span<const PackedMesh> meshes, GpuScene& out);

// packScene, also returning each mesh's PackedMesh (with its tree for deforming meshes).
GpuScene packSceneParts(const Scene& scene, std::vector<PackedMesh>& meshes);

}  // namespace wp::pack_detail
