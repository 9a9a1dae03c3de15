// The pieces of packScene that the per-frame SceneUpdater repeats for a new pose: mesh
// primitives, bottom-level builds, node and triangle records, and the instance level.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/gpu_scene.h"
#include "bvh/wide_nodes.h"

namespace wp::pack_detail {

// An emissive non-degenerate triangle of a mesh, as the light table sees it.
struct Emitter {
  uint32_t triangle = 0;  // index in the mesh
  uint32_t packed = 0;    // index in GpuScene::triangles (and triangleShading); set by writeTriangles
  float weight = 0.0f;    // luminance of its mean emitted radiance (GpuLight::emission.w); set by writeTriangles
};

// One mesh's triangles as the bottom-level build and the light table see them.
struct MeshPrimitives {
  std::vector<Aabb> bounds;  // per triangle, object space
  std::vector<glm::vec3> centroids;
  std::vector<Emitter> emitters;  // its emissive non-degenerate triangles in the mesh's order
  std::vector<uint32_t> ordinal;  // per triangle: its index in `emitters`, or WP_INVALID
};

// What the instance level needs of each packed mesh.
struct PackedMesh {
  Aabb bounds;                     // object space
  std::vector<Emitter> emitters;  // as in MeshPrimitives, after writeTriangles
  float sah = 0.0f;                // sahCost of its bottom level
  Bvh bvh;  // kept by packSceneParts for deforming meshes only (refitted per frame)
  WideLayout wide;  // the GPU nodes' shape over bvh, kept with it
};

// Requires valid material indices (as packScene).
MeshPrimitives meshPrimitives(const Scene& scene, const Mesh& mesh);

// The bottom-level build: leaves of at most WP_MAX_LEAF_TRIANGLES, depth WP_BVH_MAX_DEPTH.
Bvh buildMeshBvh(const MeshPrimitives& prims);

// Writes the triangle and shading records of `mesh` (of `scene`) in the leaf order of `bvh`
// (built over prims of this mesh) to out.triangles and out.triangleShading from firstTriangle
// on, and sets each of prims.emitters' record index and light-selection weight (its mean
// emission, textures included). Requires both arrays to hold firstTriangle +
// mesh.triangleCount() records, and out.textures and out.texels packed.
void writeTriangles(const Scene& scene, const Mesh& mesh, const Bvh& bvh, MeshPrimitives& prims,
                    uint32_t firstTriangle, GpuScene& out);

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
