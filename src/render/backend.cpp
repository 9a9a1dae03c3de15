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

Accumulation Accumulation::zeros(uint64_t pixels) {
  Accumulation a;
  for (std::vector<glm::vec4>* layer : a.layers()) layer->assign(pixels, glm::vec4(0.0f));
  return a;
}

std::vector<glm::vec4> accumulationBuffer(const Accumulation& accumulation, uint32_t pixels) {
  std::vector<glm::vec4> buffer;
  buffer.reserve(size_t(pixels) * WP_ACCUMULATION_LAYERS);
  for (const std::vector<glm::vec4>* layer : accumulation.layers()) {
    if (layer->size() != pixels)
      throw Error("internal: an accumulation layer of " + std::to_string(layer->size()) + " pixels for an image of " +
                  std::to_string(pixels));
    buffer.insert(buffer.end(), layer->begin(), layer->end());
  }
  return buffer;
}

Accumulation accumulationOfBuffer(const glm::vec4* buffer, uint32_t pixels) {
  Accumulation result;
  const glm::vec4* at = buffer;
  for (std::vector<glm::vec4>* layer : result.layers()) {
    layer->assign(at, at + pixels);
    at += pixels;
  }
  return result;
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
