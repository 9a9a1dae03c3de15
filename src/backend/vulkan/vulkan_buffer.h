// A Vulkan buffer with its own memory allocation (the renderer needs only a few dozen).
#pragma once

#include <volk.h>

#include <functional>

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

  // Copies `bytes` from host memory into the buffer and waits: in place where its memory is
  // host-visible (lavapipe's and an integrated GPU's device-local memory), else through a
  // staging buffer. In place saves a copy and the staging buffer's fresh pages: lavapipe's
  // upload of the instanced scene (--timings) 304-317 -> 243-260 ms.
  void upload(const void* data, VkDeviceSize bytes);
  // Waits for the device's writes, then hands the buffer's first `bytes` to `read` in host
  // memory: in place where its memory is host-visible and cached (lavapipe's image write of a
  // 1920x1080 render 385-419 -> 317-358 ms), else copied into `staging`, a host-visible buffer
  // kept by the caller and grown when too small: for repeated readbacks, where allocating a
  // fresh one each time costs more than the copy (the viewer's frames: 4x at 1280x720 on
  // lavapipe). `read` copies what it keeps: the pointer is valid only during the call.
  void download(VkDeviceSize bytes, VulkanBuffer& staging, const std::function<void(const void*)>& read);

private:
  void release();
  bool hasMemory(VkMemoryPropertyFlags flags) const;
  // The buffer's memory mapped for the host (mapped once, kept until the buffer goes).
  void* mapInPlace();

  VulkanContext* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  VkMemoryPropertyFlags memoryFlags_ = 0;  // of the memory type allocated
};

}  // namespace wp
