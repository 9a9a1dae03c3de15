// Shows host-made RGBA8 images in a window through its own Vulkan device and swapchain, with
// Dear ImGui drawn on top. Independent of the compute backend, so every backend shows alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <volk.h>

struct GLFWwindow;

namespace wp {

class Presenter {
public:
  // Creates an instance (with the validation layer when `validation`), a surface for
  // `window`, the first device that can present to it, a swapchain and ImGui's Vulkan
  // renderer. Create it after the compute backend: it loads volk's instance functions for
  // its own instance (loader trampolines, valid for every instance) and keeps its device
  // functions in a table of its own, so the backend's device functions stay as they were.
  // Throws wp::Error (pointing to `wavepath render`) when no device can present.
  Presenter(GLFWwindow* window, bool validation);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  std::string deviceName() const { return deviceName_; }

  // Shows `pixels` (width x height RGBA8, R in the lowest byte, top row first) in the top-left
  // corner of the window, black around it, with the ImGui frame ended by the caller
  // (ImGui::Render) drawn on top. With `capture`, also returns the whole window as shown,
  // in the same pixel format, in captureWidth x captureHeight. Recreates the swapchain when
  // the window changed size; skips the frame while the window is minimised.
  void present(const std::vector<uint32_t>& pixels, uint32_t width, uint32_t height, std::vector<uint32_t>* capture,
               uint32_t* captureWidth, uint32_t* captureHeight);

private:
  void destroy();
  void createDevice();
  void createSwapchain();
  void destroySwapchain();
  void initImGui();
  void ensureBuffer(VkBuffer& buffer, VkDeviceMemory& memory, void*& mapped, VkDeviceSize& size, VkDeviceSize needed,
                    VkBufferUsageFlags usage);
  void record(VkCommandBuffer cmd, uint32_t imageIndex, uint32_t width, uint32_t height, bool capture);

  GLFWwindow* window_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VolkDeviceTable vk_{};
  uint32_t queueFamily_ = 0;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::string deviceName_;
  VkPhysicalDeviceMemoryProperties memoryProperties_{};

  VkSurfaceFormatKHR format_{};
  bool swapRedBlue_ = false;  // the swapchain stores B, G, R, A
  bool canCapture_ = false;   // the swapchain images can be a copy source
  bool stale_ = false;        // out of date or suboptimal: recreate before the next frame
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> renderDone_;  // one per swapchain image: presentation waits on it
  VkRenderPass renderPass_ = VK_NULL_HANDLE;

  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
  VkFence frameDone_ = VK_NULL_HANDLE;
  VkSemaphore imageAcquired_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  bool imguiReady_ = false;

  // Host-visible buffers: the image to show, and the window read back for a capture.
  VkBuffer upload_ = VK_NULL_HANDLE;
  VkDeviceMemory uploadMemory_ = VK_NULL_HANDLE;
  void* uploadMapped_ = nullptr;
  VkDeviceSize uploadSize_ = 0;
  VkBuffer readback_ = VK_NULL_HANDLE;
  VkDeviceMemory readbackMemory_ = VK_NULL_HANDLE;
  void* readbackMapped_ = nullptr;
  VkDeviceSize readbackSize_ = 0;
};

}  // namespace wp
