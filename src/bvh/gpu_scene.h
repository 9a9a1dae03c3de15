// Packs a wp::Scene into the GPU buffers of layout.h: BVH nodes, triangles, instances,
// planes, materials and the light table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shaders/common/layout.h"

namespace wp {

// Where one scene mesh lives in the packed arrays.
struct GpuMeshRange {
  uint32_t rootNode = 0;       // its bottom-level BVH root in GpuScene::nodes
  uint32_t firstTriangle = 0;  // its triangles are [firstTriangle, firstTriangle + triangleCount)
  uint32_t triangleCount = 0;
};

// What a scene uses of the stages' code. Vulkan compiles each feature's code only into the
// stages of scenes that have it (specialization constants, prelude_glsl.h), since lavapipe
// pays for code that never runs (docs/performance.md); C++ and OpenCL keep all of it. The
// material features count the materials some surface (triangle, sphere, plane) has.
struct SceneFeatures {
  bool alphaTested = false;   // a triangle's material is MASK or BLEND (traverse.h)
  bool layered = false;       // a material has a clear coat or a sheen (material.h)
  bool transmissive = false;  // a material has transmission: glass (material.h)
  bool microfacet = false;    // a material is glTF's BRDF, not ideal diffuse or unlit (bsdf.h)
  bool metallic = false;      // a material has metalness: glTF's metal lobe (material.h)
  bool emissive = false;      // a material emits (materialEmits): emission at hits, triangle lights
  bool skySampled = false;    // next event estimation samples the sky (sky.selectionProbability > 0)
  bool diffuse = false;       // a material is ideal diffuse or unlit (materialShadeNeeds 0)
  // The top level's root is a node, not the leaf of a single instance (GpuScene::topLevelEntry,
  // traverse.h): most scenes without instancing hold one instance, every mesh placed once
  // baked into world space (instance_baking.h).
  bool instanced = false;
  bool planes = false;   // the scene has planes (traverse.h, surface.h)
  bool spheres = false;  // the scene has spheres (traverse.h, surface.h)
  bool skyMap = false;   // the sky is a map of more than one texel, not uniform (environment.h)
  bool punctual = false;  // the scene has punctual lights (KHR_lights_punctual, lights.h)
  // Which texture slots a material fills (materialBaseColorTexture and the rest, layout.h):
  // each slot's lookups are code of their own, which lavapipe runs for every hit.
  bool baseColorTexture = false;
  bool metallicRoughnessTexture = false;
  bool normalTexture = false;
  bool emissiveTexture = false;
  bool extensionTextures = false;  // KHR_materials_specular's, _sheen's or _clearcoat's
  // Both shade classes (layout.h): materials that need glTF's BRDF and materials that need
  // none of it. Vulkan then shades each class with a pipeline of its own (shade.comp).
  bool hasBothShadeClasses() const { return diffuse && microfacet; }
  // Marks the texture slots material m fills.
  void addTextureSlots(const gpu::GpuMaterial& m);
  // These features with the material ones (layers, transmission, metal, microfacet) as `needs`
  // says (WP_NEEDS_* bits, materialShadeNeeds).
  SceneFeatures withNeeds(uint32_t needs) const;
  // Every feature: the stages as C++ run them.
  static SceneFeatures everything();
  // Each feature the stages test by name (WP_SCENE_*, prelude_cl.h and prelude_glsl.h) and its
  // value here: OpenCL builds its programs with them defined.
  std::vector<std::pair<const char*, bool>> macros() const;
  bool operator==(const SceneFeatures&) const = default;
};

// The entries each level of the traversal's stack holds at most for a scene's trees
// (traversalStackEntries): Vulkan sizes its stacks in workgroup memory by them.
struct TraversalStackNeeds {
  uint32_t topLevel = 0;
  uint32_t bottomLevel = 0;  // the most of any mesh's
  bool operator==(const TraversalStackNeeds&) const = default;
};

struct GpuScene {
  // Every bottom-level BVH (one per mesh, in mesh order) and then the top level, with
  // absolute child indices. Bottom-level leaves index `triangles`, top-level leaves `instances`.
  std::vector<gpu::BvhNode> nodes;
  // Object-space triangles of every mesh in mesh order, each mesh's in its BVH leaf order.
  std::vector<gpu::GpuTriangle> triangles;
  std::vector<gpu::GpuTriangleShading> triangleShading;  // parallel to `triangles`
  std::vector<gpu::GpuTexture> textures;
  std::vector<uint32_t> texels;  // every texture's RGBA8 texels, padded to a multiple of 4
  // Mesh instances and spheres in top-level leaf order (the first placedInstances), then the
  // motion keys of the moving ones (layout.h). Instances of meshes without triangles and
  // instances with a singular transform are left out.
  std::vector<gpu::GpuInstance> instances;
  uint32_t placedInstances = 0;
  // Whether any instance moves during the shutter (has motion keys): the backends then run
  // the stages built with WP_MOTION_BLUR (motion.h), else the ones without.
  bool moving() const { return instances.size() > placedInstances; }
  // What the scene uses, read from its records (so any GpuScene, packed or built by hand,
  // gets the stages its data needs).
  SceneFeatures features() const;
  // What the traversal's stacks hold at most for these trees, read from `nodes`.
  TraversalStackNeeds stackNeeds() const;
  std::vector<gpu::GpuPlane> planes;
  std::vector<gpu::GpuMaterial> materials;
  // The light table: world-space emissive triangles (for each still mesh instance in
  // `instances` order, its mesh's emissive non-degenerate triangles in the mesh's original
  // order), then the scene's punctual lights in its order.
  std::vector<gpu::GpuLight> lights;
  uint32_t punctualLightCount = 0;  // the last entries of `lights`
  // The sky (environment.h): radiance texels, row and column distributions, settings. A
  // scene without a sky gets one black texel, never sampled.
  std::vector<glm::vec4> skyRadiance;
  std::vector<float> skyMarginal;
  std::vector<float> skyConditional;
  gpu::GpuEnvironment sky{};
  // Whether a ray can find emission (RenderParams.emissionHittable): a material emits (any
  // material: one no surface has only costs rays), or the sky is not black.
  bool emissionHittable() const;
  std::vector<GpuMeshRange> meshes;  // one per scene mesh
  uint32_t tlasRoot = 0;  // the top level's root node
  // The top level's root as the traversal starts from it (traverse.h, traceScene): the root
  // node's stack entry, or, where the top level holds one instance, that instance's leaf.
  uint32_t topLevelEntry() const {
    return placedInstances == 1 ? gpu::packEntry(0u, 1u) : gpu::packEntry(tlasRoot, 0u);
  }
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // world bounds of the instances (planes are
                                               // unbounded); all 0 without instances
  double bvhBuildSeconds = 0.0;  // wall time of all bottom- and top-level builds
  size_t triangleCount = 0;      // triangles stored (each mesh once, however often instanced)
  // SAH cost (sahCost, traversal and intersection cost 1) of the bottom levels, as the mean
  // over meshes weighted by triangle count; 0 without triangles.
  double sahCost = 0.0;
};

// Packs `scene` for traceClosest / traceAny and the shading stages. Requires a scene as the
// loader produces it: valid material indices, finite positions, unit plane normals.
// Singular instance transforms are skipped with a warning.
GpuScene packScene(const Scene& scene);

}  // namespace wp
