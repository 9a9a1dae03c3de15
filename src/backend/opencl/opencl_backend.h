// The OpenCL implementation of the wavefront Backend: one kernel per stage from one
// program, queue lengths handled without indirect dispatch (see ClDispatch).
#pragma once

#include <CL/cl.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "backend/opencl/opencl_buffer.h"
#include "backend/opencl/opencl_context.h"
#include "backend/opencl/opencl_program.h"
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
// code (prelude_cl.h).
std::string openClProgramOptions(const OpenClDeviceInfo& device, bool validate, bool motion);

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

private:
  // Builds the program and kernels with (`motion`) or without WP_MOTION_BLUR.
  void buildVariant(bool motion);
  // Sets kernel argument `binding` (binding_table.h) of every kernel of the current variant to `buffer`.
  void bind(uint32_t binding, const OpenClBuffer& buffer);
  // Work items for a launch sized by the dispatch arguments at counters word `word`.
  uint32_t queueThreads(uint32_t word);
  // The counters buffer as words (WP_COUNTER_*), after everything enqueued so far.
  std::array<uint32_t, WP_COUNTER_WORDS> readCounters();
  // Binds the buffers configure made (everything but the scene) to the current variant.
  void bindPathState();
  // Device memory of the scene and of maxPaths paths in flight, without the accumulation.
  uint64_t pathStateBytes(uint64_t maxPaths) const;
  void checkCounters(const std::array<uint32_t, WP_COUNTER_WORDS>& counters) const;

  std::unique_ptr<OpenClContext> context_;
  DeviceLimits limits_;  // the device's, with the testing cap (withBufferCap)
  // The stage kernels built without ([0]) and with ([1]) motion blur; [1] only once a
  // moving scene was loaded. motion_ picks the ones loadScene chose.
  struct Variant {
    std::unique_ptr<OpenClProgram> program;
    std::array<cl_kernel, kKernelCount> kernels{};
  };
  std::array<Variant, 2> variants_;
  bool motion_ = false;
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
