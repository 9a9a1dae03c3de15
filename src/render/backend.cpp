// Names of the wavefront kernels, for timings and messages, and the scene arrays a backend uploads.
#include "render/backend.h"

#include "bvh/gpu_scene.h"
#include "core/error.h"

namespace wp {

namespace {

template <typename T>
SceneArray arrayOf(const std::vector<T>& v, const char* name) {
  return {v.data(), uint64_t(v.size()) * sizeof(T), name};
}

}  // namespace

std::array<SceneArray, kSceneBindings.size()> sceneArrays(const GpuScene& s) {
  // Each scene array of the binding table is the GpuScene member of the same name, which
  // messages name it by.
#define WP_SCENE_ARRAY(name) arrayOf(s.name, #name),
  return {WP_FOR_EACH_SCENE_ARRAY};
#undef WP_SCENE_ARRAY
}

std::vector<glm::vec4> accumulationBuffer(const Accumulation& accumulation, uint32_t pixels) {
  if (accumulation.sum.size() != pixels || accumulation.sumSquares.size() != pixels) {
    throw Error("internal: an accumulation of " + std::to_string(accumulation.sum.size()) + " pixels for an image of " +
                std::to_string(pixels));
  }
  std::vector<glm::vec4> both(accumulation.sum);
  both.insert(both.end(), accumulation.sumSquares.begin(), accumulation.sumSquares.end());
  return both;
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
