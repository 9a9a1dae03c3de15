// Vulkan wavefront backend: pipelines, descriptors, pass recording with indirect dispatch,
// and per-kernel GPU timestamps.
#include "backend/vulkan/vulkan_backend.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <vector>

#include "backend/vulkan/vk_check.h"
#include "bvh/gpu_scene.h"
#include "core/error.h"
#include "core/parallel.h"
#include "shaders/common/bsdf_table_lookup.h"
#include "spirv/accumulate_spv.h"
#include "spirv/advance_spv.h"
#include "spirv/connect_motion_spv.h"
#include "spirv/connect_spv.h"
#include "spirv/extend_motion_spv.h"
#include "spirv/extend_spv.h"
#include "spirv/generate_spv.h"
#include "spirv/shade_motion_spv.h"
#include "spirv/shade_spv.h"

namespace wp {
namespace {

// Two timestamps per dispatch is ample: a pass has 2 + 4 * (bounces + 2) dispatches.
constexpr uint32_t kMaxQueries = 1024;

// The stage's code with or without motion blur (the stages that never place an instance
// have one build, shaders/CMakeLists.txt).
SpirvCode spirvFor(Kernel kernel, bool motion) {
  switch (kernel) {
    case Kernel::Generate: return {generate_spv, sizeof(generate_spv)};
    case Kernel::Extend:
      return motion ? SpirvCode{extend_motion_spv, sizeof(extend_motion_spv)}
                    : SpirvCode{extend_spv, sizeof(extend_spv)};
    case Kernel::Shade:
      return motion ? SpirvCode{shade_motion_spv, sizeof(shade_motion_spv)}
                    : SpirvCode{shade_spv, sizeof(shade_spv)};
    case Kernel::Advance: return {advance_spv, sizeof(advance_spv)};
    case Kernel::Connect:
      return motion ? SpirvCode{connect_motion_spv, sizeof(connect_motion_spv)}
                    : SpirvCode{connect_spv, sizeof(connect_spv)};
    case Kernel::Accumulate: return {accumulate_spv, sizeof(accumulate_spv)};
  }
  return {nullptr, 0};
}

// The BSDF tables as the stages fetch them: quad i (bsdf_table_lookup.h) as texel i.
std::vector<gpu::vec4> packBsdfTableQuads() {
  std::vector<gpu::vec4> texels(WP_TABLE_QUADS);
  for (uint32_t i = 0; i < WP_TABLE_QUADS; ++i) {
    const gpu::BsdfTableQuad quad = gpu::bsdfTableQuad(i);
    texels[i] = gpu::vec4(quad.row, quad.nextRow);
  }
  return texels;
}

VkDescriptorType descriptorType(uint32_t binding) {
  switch (gpu::kBindings[binding].access) {
    case gpu::BindingAccess::Uniform: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case gpu::BindingAccess::Texels:
    case gpu::BindingAccess::TexelView:
    case gpu::BindingAccess::Constant: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    case gpu::BindingAccess::Storage:
    case gpu::BindingAccess::Write: break;
  }
  return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

// Bytes of one texel of the view a texel-buffer binding is read through (bindings.glsl).
uint64_t texelBytes(uint32_t binding) { return gpu::kBindings[binding].format == gpu::TexelFormat::R32ui ? 4 : 16; }

// The push constants of every stage: the dispatch's constants, then the entry of the render
// parameters in their uniform buffer, always 0 (bindings.glsl says why it is pushed).
struct VulkanPushConstants {
  gpu::PassConstants pass;
  uint32_t paramsEntry;
};

// Device memory per path in flight: the queues of both backends and the deferred shade
// queue (shade.comp).
constexpr uint64_t kVulkanBytesPerPath = kBytesPerPath + sizeof(uint32_t);

// Storage for the queues, the paths' radiance and features and the pixels' sums, also read as
// texels (the TEXEL_VIEW rows of binding_table.h).
constexpr VkBufferUsageFlags kViewedStorageUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

}  // namespace

VulkanBackend::VulkanBackend(int deviceIndex, bool validation)
    : context_(std::make_unique<VulkanContext>(deviceIndex, validation)) {
  // The pipelines come with the first scene (loadScene), specialized to it: built here with
  // no features they were built again there, which cost lavapipe 0.9 s of a 2.2 s start-up
  // (the instanced scene; its shade pipeline alone takes 0.7 s with Mesa's cache warm).
  createLayouts();
  VkDevice device = context_->device;

  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, gpu::kBindingCount},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, gpu::kBindingCount},
                                  {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, gpu::kBindingCount}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = 3;
  poolInfo.pPoolSizes = sizes;
  VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &descriptorPool_));
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = descriptorPool_;
  setInfo.descriptorSetCount = 1;
  setInfo.pSetLayouts = &setLayout_;
  VK_CHECK(vkAllocateDescriptorSets(device, &setInfo, &descriptorSet_));

  VkCommandBufferAllocateInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cmdInfo.commandPool = context_->commandPool;
  cmdInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cmdInfo.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(device, &cmdInfo, &commandBuffer_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence_));
  if (context_->timestampsSupported) {
    VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = kMaxQueries;
    VK_CHECK(vkCreateQueryPool(device, &queryInfo, nullptr, &queryPool_));
  }
  countersReadback_ = VulkanBuffer(*context_, sizeof(gpu::QueueCounters), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  const std::vector<gpu::vec4> bsdfTableTexels = packBsdfTableQuads();
  const size_t bsdfTableBytes = bsdfTableTexels.size() * sizeof(gpu::vec4);
  bsdfTables_ = VulkanBuffer(*context_, bsdfTableBytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, false);
  bsdfTables_.upload(bsdfTableTexels.data(), bsdfTableBytes);
}

VulkanBackend::~VulkanBackend() {
  VkDevice device = context_->device;
  vkDeviceWaitIdle(device);
  if (queryPool_ != VK_NULL_HANDLE) {
    vkDestroyQueryPool(device, queryPool_, nullptr);
  }
  for (VkBufferView view : texelViews_) {
    vkDestroyBufferView(device, view, nullptr);
  }
  vkDestroyFence(device, fence_, nullptr);
  vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
  for (VkPipeline pipeline : pipelines_) {
    vkDestroyPipeline(device, pipeline, nullptr);
  }
  vkDestroyPipeline(device, microfacetShadePipeline_, nullptr);
  vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
  vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
  // Buffers are members and release themselves before context_ is destroyed.
  sceneBuffers_ = {};
  bsdfTables_ = {};
  params_ = {};
  rays_ = {};
  hits_ = {};
  shadowRays_ = {};
  pathRadiance_ = {};
  pathFeatures_ = {};
  deferredHits_ = {};
  counters_ = {};
  countersReadback_ = {};
  accumulation_ = {};
  accumulationReadback_ = {};
}

std::string VulkanBackend::deviceName() const {
  return std::string(context_->properties.deviceName) + " (Vulkan)";
}

uint32_t VulkanBackend::maxPathsInFlight() const {
  const VkPhysicalDeviceLimits& limits = context_->properties.limits;
  uint64_t byDispatch = uint64_t(limits.maxComputeWorkGroupCount[0]) * WP_WORKGROUP_SIZE;
  // The two ray queues share one buffer, bound whole as storage and as RGBA32UI texels; path
  // state may take half the memory, the rest is for the scene and the image.
  uint64_t byStorage = context_->limits.writable.bytes / (2 * sizeof(gpu::PathRay));
  uint64_t byTexels = uint64_t(limits.maxTexelBufferElements) / (2 * sizeof(gpu::PathRay) / 16);
  uint64_t byMemory = context_->limits.memory.bytes / 2 / kVulkanBytesPerPath;
  return uint32_t(std::min({byDispatch, byStorage, byTexels, byMemory, uint64_t(UINT32_MAX)}));
}

bool VulkanBackend::onCpu() const { return context_->onCpu(); }

uint64_t VulkanBackend::pathStateBytes(uint64_t maxPaths) const {
  return sceneBytes_ + sizeof(gpu::RenderParams) + maxPaths * kVulkanBytesPerPath + sizeof(gpu::QueueCounters);
}

uint64_t VulkanBackend::maxAccumulationPixels(uint32_t maxPaths) const {
  const DeviceLimits& limits = context_->limits;
  const uint64_t used = pathStateBytes(maxPaths);
  const uint64_t byMemory = limits.memory.bytes > used ? (limits.memory.bytes - used) / kAccumulationBytesPerPixel : 0;
  // Also read as RGBA32 texels (its TEXEL_VIEW row), a texel of each layer per pixel.
  const uint64_t byTexels = uint64_t(context_->properties.limits.maxTexelBufferElements) / WP_ACCUMULATION_LAYERS;
  return std::min({limits.writable.bytes / kAccumulationBytesPerPixel, byMemory, byTexels});
}

void VulkanBackend::createLayouts() {
  VkDevice device = context_->device;
  std::vector<VkDescriptorSetLayoutBinding> bindings(gpu::kBindingCount);
  for (uint32_t i = 0; i < gpu::kBindingCount; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = descriptorType(i);
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = gpu::kBindingCount;
  layoutInfo.pBindings = bindings.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device, &layoutInfo, nullptr, &setLayout_));

  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(VulkanPushConstants)};
  VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipelineLayoutInfo.setLayoutCount = 1;
  pipelineLayoutInfo.pSetLayouts = &setLayout_;
  pipelineLayoutInfo.pushConstantRangeCount = 1;
  pipelineLayoutInfo.pPushConstantRanges = &push;
  VK_CHECK(vkCreatePipelineLayout(device, &pipelineLayoutInfo, nullptr, &pipelineLayout_));
}

VkPipeline VulkanBackend::createPipeline(SpirvCode code, const SceneFeatures& features, uint32_t shadeClass) {
  VkDevice device = context_->device;
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = code.bytes;
  moduleInfo.pCode = code.words;
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(device, &moduleInfo, nullptr, &module));
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  // The constants in constant_id order, each 32 bits (VkBool32 or uint): the features of
  // prelude_glsl.h and the render's light selection, shade.comp's class and split, then the
  // traversal's stacks, top level, planes, spheres, the sky's map, punctual lights, the
  // render's feature passes and its sampler, the texture slots but the base colour's (a stage
  // without some of them ignores them, which Vulkan allows).
  const std::array<uint32_t, 25> constants = {
      features.alphaTested,       features.layered,
      features.baseColorTexture,  features.transmissive,
      features.microfacet,        features.metallic,
      features.emissive,          features.skySampled,
      render_.solidAngleSelection, shadeClass,
      splitShade_,                stacks_.inWorkgroupMemory,
      stacks_.topLevelEntries,    stacks_.bottomLevelEntries,
      features.instanced,         features.planes,
      features.spheres,           features.skyMap,
      features.punctual,          render_.featurePasses,
      render_.independentSampler, features.metallicRoughnessTexture,
      features.normalTexture,     features.emissiveTexture,
      features.extensionTextures};
  std::array<VkSpecializationMapEntry, constants.size()> entries;
  for (uint32_t id = 0; id < entries.size(); ++id) {
    entries[id] = {id, uint32_t(id * sizeof(uint32_t)), sizeof(uint32_t)};
  }
  const VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof(constants),
                                           constants.data()};
  info.stage.pSpecializationInfo = &specialization;
  info.layout = pipelineLayout_;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  VK_CHECK(result);
  return pipeline;
}

void VulkanBackend::buildPipelines(bool motion, bool respecialize) {
  // The pipelines to build, each into its slot: the shade stages first, the longest to
  // compile, so that the rest fill the other cores meanwhile.
  struct PipelineBuild {
    VkPipeline* slot;
    SpirvCode code;
    SceneFeatures features;
    uint32_t shadeClass;
  };
  std::vector<PipelineBuild> builds;
  const bool split = splitShade_;
  if (respecialize || motion != motion_ || (split && microfacetShadePipeline_ == VK_NULL_HANDLE)) {
    vkDestroyPipeline(context_->device, microfacetShadePipeline_, nullptr);
    microfacetShadePipeline_ = VK_NULL_HANDLE;
    if (split) {
      builds.push_back({&microfacetShadePipeline_, spirvFor(Kernel::Shade, motion), sceneFeatures_,
                        WP_SHADE_CLASS_MICROFACET});
    }
  }
  for (int k = 0; k < kKernelCount; ++k) {
    const SpirvCode code = spirvFor(Kernel(k), motion);
    if (pipelines_[k] == VK_NULL_HANDLE || respecialize || code.words != spirvFor(Kernel(k), motion_).words) {
      vkDestroyPipeline(context_->device, pipelines_[k], nullptr);
      pipelines_[k] = VK_NULL_HANDLE;  // so that a failure below leaves nothing to destroy twice
      // Split, shade is first the diffuse class's, which needs nothing of the materials' code.
      const bool diffuseShade = split && Kernel(k) == Kernel::Shade;
      builds.push_back({&pipelines_[k], code, diffuseShade ? sceneFeatures_.withNeeds(0) : sceneFeatures_,
                        WP_SHADE_CLASS_DIFFUSE});
    }
  }
  std::stable_partition(builds.begin(), builds.end(), [&](const PipelineBuild& b) {
    return b.slot == &microfacetShadePipeline_ || b.slot == &pipelines_[int(Kernel::Shade)];
  });
  // On every core at once: lavapipe compiles a pipeline on the thread that creates it. The
  // upload of --timings, which holds this, on two cores: the shared box (seven pipelines)
  // 317-333 -> 172-178 ms; the instanced scene (six, shade most of their time) 261-264 ->
  // 229-234 ms.
  forEachInParallel(uint32_t(builds.size()), [&](uint32_t i) {
    *builds[i].slot = createPipeline(builds[i].code, builds[i].features, builds[i].shadeClass);
  });
  motion_ = motion;
}

void VulkanBackend::loadScene(const GpuScene& scene) {
  vkDeviceWaitIdle(context_->device);
  // The stages for the first scene; then the other build of the stages that have two (still
  // or with motion blur) and stages specialized to the scene's features and shade classes
  // when those change: a scene like the last costs nothing. They are built in configure,
  // which knows the render's settings too, so that no stage is built twice.
  const bool motion = scene.moving();
  const SceneFeatures sceneFeatures = scene.features();
  const SceneFeatures features = specializeToScene_ ? sceneFeatures : SceneFeatures::everything();
  const bool split = splitShadeByMaterial_ && sceneFeatures.hasBothShadeClasses();
  const StackDevice stackDevice{context_->properties.limits.maxComputeSharedMemorySize, onCpu()};
  const StackPlacement stacks =
      specializeToScene_ ? placeStacks(scene.stackNeeds(), stackDevice, stacks_) : StackPlacement{};
  const bool respecialize = !(features == sceneFeatures_) || split != splitShade_ || !(stacks == stacks_);
  sceneFeatures_ = features;
  stacks_ = stacks;
  splitShade_ = split;
  pendingMotion_ = motion;
  pendingRespecialize_ = pendingRespecialize_ || respecialize;
  const auto arrays = sceneArrays(scene);
  const DeviceLimits& limits = context_->limits;
  const uint64_t bytes = checkSceneFits(limits, arrays);
  for (size_t i = 0; i < arrays.size(); ++i) {
    const uint64_t texel = texelBytes(kSceneBindings[i]);
    checkFits(limits, std::string("the scene's ") + arrays[i].name, arrays[i].bytes,
              {context_->properties.limits.maxTexelBufferElements * texel, "maxTexelBufferElements"},
              "render a smaller scene (fewer triangles, smaller textures or sky), or use --backend opencl");
  }
  sceneBytes_ = 0;  // nothing held while the old buffers go and the new ones come
  for (size_t i = 0; i < arrays.size(); ++i) {
    sceneBuffers_[i] = VulkanBuffer(*context_, arrays[i].bytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, false);
    sceneBuffers_[i].upload(arrays[i].data, arrays[i].bytes);
  }
  sceneBytes_ = bytes;
  if (params_.handle() != VK_NULL_HANDLE) {
    writeDescriptors();
  }
}

void VulkanBackend::configure(const gpu::RenderParams& params) {
  if (sceneBuffers_[0].handle() == VK_NULL_HANDLE) {
    throw Error("internal: VulkanBackend::configure called before loadScene");
  }
  uint32_t maxPaths = params.maxPaths;
  if (maxPaths > maxPathsInFlight()) {
    throw Error("internal: " + std::to_string(maxPaths) + " paths in flight exceed the device's " +
                std::to_string(maxPathsInFlight()));
  }
  const uint64_t accumulationBytes = uint64_t(params.pixelCount) * kAccumulationBytesPerPixel;
  checkPathStateFits(context_->limits, 2ull * maxPaths * sizeof(gpu::PathRay), params.pixelCount,
                     pathStateBytes(maxPaths) + accumulationBytes);
  vkDeviceWaitIdle(context_->device);
  // With every feature (specializeToScene_ false) the stages keep all of the render's code.
  const bool all = !specializeToScene_;
  const RenderSpecialization render{
      // The solid-angle light selection only for a render that uses it: lavapipe runs a
      // loop's body once even where no lane enters it.
      .solidAngleSelection = params.lightSelection == WP_LIGHT_SELECTION_SOLID_ANGLE || all,
      // The feature passes only for a render that keeps them: a few percent of shade's time
      // and half of accumulate's on lavapipe (docs/performance.md).
      .featurePasses = params.featurePasses != 0u || all,
      // The independent sampler only for a render that draws from it: each draw of a Sobol
      // render ran the PCG stream's code too (docs/performance.md).
      .independentSampler = params.samplerKind == WP_SAMPLER_INDEPENDENT || all};
  const bool respecialize = pendingRespecialize_ || render != render_;
  render_ = render;
  buildPipelines(pendingMotion_, respecialize);
  pendingRespecialize_ = false;
  params_ = VulkanBuffer(*context_, sizeof(params), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
  std::memcpy(params_.mapped(), &params, sizeof(params));

  bool resized = rays_.handle() == VK_NULL_HANDLE || hits_.size() < maxPaths * sizeof(gpu::HitRecord);
  if (resized) {
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    rays_ = VulkanBuffer(*context_, 2ull * maxPaths * sizeof(gpu::PathRay), kViewedStorageUsage, false);
    hits_ = VulkanBuffer(*context_, uint64_t(maxPaths) * sizeof(gpu::HitRecord), kViewedStorageUsage, false);
    shadowRays_ = VulkanBuffer(*context_, uint64_t(maxPaths) * sizeof(gpu::ShadowRay), kViewedStorageUsage, false);
    pathRadiance_ = VulkanBuffer(*context_, uint64_t(maxPaths) * sizeof(glm::vec4), kViewedStorageUsage, false);
    pathFeatures_ = VulkanBuffer(*context_, uint64_t(maxPaths) * sizeof(gpu::PathFeatures), kViewedStorageUsage, false);
    deferredHits_ = VulkanBuffer(*context_, uint64_t(maxPaths) * sizeof(uint32_t), storage, false);
    counters_ = VulkanBuffer(*context_, sizeof(gpu::QueueCounters),
                             storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, false);
  }
  pixelCount_ = params.pixelCount;
  accumulation_ = VulkanBuffer(*context_, accumulationBytes, kViewedStorageUsage, false);
  context_->runOnce([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, accumulation_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);  // empty queues (queues.h)
  });
  writeDescriptors();
}

void VulkanBackend::writeDescriptors() {
  std::array<const VulkanBuffer*, gpu::kBindingCount> buffers{};
  buffers[gpu::Binding::params] = &params_;
  buffers[gpu::Binding::rays] = buffers[gpu::Binding::raysTexelView] = &rays_;
  buffers[gpu::Binding::hits] = buffers[gpu::Binding::hitsTexelView] = &hits_;
  buffers[gpu::Binding::shadowRays] = buffers[gpu::Binding::shadowRaysTexelView] = &shadowRays_;
  buffers[gpu::Binding::pathRadiance] = buffers[gpu::Binding::pathRadianceTexelView] = &pathRadiance_;
  buffers[gpu::Binding::pathFeatures] = buffers[gpu::Binding::pathFeaturesTexelView] = &pathFeatures_;
  buffers[gpu::Binding::counters] = &counters_;
  buffers[gpu::Binding::deferredHits] = &deferredHits_;
  buffers[gpu::Binding::accumulation] = buffers[gpu::Binding::accumulationTexelView] = &accumulation_;
  buffers[gpu::Binding::bsdfTables] = &bsdfTables_;
  for (size_t i = 0; i < kSceneBindings.size(); ++i) {
    buffers[kSceneBindings[i]] = &sceneBuffers_[i];
  }
  for (VkBufferView view : texelViews_) {
    vkDestroyBufferView(context_->device, view, nullptr);
  }
  texelViews_.clear();
  std::array<VkDescriptorBufferInfo, gpu::kBindingCount> infos;
  std::array<VkBufferView, gpu::kBindingCount> views{};
  std::array<VkWriteDescriptorSet, gpu::kBindingCount> writes;
  for (uint32_t i = 0; i < gpu::kBindingCount; ++i) {
    VkDescriptorType type = descriptorType(i);
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = descriptorSet_;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = type;
    if (type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) {
      views[i] = texelView(*buffers[i], texelBytes(i) == 4 ? VK_FORMAT_R32_UINT : VK_FORMAT_R32G32B32A32_UINT);
      writes[i].pTexelBufferView = &views[i];
    } else {
      infos[i] = {buffers[i]->handle(), 0, VK_WHOLE_SIZE};
      writes[i].pBufferInfo = &infos[i];
    }
  }
  vkUpdateDescriptorSets(context_->device, gpu::kBindingCount, writes.data(), 0, nullptr);
}

VkBufferView VulkanBackend::texelView(const VulkanBuffer& buffer, VkFormat format) {
  // loadScene, maxPathsInFlight and maxAccumulationPixels keep every buffer within
  // maxTexelBufferElements.
  uint64_t bytesPerTexel = format == VK_FORMAT_R32_UINT ? 4 : 16;
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.handle();
  info.format = format;
  info.offset = 0;
  info.range = buffer.size() / bytesPerTexel * bytesPerTexel;
  VkBufferView view;
  VK_CHECK(vkCreateBufferView(context_->device, &info, nullptr, &view));
  texelViews_.push_back(view);
  return view;
}

void VulkanBackend::barrier(VkPipelineStageFlags dstStages, VkAccessFlags dstAccess) {
  VkMemoryBarrier memoryBarrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  memoryBarrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  memoryBarrier.dstAccessMask = dstAccess;
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dstStages, 0, 1, &memoryBarrier, 0,
                       nullptr, 0, nullptr);
}

void VulkanBackend::timestamp(int kernel) {
  if (queryPool_ == VK_NULL_HANDLE || queryKernels_.size() >= kMaxQueries) {
    return;
  }
  vkCmdWriteTimestamp(commandBuffer_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, queryPool_,
                      static_cast<uint32_t>(queryKernels_.size()));
  queryKernels_.push_back(kernel);
}

void VulkanBackend::beginPass(const PassShape&) {
  VK_CHECK(vkResetCommandBuffer(commandBuffer_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(commandBuffer_, &begin));
  // Order this pass after everything submitted before it (uploads, clears, earlier passes).
  VkMemoryBarrier memoryBarrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  memoryBarrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  memoryBarrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1,
                       &memoryBarrier, 0, nullptr, 0, nullptr);
  vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &descriptorSet_, 0,
                          nullptr);
  queryKernels_.clear();
  if (queryPool_ != VK_NULL_HANDLE) {
    vkCmdResetQueryPool(commandBuffer_, queryPool_, 0, kMaxQueries);
  }
  timestamp(-1);
  recordedDispatch_ = false;
}

void VulkanBackend::dispatch(const StageDispatch& stage) {
  const int k = static_cast<int>(stage.kernel);
  record(pipelines_[k], stage.constants, stage.size);
  if (stage.kernel == Kernel::Shade && splitShade_) {
    // Then the hits that the diffuse class deferred (shade.comp).
    record(microfacetShadePipeline_, stage.constants,
           {DispatchSize::Source::Queue, 0, WP_COUNTER_DEFERRED_SHADE_DISPATCH});
  }
  timestamp(k);
}

void VulkanBackend::record(VkPipeline pipeline, const gpu::PassConstants& constants, const DispatchSize& size) {
  if (recordedDispatch_) {
    // Each dispatch reads what the previous ones wrote, including indirect dispatch sizes.
    barrier(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
  }
  recordedDispatch_ = true;
  vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  const VulkanPushConstants push{constants, 0u};
  vkCmdPushConstants(commandBuffer_, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  // The barrier before every dispatch makes arguments written by an earlier stage visible.
  switch (size.source) {
    case DispatchSize::Source::Host:
      vkCmdDispatch(commandBuffer_, (size.threads + WP_WORKGROUP_SIZE - 1) / WP_WORKGROUP_SIZE, 1, 1);
      break;
    case DispatchSize::Source::Queue:
      vkCmdDispatchIndirect(commandBuffer_, counters_.handle(), size.argumentsWord * sizeof(uint32_t));
      break;
  }
}

PassResult VulkanBackend::endPass() {
  barrier(VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferCopy region{0, 0, sizeof(gpu::QueueCounters)};
  vkCmdCopyBuffer(commandBuffer_, counters_.handle(), countersReadback_.handle(), 1, &region);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                       nullptr, 0, nullptr);
  VK_CHECK(vkEndCommandBuffer(commandBuffer_));

  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commandBuffer_;
  VK_CHECK(vkResetFences(context_->device, 1, &fence_));
  VK_CHECK(vkQueueSubmit(context_->queue, 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(context_->device, 1, &fence_, VK_TRUE, UINT64_MAX));

  gpu::QueueCounters counters;
  std::memcpy(&counters, countersReadback_.mapped(), sizeof(counters));
  PassResult result;
  result.extensionRays = gpu::tracedRays(counters);
  result.shadowRays = gpu::tracedShadowRays(counters);
  if (queryPool_ != VK_NULL_HANDLE && queryKernels_.size() > 1) {
    std::vector<uint64_t> ticks(queryKernels_.size());
    VK_CHECK(vkGetQueryPoolResults(context_->device, queryPool_, 0, static_cast<uint32_t>(ticks.size()),
                                   ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    double msPerTick = context_->properties.limits.timestampPeriod * 1e-6;
    for (size_t i = 1; i < ticks.size(); ++i) {
      result.kernelMs[queryKernels_[i]] += double(ticks[i] - ticks[i - 1]) * msPerTick;
    }
  }
  return result;
}

Accumulation VulkanBackend::readAccumulation() {
  Accumulation result;
  accumulation_.download(uint64_t(WP_ACCUMULATION_LAYERS) * pixelCount_ * sizeof(glm::vec4), accumulationReadback_,
                         [&](const void* bytes) {
                           result = accumulationOfBuffer(static_cast<const glm::vec4*>(bytes), pixelCount_);
                         });
  return result;
}

void VulkanBackend::writeAccumulation(const Accumulation& accumulation) {
  std::vector<glm::vec4> buffer = accumulationBuffer(accumulation, pixelCount_);
  accumulation_.upload(buffer.data(), buffer.size() * sizeof(glm::vec4));
}

}  // namespace wp
