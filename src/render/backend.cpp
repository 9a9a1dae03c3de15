// Names of the wavefront kernels, for timings and messages, and the scene arrays a backend uploads.
#include "render/backend.h"

#include "bvh/gpu_scene.h"

namespace wp {

namespace {

template <typename T>
SceneArray arrayOf(const std::vector<T>& v, const char* name) {
  return {v.data(), uint64_t(v.size()) * sizeof(T), name};
}

}  // namespace

std::array<SceneArray, kSceneBindings.size()> sceneArrays(const GpuScene& s) {
  // In the order of kSceneBindings.
  return {arrayOf(s.nodes, "BVH nodes"),
          arrayOf(s.triangles, "triangles"),
          arrayOf(s.instances, "instances"),
          arrayOf(s.planes, "planes"),
          arrayOf(s.materials, "materials"),
          arrayOf(s.lights, "emissive triangles"),
          arrayOf(s.skyRadiance, "sky texels"),
          arrayOf(s.skyMarginal, "sky row distribution"),
          arrayOf(s.skyConditional, "sky column distributions"),
          arrayOf(s.triangleShading, "triangle shading"),
          arrayOf(s.textures, "textures"),
          arrayOf(s.texels, "texture texels")};
}

const char* kernelName(Kernel kernel) {
  switch (kernel) {
    case Kernel::Generate: return "generate";
    case Kernel::Extend: return "extend";
    case Kernel::Shade: return "shade";
    case Kernel::Advance: return "advance";
    case Kernel::Connect: return "connect";
    case Kernel::Accumulate: return "accumulate";
  }
  return "?";
}

}  // namespace wp
