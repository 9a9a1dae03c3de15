// A Vulkan buffer with its own memory allocation (the renderer needs only a few dozen).
#pragma once

#include <volk.h>

namespace wp {

class VulkanContext;

class VulkanBuffer {
public:
  VulkanBuffer() = default;
  // Host-visible buffers are mapped for their whole life; others prefer device-local memory.
  // A size of 0 allocates a small placeholder so the buffer can still be bound.
  VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible);
  ~VulkanBuffer();
  VulkanBuffer(VulkanBuffer&& other) noexcept;
  VulkanBuffer& operator=(VulkanBuffer&& other) noexcept;
  VulkanBuffer(const VulkanBuffer&) = delete;
  VulkanBuffer& operator=(const VulkanBuffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }

  // Copies `bytes` from host memory into the buffer through a staging buffer and waits.
  void upload(const void* data, VkDeviceSize bytes);
  // Copies the buffer's first `bytes` into host memory through a staging buffer and waits.
  void download(void* data, VkDeviceSize bytes);
  // The same through `staging`, a host-visible buffer kept by the caller and grown when too
  // small: for repeated readbacks, where allocating a fresh one each time costs more than the
  // copy (the viewer's frames: 4x at 1280x720 on lavapipe).
  void download(void* data, VkDeviceSize bytes, VulkanBuffer& staging);

private:
  void release();

  VulkanContext* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace wp
