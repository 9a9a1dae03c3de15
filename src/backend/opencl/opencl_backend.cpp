// OpenCL wavefront backend: kernels and buffers, passes as in-order launches sized without
// indirect dispatch, per-kernel times from profiling events.
#include "backend/opencl/opencl_backend.h"

#include <algorithm>
#include <optional>

#include "backend/opencl/cl_check.h"
#include "bvh/gpu_scene.h"
#include "core/error.h"
#include "render/device_limits.h"

namespace wp {
namespace {

// The kernels take one argument per binding that OpenCL uses (at the binding's index, the
// table lists them first), then the pass constants.
constexpr uint32_t kPassConstantsArgument = [] {
  uint32_t count = 0;
  for (const gpu::BindingInfo& b : gpu::kBindings) {
    count += b.openCl ? 1 : 0;
  }
  return count;
}();

}  // namespace

std::string openClProgramOptions(const OpenClDeviceInfo& device, bool validate, bool motion,
                                 const SceneFeatures& features, bool solidAngleSelection) {
  // Denormal floats flushed to zero, as GPUs do: a CPU takes a microcode assist of a hundred
  // cycles or more on each denormal operand, and the stages make some (a pinhole's f / D with
  // the focus D at infinity, the unused lane of a vec3 in a vector register). PoCL's generate
  // took twice as long, its extend and connect 10% longer; images are bit-identical.
  std::string options = "-cl-std=CL1.2 -cl-denorms-are-zero";
  if (validate) {
    options += " -Werror";
  }
  if (motion) {
    options += " -DWP_MOTION_BLUR=1";
  }
  if (device.type == "CPU") {
    options += " -DWP_WORK_ITEMS_ARE_THREADS=1";
  }
  // Code for what the scene lacks compiled out, as Vulkan's specialization constants do
  // (prelude_glsl.h lists the features): shade 7-13% shorter on PoCL for the Lambertian box,
  // 21-23% for the instanced scene, 40-47% on an NVIDIA H200.
  for (const auto& [macro, on] : features.macros()) {
    if (!on) options += std::string(" -D") + macro + "=false";
  }
  if (!solidAngleSelection) {
    options += " -DWP_RENDER_SOLID_ANGLE_SELECTION=false";
  }
  return options;
}

OpenClBackend::OpenClBackend(int deviceIndex, ClDispatch dispatch, bool validate)
    : context_(std::make_unique<OpenClContext>(deviceIndex)), dispatchMode_(dispatch), validate_(validate) {
  const OpenClDeviceInfo& device = context_->device;
  const ByteLimit allocation{device.maxAllocationBytes, "CL_DEVICE_MAX_MEM_ALLOC_SIZE"};
  limits_ = withBufferCap({"OpenCL device '" + device.name + "'", allocation, allocation,
                           {device.globalMemoryBytes, "CL_DEVICE_GLOBAL_MEM_SIZE"}});
}

std::string OpenClBackend::variantOptions() const {
  return openClProgramOptions(context_->device, validate_, motion_,
                              specializeToScene_ ? sceneFeatures_ : SceneFeatures::everything(),
                              solidAngleSelection_ || !specializeToScene_);
}

void OpenClBackend::useVariant() {
  const std::string options = variantOptions();
  Variant& v = variants_[options];
  if (&v == variant_) return;
  if (v.program == nullptr) {
    // The binary cache keys on the options, so each variant is cached apart.
    v.program = std::make_unique<OpenClProgram>(*context_, options);
    for (int k = 0; k < kKernelCount; ++k) {
      cl_int result = CL_SUCCESS;
      v.kernels[k] = clCreateKernel(v.program->handle(), kernelName(Kernel(k)), &result);
      CL_CHECK(result);
    }
  }
  variant_ = &v;
}

OpenClBackend::~OpenClBackend() {
  clFinish(context_->queue);
  for (auto& [kernel, event] : events_) {
    clReleaseEvent(event);
  }
  for (auto& [options, v] : variants_) {
    for (cl_kernel kernel : v.kernels) {
      if (kernel != nullptr) {
        clReleaseKernel(kernel);
      }
    }
  }
}

std::string OpenClBackend::deviceName() const { return context_->device.name + " (OpenCL)"; }

uint32_t OpenClBackend::maxPathsInFlight() const {
  // The two ray queues share the largest buffer; path state may take half the memory, the
  // rest is for the scene and the image.
  uint64_t byAllocation = limits_.writable.bytes / (2 * sizeof(gpu::PathRay));
  uint64_t byMemory = limits_.memory.bytes / 2 / kBytesPerPath;
  return uint32_t(std::min({byAllocation, byMemory, uint64_t(UINT32_MAX)}));
}

bool OpenClBackend::onCpu() const { return context_->device.type == "CPU"; }

uint64_t OpenClBackend::pathStateBytes(uint64_t maxPaths) const {
  return sceneBytes_ + sizeof(gpu::RenderParams) + maxPaths * kBytesPerPath + sizeof(gpu::QueueCounters);
}

uint64_t OpenClBackend::maxAccumulationPixels(uint32_t maxPaths) const {
  const uint64_t used = pathStateBytes(maxPaths);
  const uint64_t byMemory = limits_.memory.bytes > used ? (limits_.memory.bytes - used) / kAccumulationBytesPerPixel : 0;
  return std::min(limits_.writable.bytes / kAccumulationBytesPerPixel, byMemory);
}

OpenClBuffer OpenClBackend::newBuffer(cl_mem_flags flags, uint64_t size, const void* data) const {
  return OpenClBuffer(context_->context, flags, size, data, onCpu() ? OpenClMemory::hostHugePages : OpenClMemory::driver);
}

void OpenClBackend::bind(uint32_t binding, const OpenClBuffer& buffer) {
  for (cl_kernel kernel : variant_->kernels) {
    CL_CHECK(clSetKernelArg(kernel, binding, sizeof(cl_mem), buffer.argument()));
  }
}

void OpenClBackend::loadScene(const GpuScene& scene) {
  clFinish(context_->queue);
  // The stages for this scene (with motion blur where something moves, and its features) are
  // picked by configure, which knows the render's light selection too: one build, not two.
  motion_ = scene.moving();
  sceneFeatures_ = scene.features();
  const auto arrays = sceneArrays(scene);
  const uint64_t bytes = checkSceneFits(limits_, arrays);
  for (size_t i = 0; i < arrays.size(); ++i) {
    sceneBuffers_[i] = newBuffer(CL_MEM_READ_ONLY, arrays[i].bytes, arrays[i].data);
  }
  sceneBytes_ = bytes;
}

void OpenClBackend::configure(const gpu::RenderParams& params) {
  if (sceneBuffers_[0].handle() == nullptr) {
    throw Error("internal: OpenClBackend::configure called before loadScene");
  }
  uint64_t maxPaths = params.maxPaths;
  uint64_t pixels = params.pixelCount;
  uint64_t rayBytes = 2 * maxPaths * sizeof(gpu::PathRay);
  uint64_t accumulationBytes = pixels * kAccumulationBytesPerPixel;
  checkPathStateFits(limits_, rayBytes, pixels, pathStateBytes(maxPaths) + accumulationBytes);

  clFinish(context_->queue);
  solidAngleSelection_ = params.lightSelection == WP_LIGHT_SELECTION_SOLID_ANGLE;
  useVariant();
  params_ = newBuffer(CL_MEM_READ_ONLY, sizeof(params), &params);
  if (rays_.handle() == nullptr || rays_.size() < rayBytes) {
    rays_ = newBuffer(CL_MEM_READ_WRITE, rayBytes);
    hits_ = newBuffer(CL_MEM_READ_WRITE, maxPaths * sizeof(gpu::HitRecord));
    shadowRays_ = newBuffer(CL_MEM_READ_WRITE, maxPaths * sizeof(gpu::ShadowRay));
    pathRadiance_ = newBuffer(CL_MEM_READ_WRITE, maxPaths * sizeof(glm::vec4));
    pathFeatures_ = newBuffer(CL_MEM_READ_WRITE, maxPaths * sizeof(gpu::PathFeatures));
    counters_ = newBuffer(CL_MEM_READ_WRITE, sizeof(gpu::QueueCounters));
  }
  pixelCount_ = params.pixelCount;
  accumulation_ = newBuffer(CL_MEM_READ_WRITE, accumulationBytes);
  const float zero = 0.0f;
  CL_CHECK(clEnqueueFillBuffer(context_->queue, accumulation_.handle(), &zero, sizeof(zero), 0,
                               accumulation_.size(), 0, nullptr, nullptr));
  const uint32_t empty = 0;  // empty queues (queues.h)
  CL_CHECK(clEnqueueFillBuffer(context_->queue, counters_.handle(), &empty, sizeof(empty), 0, counters_.size(), 0,
                               nullptr, nullptr));
  CL_CHECK(clFinish(context_->queue));
  bindBuffers();
}

void OpenClBackend::bindBuffers() {
  for (size_t i = 0; i < sceneBuffers_.size(); ++i) {
    bind(kSceneBindings[i], sceneBuffers_[i]);
  }
  bind(gpu::Binding::params, params_);
  bind(gpu::Binding::rays, rays_);
  bind(gpu::Binding::hits, hits_);
  bind(gpu::Binding::shadowRays, shadowRays_);
  bind(gpu::Binding::pathRadiance, pathRadiance_);
  bind(gpu::Binding::pathFeatures, pathFeatures_);
  bind(gpu::Binding::counters, counters_);
  bind(gpu::Binding::accumulation, accumulation_);
}

void OpenClBackend::beginPass(const PassShape& shape) {
  pass_ = shape;
  countersStale_ = true;
}

std::array<uint32_t, WP_COUNTER_WORDS> OpenClBackend::readCounters() {
  std::array<uint32_t, WP_COUNTER_WORDS> counters;
  CL_CHECK(clEnqueueReadBuffer(context_->queue, counters_.handle(), CL_TRUE, 0, sizeof(counters), &counters, 0,
                               nullptr, nullptr));
  return counters;
}

uint32_t OpenClBackend::queueThreads(uint32_t word) {
  if (dispatchMode_ == ClDispatch::Max) {
    return pass_.paths;
  }
  if (countersStale_) {
    lastCounters_ = readCounters();
    countersStale_ = false;
  }
  return lastCounters_[word] * WP_WORKGROUP_SIZE;
}

void OpenClBackend::dispatch(const StageDispatch& stage) {
  const DispatchSize& size = stage.size;
  uint32_t threads = size.source == DispatchSize::Source::Queue ? queueThreads(size.argumentsWord) : size.threads;
  countersStale_ = countersStale_ || stage.arguments == DispatchArguments::Written;
  if (threads == 0) {
    return;
  }
  int k = static_cast<int>(stage.kernel);
  cl_kernel clKernel = variant_->kernels[k];
  CL_CHECK(clSetKernelArg(clKernel, kPassConstantsArgument, sizeof(stage.constants), &stage.constants));
  size_t local = WP_WORKGROUP_SIZE;
  size_t global = (size_t(threads) + local - 1) / local * local;
  cl_event event = nullptr;
  CL_CHECK(clEnqueueNDRangeKernel(context_->queue, clKernel, 1, nullptr, &global, &local, 0, nullptr, &event));
  events_.emplace_back(k, event);
}

void OpenClBackend::checkCounters(const std::array<uint32_t, WP_COUNTER_WORDS>& words) const {
  // A queue never holds more than one entry per path, and each bounce traces at most one
  // ray and one shadow ray per path.
  uint64_t paths = pass_.paths;
  bool inBounds = words[WP_COUNTER_TOTAL_RAYS] <= paths * pass_.bounces &&
                  words[WP_COUNTER_TOTAL_SHADOW_RAYS] <= paths * pass_.bounces;
  std::string queues;
  for (uint32_t i = 0; i < 4; ++i) {
    inBounds = inBounds && words[WP_COUNTER_RAYS + i] <= paths;
    queues += (i > 0 ? ", " : "") + std::to_string(words[WP_COUNTER_RAYS + i]);
  }
  if (!inBounds) {
    throw Error("OpenCL validation: the queue counters left their bounds in a pass of " + std::to_string(paths) +
                " paths (queues " + queues + "); this is a bug, please report it with the command line used");
  }
}

PassResult OpenClBackend::endPass() {
  // Blocking: the in-order queue has finished every launch of the pass when it returns.
  std::array<uint32_t, WP_COUNTER_WORDS> counters = readCounters();
  PassResult result;
  result.extensionRays = counters[WP_COUNTER_TOTAL_RAYS];
  result.shadowRays = counters[WP_COUNTER_TOTAL_SHADOW_RAYS];
  std::vector<std::pair<int, cl_event>> events = std::move(events_);
  events_.clear();
  std::string failed;
  for (auto& [kernel, event] : events) {
    cl_int status = CL_COMPLETE;
    cl_ulong start = 0;
    cl_ulong end = 0;
    clGetEventInfo(event, CL_EVENT_COMMAND_EXECUTION_STATUS, sizeof(status), &status, nullptr);
    if (status < 0 && failed.empty()) {
      failed = std::string("the OpenCL kernel '") + kernelName(Kernel(kernel)) + "' failed with " +
               cl::errorName(status) + "; lower --max-paths or the image size, or pick another --device";
    }
    if (clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_START, sizeof(start), &start, nullptr) == CL_SUCCESS &&
        clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_END, sizeof(end), &end, nullptr) == CL_SUCCESS &&
        end > start) {
      result.kernelMs[kernel] += double(end - start) * 1e-6;
    }
    clReleaseEvent(event);
  }
  if (!failed.empty()) {
    throw Error(failed);
  }
  if (validate_) {
    checkCounters(counters);
  }
  variant_->program->cacheBinary();
  return result;
}

// Mapped, not read into a host buffer first: a CPU device maps its own memory, so the layers
// are copied once (image write of the instanced scene at 960x540, five runs each: PoCL 155-160
// -> 135-145 ms, lavapipe 155-168 -> 135-141 ms reading its memory in place the same way).
Accumulation OpenClBackend::readAccumulation() {
  cl_int error = CL_SUCCESS;
  void* mapped = clEnqueueMapBuffer(context_->queue, accumulation_.handle(), CL_TRUE, CL_MAP_READ, 0,
                                    uint64_t(WP_ACCUMULATION_LAYERS) * pixelCount_ * sizeof(glm::vec4), 0, nullptr,
                                    nullptr, &error);
  CL_CHECK(error);
  std::optional<Accumulation> result;
  try {
    result = accumulationOfBuffer(static_cast<const glm::vec4*>(mapped), pixelCount_);
  } catch (...) {
    clEnqueueUnmapMemObject(context_->queue, accumulation_.handle(), mapped, 0, nullptr, nullptr);
    throw;
  }
  CL_CHECK(clEnqueueUnmapMemObject(context_->queue, accumulation_.handle(), mapped, 0, nullptr, nullptr));
  return std::move(*result);
}

void OpenClBackend::writeAccumulation(const Accumulation& accumulation) {
  std::vector<glm::vec4> buffer = accumulationBuffer(accumulation, pixelCount_);
  CL_CHECK(clEnqueueWriteBuffer(context_->queue, accumulation_.handle(), CL_TRUE, 0,
                                buffer.size() * sizeof(glm::vec4), buffer.data(), 0, nullptr, nullptr));
}

}  // namespace wp
