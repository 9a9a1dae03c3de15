// The execution interface the wavefront integrator drives. Vulkan and OpenCL implement it;
// the stage order lives above it (src/render/wavefront.cpp), written once.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/common/accumulation.h"
#include "shaders/common/binding_table.h"

namespace wp {

struct GpuScene;

// The bindings of a packed scene's arrays: the binding table's TEXELS rows, in its order,
// which is the order sceneArrays lists them in.
inline constexpr size_t kSceneArrayCount = [] {
  size_t count = 0;
  for (const gpu::BindingInfo& b : gpu::kBindings) {
    count += b.access == gpu::BindingAccess::Texels ? 1 : 0;
  }
  return count;
}();
inline constexpr std::array<uint32_t, kSceneArrayCount> kSceneBindings = [] {
  std::array<uint32_t, kSceneArrayCount> bindings{};
  size_t next = 0;
  for (const gpu::BindingInfo& b : gpu::kBindings) {
    if (b.access == gpu::BindingAccess::Texels) {
      bindings[next++] = b.index;
    }
  }
  return bindings;
}();

// One array of a packed scene as a backend uploads it to kSceneBindings[i].
struct SceneArray {
  const void* data = nullptr;
  uint64_t bytes = 0;
  const char* name = "";  // what it holds, for messages: "triangle shading"
};

// What a GpuScene puts on the device, the one list both backends upload: entry i is read by
// the stages through binding kSceneBindings[i].
std::array<SceneArray, kSceneBindings.size()> sceneArrays(const GpuScene& scene);

enum class Kernel { Generate, Extend, Shade, Advance, Connect, Accumulate };
inline constexpr int kKernelCount = 6;
const char* kernelName(Kernel kernel);

// How many threads a dispatch runs: a count the host knows, or a queue's length as dispatch
// arguments that an earlier dispatch of the pass wrote into the counters buffer, at word
// `argumentsWord` (queues.h; Vulkan dispatches indirectly, OpenCL reads them back or
// launches every path of the pass).
struct DispatchSize {
  enum class Source { Host, Queue };
  Source source = Source::Host;
  uint32_t threads = 0;        // Host
  uint32_t argumentsWord = 0;  // Queue: WP_COUNTER_*_DISPATCH

  static DispatchSize fixed(uint32_t threads) { return {Source::Host, threads, 0}; }
  // The current bounce's ray queue (extend and shade).
  static DispatchSize rayQueue() { return {Source::Queue, 0, WP_COUNTER_EXTEND_DISPATCH}; }
  // The current bounce's shadow queue (connect).
  static DispatchSize shadowQueue() { return {Source::Queue, 0, WP_COUNTER_CONNECT_DISPATCH}; }
};

// Whether a stage writes the dispatch arguments that later Queue-sized dispatches read.
enum class DispatchArguments { Untouched, Written };

// One stage of a pass, as the integrator orders them (wavefront.cpp).
struct StageDispatch {
  Kernel kernel;
  gpu::PassConstants constants;
  DispatchSize size;
  DispatchArguments arguments = DispatchArguments::Untouched;
};

// What a pass is, before its dispatches: its paths, and the bounces it traces (rounds of
// extend, shade, advance and connect), each of which traces at most one ray and one shadow
// ray per path.
struct PassShape {
  uint32_t paths = 0;
  uint32_t bounces = 0;
};

struct PassResult {
  uint64_t extensionRays = 0;
  uint64_t shadowRays = 0;
  std::array<double, kKernelCount> kernelMs{};  // GPU time per kernel; zeros if unsupported
};

// Device memory a path in flight takes: two ray-queue entries, a hit, a shadow ray, its
// radiance and its feature passes.
inline constexpr uint64_t kBytesPerPath = 2 * sizeof(gpu::PathRay) + sizeof(gpu::HitRecord) +
                                          sizeof(gpu::ShadowRay) + sizeof(glm::vec4) + sizeof(gpu::PathFeatures);
// Device memory a pixel of the accumulation takes: a vec4 per layer (accumulation.h).
inline constexpr uint64_t kAccumulationBytesPerPixel = WP_ACCUMULATION_LAYERS * sizeof(glm::vec4);

// Running per-pixel sums over all samples so far, the layers of the accumulation buffer
// (shaders/common/accumulation.h), one entry per pixel each.
struct Accumulation {
  std::vector<glm::vec4> sum;          // WP_LAYER_RADIANCE
  std::vector<glm::vec4> sumSquares;   // WP_LAYER_RADIANCE_SQUARES
  std::vector<glm::vec4> albedoDepth;  // WP_LAYER_ALBEDO_DEPTH
  std::vector<glm::vec4> normal;       // WP_LAYER_NORMAL

  // The layers in the buffer's order (layer WP_LAYER_* is entry WP_LAYER_*).
  std::array<std::vector<glm::vec4>*, WP_ACCUMULATION_LAYERS> layers() {
    return {&sum, &sumSquares, &albedoDepth, &normal};
  }
  std::array<const std::vector<glm::vec4>*, WP_ACCUMULATION_LAYERS> layers() const {
    return {&sum, &sumSquares, &albedoDepth, &normal};
  }
  // Every layer `pixels` entries of zeros.
  static Accumulation zeros(uint64_t pixels);
};

// The accumulation buffer's contents for `accumulation` (Binding::accumulation: its layers
// one after another); throws wp::Error when a layer does not hold `pixels` entries.
std::vector<glm::vec4> accumulationBuffer(const Accumulation& accumulation, uint32_t pixels);
// The accumulation that the buffer's contents hold, for `pixels` pixels: read where the device
// lets the host see them (mapped), so each layer is copied once, into its own vector.
Accumulation accumulationOfBuffer(const glm::vec4* buffer, uint32_t pixels);

class Backend {
public:
  virtual ~Backend() = default;

  virtual std::string deviceName() const = 0;
  // The most paths the device can keep in flight in one pass (dispatch and buffer limits).
  virtual uint32_t maxPathsInFlight() const = 0;
  // Whether the device is a CPU implementation (lavapipe, PoCL) rather than a GPU.
  virtual bool onCpu() const = 0;
  // Uploads the scene and chooses the stage kernels for it: with motion blur where something
  // moves (GpuScene::moving), else without, specialized to its features; they are in place
  // once configure has run (OpenCL builds them there, knowing the render's light selection
  // too). Call before configure; may be called again to replace the scene. Throws wp::Error, naming the array, its size and the device's limit,
  // when an array or the whole scene does not fit the device.
  virtual void loadScene(const GpuScene& scene) = 0;
  // Whether the kernels of the loaded scene are the motion-blur ones.
  virtual bool motionKernels() const = 0;
  // The most pixels whose accumulation fits the device beside the loaded scene and
  // `maxPaths` paths in flight, by the largest buffer, by its memory and, where the backend
  // reads it as texels, by the most texels a view may hold (an image with more is rendered in
  // tiles). Call after loadScene.
  virtual uint64_t maxAccumulationPixels(uint32_t maxPaths) const = 0;
  // Sets the render parameters and sizes path state for params.maxPaths paths and the
  // accumulation for params.pixelCount pixels (the tile's); clears the accumulation. Throws
  // wp::Error, saying what needs how much and what the device allows, when a buffer does
  // not fit.
  virtual void configure(const gpu::RenderParams& params) = 0;
  // Starts recording a sample pass; dispatches run in order, each after the previous one.
  virtual void beginPass(const PassShape& shape) = 0;
  virtual void dispatch(const StageDispatch& stage) = 0;
  // Runs the recorded pass and waits for it.
  virtual PassResult endPass() = 0;
  virtual Accumulation readAccumulation() = 0;
  // Replaces the accumulation with `accumulation` (one entry per pixel of params.pixelCount in
  // each array), e.g. a checkpoint's sums to go on from.
  virtual void writeAccumulation(const Accumulation& accumulation) = 0;
};

}  // namespace wp
