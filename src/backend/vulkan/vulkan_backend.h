// The Vulkan implementation of the wavefront Backend: one compute pipeline per stage,
// a sample pass recorded into one command buffer with indirect dispatches.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "backend/vulkan/stack_placement.h"
#include "backend/vulkan/vulkan_buffer.h"
#include "backend/vulkan/vulkan_context.h"
#include "bvh/gpu_scene.h"
#include "render/backend.h"

namespace wp {

// A stage's SPIR-V, embedded at build time (shaders/CMakeLists.txt).
struct SpirvCode {
  const uint32_t* words;
  size_t bytes;
};

class VulkanBackend final : public Backend {
public:
  // deviceIndex < 0 picks the best device; see VulkanContext for `validation`.
  VulkanBackend(int deviceIndex, bool validation);
  ~VulkanBackend() override;

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
  // Whether the next loadScene of a scene with both shade classes (SceneFeatures::
  // hasBothShadeClasses) builds a shade pipeline for each (shade.comp), as it does by
  // default, or one for the whole scene: the images are the same, only the time differs
  // (docs/performance.md).
  void splitShadeByMaterial(bool split) { splitShadeByMaterial_ = split; }
  // Whether the next loadScene and configure specialize the stages to the scene's features,
  // its trees' stacks and the render's light selection (prelude_glsl.h), as they do by
  // default, or build them with every feature and the stacks in each invocation's own arrays,
  // as C++ and OpenCL run them: the images are the same, only the time differs.
  void specializeToScene(bool specialize) { specializeToScene_ = specialize; }
  // Where the stages built for the last scene keep the traversal's stacks.
  const StackPlacement& stackPlacement() const { return stacks_; }

private:
  // Device memory of the scene and of maxPaths paths in flight, without the accumulation.
  uint64_t pathStateBytes(uint64_t maxPaths) const;
  void createLayouts();
  // A compute pipeline of the SPIR-V `code` with the shared layout, specialized to
  // `features` (prelude_glsl.h) and, for shade, to shade class `shadeClass` (WP_SHADE_CLASS_*)
  // of a split shade or not (splitShade_).
  VkPipeline createPipeline(SpirvCode code, const SceneFeatures& features, uint32_t shadeClass);
  // (Re)builds the stages for `motion` (WP_MOTION_BLUR or not) specialized to sceneFeatures_,
  // stacks_, splitShade_ and render_: those whose build changed, or all with respecialize.
  void buildPipelines(bool motion, bool respecialize);
  // Records a dispatch of `pipeline`, after a barrier on what the dispatches before wrote.
  void record(VkPipeline pipeline, const gpu::PassConstants& constants, const DispatchSize& size);
  void writeDescriptors();
  // A view of the whole buffer as texels of `format` (RGBA32UI or R32UI) (kept until the descriptors are rewritten).
  VkBufferView texelView(const VulkanBuffer& buffer, VkFormat format);
  void barrier(VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);
  void timestamp(int kernel);

  std::unique_ptr<VulkanContext> context_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
  std::array<VkPipeline, kKernelCount> pipelines_{};  // none until the first loadScene
  bool motion_ = false;  // pipelines_ hold the stages built with WP_MOTION_BLUR
  SceneFeatures sceneFeatures_;  // and specialized to these
  StackPlacement stacks_;        // with the traversal's stacks here
  // and to what the render uses (configure; the WP_RENDER_* constants of prelude_glsl.h)
  struct RenderSpecialization {
    bool solidAngleSelection = false;  // lights selected by solid angle
    bool featurePasses = true;         // feature passes recorded
    bool independentSampler = true;    // draws from the independent sampler
    bool operator==(const RenderSpecialization&) const = default;
  } render_;
  // What loadScene asks of the stages, which configure builds: the motion build or not, and
  // whether the loaded scene needs them specialized anew.
  bool pendingMotion_ = false;
  bool pendingRespecialize_ = false;
  // Whether shade is split by shade class: pipelines_[Shade] then shades the diffuse class
  // and microfacetShadePipeline_ the hits it deferred.
  bool splitShade_ = false;
  VkPipeline microfacetShadePipeline_ = VK_NULL_HANDLE;
  bool splitShadeByMaterial_ = true;
  bool specializeToScene_ = true;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkQueryPool queryPool_ = VK_NULL_HANDLE;
  std::vector<VkBufferView> texelViews_;

  std::array<VulkanBuffer, kSceneBindings.size()> sceneBuffers_;  // for kSceneBindings[i]
  VulkanBuffer bsdfTables_;  // gpu::kBsdfTables as quads (bsdf_table_lookup.h)
  VulkanBuffer params_;
  VulkanBuffer rays_;
  VulkanBuffer hits_;
  VulkanBuffer shadowRays_;
  VulkanBuffer pathRadiance_;
  VulkanBuffer pathFeatures_;
  VulkanBuffer deferredHits_;  // the deferred shade queue (queues.h)
  VulkanBuffer counters_;
  VulkanBuffer countersReadback_;
  VulkanBuffer accumulation_;
  VulkanBuffer accumulationReadback_;  // staging kept across readAccumulation calls (the viewer's frames)
  uint32_t pixelCount_ = 0;
  uint64_t sceneBytes_ = 0;  // of the loaded scene's arrays

  // Kernel of each timestamp written in the current pass (query i ends kernel i's span).
  std::vector<int> queryKernels_;
  bool recordedDispatch_ = false;
};

}  // namespace wp
