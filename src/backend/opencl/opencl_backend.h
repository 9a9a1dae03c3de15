// The OpenCL implementation of the wavefront Backend: one kernel per stage from one
// program, queue lengths handled without indirect dispatch (see ClDispatch).
#pragma once

#include <CL/cl.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "backend/opencl/opencl_buffer.h"
#include "backend/opencl/opencl_context.h"
#include "backend/opencl/opencl_program.h"
#include "bvh/gpu_scene.h"
#include "render/backend.h"
#include "render/device_limits.h"

namespace wp {

// How extend, shade and connect are sized, OpenCL 1.2 having no indirect dispatch.
enum class ClDispatch {
  // Every such launch covers all paths of the pass; work items past the queue length exit.
  Max,
  // The host reads the queue lengths back after each stage that writes dispatch arguments
  // (StageDispatch::arguments: generate and advance, a wait each bounce) and launches
  // exactly those, skipping empty queues.
  Readback,
};

// The options the kernels are built with on `device`: OpenCL C 1.2 with denormals flushed
// to zero; warnings as errors with `validate`; WP_MOTION_BLUR for the `motion` variant;
// WP_WORK_ITEMS_ARE_THREADS on a CPU device, where each work-item runs as a thread's scalar
// code (prelude_cl.h); each WP_SCENE_* feature the scene lacks defined false, and
// WP_RENDER_SOLID_ANGLE_SELECTION where lights are selected by power (prelude_cl.h).
std::string openClProgramOptions(const OpenClDeviceInfo& device, bool validate, bool motion,
                                 const SceneFeatures& features = SceneFeatures::everything(),
                                 bool solidAngleSelection = true);

class OpenClBackend final : public Backend {
public:
  // deviceIndex < 0 picks the most capable device. With `validate` the kernels build with
  // warnings as errors and every pass checks that its queue counters stayed in bounds.
  OpenClBackend(int deviceIndex, ClDispatch dispatch, bool validate);
  ~OpenClBackend() override;

  std::string deviceName() const override;
  uint32_t maxPathsInFlight() const override;
  bool onCpu() const override;
  uint64_t maxAccumulationPixels(uint32_t maxPaths) const override;
  void loadScene(const GpuScene& scene) override;
  bool motionKernels() const override { return motion_; }
  void configure(const gpu::RenderParams& params) override;
  void beginPass(const PassShape& shape) override;
  void dispatch(const StageDispatch& stage) override;
  PassResult endPass() override;
  Accumulation readAccumulation() override;
  void writeAccumulation(const Accumulation& accumulation) override;

  // For tests: build the stages with every feature and light selection (true, the default:
  // specialized to the loaded scene and the render), from the next configure on.
  void specializeToScene(bool specialize) { specializeToScene_ = specialize; }

private:
  // Makes the stages built with the options of the loaded scene and the render current
  // (variantOptions), building them the first time.
  void useVariant();
  std::string variantOptions() const;
  // A buffer in this device's memory: on a CPU device, huge pages of wavepath's own
  // (OpenClMemory); `data`, if given, is `size` bytes copied in.
  OpenClBuffer newBuffer(cl_mem_flags flags, uint64_t size, const void* data = nullptr) const;
  // Sets kernel argument `binding` (binding_table.h) of every kernel of the current variant to `buffer`.
  void bind(uint32_t binding, const OpenClBuffer& buffer);
  // Work items for a launch sized by the dispatch arguments at counters word `word`.
  uint32_t queueThreads(uint32_t word);
  // The counters buffer as words (WP_COUNTER_*), after everything enqueued so far.
  std::array<uint32_t, WP_COUNTER_WORDS> readCounters();
  // Binds the scene's buffers and those configure made to the current variant's kernels.
  void bindBuffers();
  // Device memory of the scene and of maxPaths paths in flight, without the accumulation.
  uint64_t pathStateBytes(uint64_t maxPaths) const;
  void checkCounters(const std::array<uint32_t, WP_COUNTER_WORDS>& counters) const;

  std::unique_ptr<OpenClContext> context_;
  DeviceLimits limits_;  // the device's, with the testing cap (withBufferCap)
  // The stage kernels of each set of build options a scene or render asked for (motion blur,
  // the scene's features, the light selection), built when first asked for; variant_ is the
  // current one's.
  struct Variant {
    std::unique_ptr<OpenClProgram> program;
    std::array<cl_kernel, kKernelCount> kernels{};
  };
  std::map<std::string, Variant> variants_;
  Variant* variant_ = nullptr;
  bool motion_ = false;
  bool specializeToScene_ = true;
  SceneFeatures sceneFeatures_ = SceneFeatures::everything();
  bool solidAngleSelection_ = true;
  ClDispatch dispatchMode_;
  bool validate_;

  std::array<OpenClBuffer, kSceneBindings.size()> sceneBuffers_;  // for kSceneBindings[i]
  uint64_t sceneBytes_ = 0;
  OpenClBuffer params_;
  OpenClBuffer rays_;
  OpenClBuffer hits_;
  OpenClBuffer shadowRays_;
  OpenClBuffer pathRadiance_;
  OpenClBuffer pathFeatures_;
  OpenClBuffer counters_;
  OpenClBuffer accumulation_;
  uint32_t pixelCount_ = 0;

  // The current pass: its shape, each launch's kernel and profiling event, the counters as
  // last read back and whether a stage that writes dispatch arguments ran since.
  PassShape pass_;
  std::vector<std::pair<int, cl_event>> events_;
  std::array<uint32_t, WP_COUNTER_WORDS> lastCounters_{};
  bool countersStale_ = true;
};

}  // namespace wp
