// Vulkan buffers and staging copies.
#include "backend/vulkan/vulkan_buffer.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "backend/vulkan/vk_check.h"
#include "backend/vulkan/vulkan_context.h"
#include "core/huge_pages.h"

namespace wp {

VulkanBuffer::VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible)
    : context_(&context), size_(std::max<VkDeviceSize>(size, 16)) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size_;
  info.usage = usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(context.device, &info, nullptr, &buffer_));

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(context.device, buffer_, &requirements);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex =
      hostVisible ? context.memoryType(requirements.memoryTypeBits,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                       VK_MEMORY_PROPERTY_HOST_CACHED_BIT)
                  : context.memoryType(requirements.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkResult result = vkAllocateMemory(context.device, &alloc, nullptr, &memory_);
  if (result != VK_SUCCESS) {
    release();
    VK_CHECK(result);
  }
  VK_CHECK(vkBindBufferMemory(context.device, buffer_, memory_, 0));
  memoryFlags_ = context.memoryProperties.memoryTypes[alloc.memoryTypeIndex].propertyFlags;
  if (hostVisible) {
    VK_CHECK(vkMapMemory(context.device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  }
  // On a CPU device the memory is a fresh block of the process's heap that the first upload or
  // stage touches page by page: huge pages make that one fault per 2 MiB (core/huge_pages.h;
  // the instanced scene's upload on lavapipe, its pipelines' build included, 0.55-0.61 ->
  // 0.22-0.26 s with the operator new of large_allocations.cpp).
  if (context.onCpu() && hasMemory(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)) {
    adviseHugePages(mapInPlace(), size_);
  }
}

VulkanBuffer::~VulkanBuffer() { release(); }

VulkanBuffer::VulkanBuffer(VulkanBuffer&& other) noexcept { *this = std::move(other); }

VulkanBuffer& VulkanBuffer::operator=(VulkanBuffer&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
    memoryFlags_ = std::exchange(other.memoryFlags_, 0);
  }
  return *this;
}

void VulkanBuffer::release() {
  if (context_ == nullptr) {
    return;
  }
  if (buffer_ != VK_NULL_HANDLE) {
    vkDestroyBuffer(context_->device, buffer_, nullptr);
  }
  if (memory_ != VK_NULL_HANDLE) {
    vkFreeMemory(context_->device, memory_, nullptr);
  }
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  memoryFlags_ = 0;
}

bool VulkanBuffer::hasMemory(VkMemoryPropertyFlags flags) const { return (memoryFlags_ & flags) == flags; }

void* VulkanBuffer::mapInPlace() {
  if (mapped_ == nullptr) {
    VK_CHECK(vkMapMemory(context_->device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  }
  return mapped_;
}

void VulkanBuffer::upload(const void* data, VkDeviceSize bytes) {
  if (bytes == 0) {
    return;
  }
  if (hasMemory(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)) {
    // Written in place once the queue is idle; the next submission sees the writes.
    VK_CHECK(vkQueueWaitIdle(context_->queue));
    std::memcpy(mapInPlace(), data, bytes);
    return;
  }
  VulkanBuffer staging(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::memcpy(staging.mapped(), data, bytes);
  context_->runOnce([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &region);
  });
}

void VulkanBuffer::download(VkDeviceSize bytes, VulkanBuffer& staging, const std::function<void(const void*)>& read) {
  if (bytes == 0) {
    return;
  }
  // Read in place where the host can read this memory quickly (cached); otherwise copied into
  // `staging` first.
  const bool inPlace = hasMemory(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                                 VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
  if (!inPlace && staging.size() < bytes) {
    staging = VulkanBuffer(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  }
  context_->runOnce([&](VkCommandBuffer cmd) {
    // Make every earlier shader and transfer write visible to the copy, or to the host.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = inPlace ? VK_ACCESS_HOST_READ_BIT : VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         inPlace ? VK_PIPELINE_STAGE_HOST_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    if (inPlace) {
      return;
    }
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, buffer_, staging.handle(), 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                         0, nullptr);
  });
  read(inPlace ? mapInPlace() : staging.mapped());
}

}  // namespace wp
