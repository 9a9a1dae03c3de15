// Window presentation: upload the display image, copy it into the swapchain image, draw ImGui
// over it in a render pass, present; one frame in flight (the path tracer is the slow part).
#include "app/viewer/presenter.h"

#include <algorithm>
#include <cstring>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_vulkan.h>

#include "app/viewer/window.h"
#include "backend/vulkan/vk_check.h"
#include "backend/vulkan/vulkan_context.h"
#include "core/error.h"

namespace wp {
namespace {

// Formats whose bytes the host fills directly (packDisplay already applied the transfer
// curve, so the swapchain must not encode again: UNORM, not SRGB).
bool isBgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM; }
bool isRgba(VkFormat f) { return f == VK_FORMAT_R8G8B8A8_UNORM; }

void checkImGuiVk(VkResult result) { VK_CHECK(result); }

PFN_vkVoidFunction loadForImGui(const char* name, void* instance) {
  return vkGetInstanceProcAddr(static_cast<VkInstance>(instance), name);
}

void swapRedBlue(uint32_t* pixels, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    uint32_t p = pixels[i];
    pixels[i] = (p & 0xff00ff00u) | ((p & 0xffu) << 16) | ((p >> 16) & 0xffu);
  }
}

}  // namespace

Presenter::Presenter(GLFWwindow* window, bool validation) : window_(window) {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) {
    failNoWindow("the Vulkan driver has no surface extension for this window system");
  }
  try {
    instance_ = createVulkanInstance(validation, std::vector<const char*>(names, names + count));
    if (validation) {
      messenger_ = createValidationMessenger(instance_);
    }
    VK_CHECK(glfwCreateWindowSurface(instance_, window_, nullptr, &surface_));
    createDevice();
    createSwapchain();
    initImGui();
  } catch (...) {
    destroy();
    throw;
  }
}

Presenter::~Presenter() { destroy(); }

void Presenter::destroy() {
  if (device_ != VK_NULL_HANDLE) {
    vk_.vkDeviceWaitIdle(device_);
    if (imguiReady_) {
      ImGui_ImplVulkan_Shutdown();
      imguiReady_ = false;
    }
    destroySwapchain();
    for (VkBuffer b : {upload_, readback_}) vk_.vkDestroyBuffer(device_, b, nullptr);
    for (VkDeviceMemory m : {uploadMemory_, readbackMemory_}) vk_.vkFreeMemory(device_, m, nullptr);
    vk_.vkDestroyDescriptorPool(device_, descriptorPool_, nullptr);
    vk_.vkDestroyRenderPass(device_, renderPass_, nullptr);
    vk_.vkDestroySemaphore(device_, imageAcquired_, nullptr);
    vk_.vkDestroyFence(device_, frameDone_, nullptr);
    vk_.vkDestroyCommandPool(device_, commandPool_, nullptr);
    vk_.vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (messenger_ != VK_NULL_HANDLE) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
  surface_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
}

void Presenter::createDevice() {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
  for (VkPhysicalDevice candidate : devices) {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
    for (uint32_t i = 0; i < familyCount && physicalDevice_ == VK_NULL_HANDLE; ++i) {
      VkBool32 presents = VK_FALSE;
      VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(candidate, i, surface_, &presents));
      if (presents && (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
        physicalDevice_ = candidate;
        queueFamily_ = i;
      }
    }
  }
  if (physicalDevice_ == VK_NULL_HANDLE) {
    failNoWindow("no Vulkan device can present to this window");
  }
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties);
  deviceName_ = properties.deviceName;
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  const char* extensions[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = extensions;
  VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));
  volkLoadDeviceTable(&vk_, device_);
  vk_.vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VK_CHECK(vk_.vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_));
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = commandPool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VK_CHECK(vk_.vkAllocateCommandBuffers(device_, &alloc, &commandBuffer_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VK_CHECK(vk_.vkCreateFence(device_, &fenceInfo, nullptr, &frameDone_));
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vk_.vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &imageAcquired_));
}

void Presenter::createSwapchain() {
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physicalDevice_, surface_, &caps));
  extent_ = caps.currentExtent;
  if (extent_.width == UINT32_MAX) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    extent_ = {std::clamp(uint32_t(w), caps.minImageExtent.width, caps.maxImageExtent.width),
               std::clamp(uint32_t(h), caps.minImageExtent.height, caps.maxImageExtent.height)};
  }
  if (extent_.width == 0 || extent_.height == 0) {
    return;  // minimised: no swapchain until the window has an area again
  }
  if (renderPass_ == VK_NULL_HANDLE) {
    uint32_t formatCount = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice_, surface_, &formatCount, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(formatCount);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice_, surface_, &formatCount, formats.data()));
    auto it = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
      return (isBgra(f.format) || isRgba(f.format)) && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    });
    if (it == formats.end()) {
      failNoWindow("the window's Vulkan surface offers no 8-bit UNORM RGBA or BGRA format");
    }
    format_ = *it;
    swapRedBlue_ = isBgra(format_.format);

    VkAttachmentDescription color{};
    color.format = format_.format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the copied image, ImGui drawn over it
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // In: after the copy into the image. Out: before a capture's copy out of it.
    VkSubpassDependency deps[2] = {};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[0].srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rp.attachmentCount = 1;
    rp.pAttachments = &color;
    rp.subpassCount = 1;
    rp.pSubpasses = &subpass;
    rp.dependencyCount = 2;
    rp.pDependencies = deps;
    VK_CHECK(vk_.vkCreateRenderPass(device_, &rp, nullptr, &renderPass_));
  }

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = std::max(caps.minImageCount, 2u);
  if (caps.maxImageCount > 0) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  // Transfer source only for window captures, where the surface allows it.
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  canCapture_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
    failNoWindow("the window's Vulkan surface cannot be a copy destination");
  }
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  info.clipped = VK_TRUE;
  VK_CHECK(vk_.vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_));

  uint32_t imageCount = 0;
  VK_CHECK(vk_.vkGetSwapchainImagesKHR(device_, swapchain_, &imageCount, nullptr));
  images_.resize(imageCount);
  VK_CHECK(vk_.vkGetSwapchainImagesKHR(device_, swapchain_, &imageCount, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    views_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk_.vkCreateImageView(device_, &view, nullptr, &views_.back()));
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = renderPass_;
    fb.attachmentCount = 1;
    fb.pAttachments = &views_.back();
    fb.width = extent_.width;
    fb.height = extent_.height;
    fb.layers = 1;
    framebuffers_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk_.vkCreateFramebuffer(device_, &fb, nullptr, &framebuffers_.back()));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    renderDone_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk_.vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &renderDone_.back()));
  }
}

void Presenter::destroySwapchain() {
  for (VkFramebuffer f : framebuffers_) vk_.vkDestroyFramebuffer(device_, f, nullptr);
  for (VkImageView v : views_) vk_.vkDestroyImageView(device_, v, nullptr);
  for (VkSemaphore s : renderDone_) vk_.vkDestroySemaphore(device_, s, nullptr);
  framebuffers_.clear();
  views_.clear();
  renderDone_.clear();
  images_.clear();
  vk_.vkDestroySwapchainKHR(device_, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

void Presenter::initImGui() {
  // ImGui's Vulkan backend is built without prototypes (volk owns them): give it the loader.
  if (!ImGui_ImplVulkan_LoadFunctions(loadForImGui, instance_)) {
    throw Error("ImGui could not load its Vulkan functions; reinstall libvulkan1");
  }
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 4;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VK_CHECK(vk_.vkCreateDescriptorPool(device_, &poolInfo, nullptr, &descriptorPool_));
  if (renderPass_ == VK_NULL_HANDLE) {
    failNoWindow("the window has no area to draw in");
  }
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = instance_;
  info.PhysicalDevice = physicalDevice_;
  info.Device = device_;
  info.QueueFamily = queueFamily_;
  info.Queue = queue_;
  info.DescriptorPool = descriptorPool_;
  info.MinImageCount = 2;
  info.ImageCount = uint32_t(images_.size());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImGuiVk;
  ImGui_ImplVulkan_Init(&info, renderPass_);
  imguiReady_ = true;

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vk_.vkBeginCommandBuffer(commandBuffer_, &begin));
  ImGui_ImplVulkan_CreateFontsTexture(commandBuffer_);
  VK_CHECK(vk_.vkEndCommandBuffer(commandBuffer_));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commandBuffer_;
  VK_CHECK(vk_.vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE));
  VK_CHECK(vk_.vkQueueWaitIdle(queue_));
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void Presenter::ensureBuffer(VkBuffer& buffer, VkDeviceMemory& memory, void*& mapped, VkDeviceSize& size,
                             VkDeviceSize needed, VkBufferUsageFlags usage) {
  if (size >= needed) {
    return;
  }
  vk_.vkDestroyBuffer(device_, buffer, nullptr);
  vk_.vkFreeMemory(device_, memory, nullptr);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = needed;
  info.usage = usage;
  VK_CHECK(vk_.vkCreateBuffer(device_, &info, nullptr, &buffer));
  VkMemoryRequirements req;
  vk_.vkGetBufferMemoryRequirements(device_, buffer, &req);
  const VkMemoryPropertyFlags flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  uint32_t type = UINT32_MAX;
  for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount && type == UINT32_MAX; ++i) {
    if ((req.memoryTypeBits & (1u << i)) && (memoryProperties_.memoryTypes[i].propertyFlags & flags) == flags) {
      type = i;
    }
  }
  if (type == UINT32_MAX) {
    throw Error("the presenting Vulkan device '" + deviceName_ + "' has no host-visible memory; use 'wavepath render'");
  }
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = type;
  VK_CHECK(vk_.vkAllocateMemory(device_, &alloc, nullptr, &memory));
  VK_CHECK(vk_.vkBindBufferMemory(device_, buffer, memory, 0));
  VK_CHECK(vk_.vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped));
  size = needed;
}

void Presenter::record(VkCommandBuffer cmd, uint32_t index, uint32_t width, uint32_t height, bool capture) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vk_.vkBeginCommandBuffer(cmd, &begin));
  VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toCopy.image = images_[index];
  toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  // Chained to the acquire semaphore, which the submit waits for at the transfer stage.
  vk_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                           nullptr, 1, &toCopy);
  uint32_t copyW = std::min(width, extent_.width), copyH = std::min(height, extent_.height);
  if (copyW != extent_.width || copyH != extent_.height) {
    // The image does not cover the window (it is being resized): black around it.
    VkClearColorValue black{};
    vk_.vkCmdClearColorImage(cmd, images_[index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1,
                             &toCopy.subresourceRange);
    VkImageMemoryBarrier afterClear = toCopy;
    afterClear.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    afterClear.oldLayout = afterClear.newLayout;
    vk_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &afterClear);
  }
  if (copyW > 0 && copyH > 0) {
    VkBufferImageCopy region{};
    region.bufferRowLength = width;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {copyW, copyH, 1};
    vk_.vkCmdCopyBufferToImage(cmd, upload_, images_[index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  }
  VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rp.renderPass = renderPass_;
  rp.framebuffer = framebuffers_[index];
  rp.renderArea.extent = extent_;
  vk_.vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vk_.vkCmdEndRenderPass(cmd);
  if (capture) {
    VkImageMemoryBarrier toRead = toCopy;
    toRead.srcAccessMask = 0;  // the render pass's outgoing dependency made its writes visible
    toRead.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    toRead.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    toRead.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    vk_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toRead);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vk_.vkCmdCopyImageToBuffer(cmd, images_[index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_, 1, &region);
    VkImageMemoryBarrier toPresent = toCopy;
    toPresent.srcAccessMask = 0;  // a read needs no availability; presentation waits on the semaphore
    toPresent.dstAccessMask = 0;
    toPresent.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    toPresent.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_;
    toHost.size = VK_WHOLE_SIZE;
    vk_.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 1,
                             &toHost, 1, &toPresent);
  }
  VK_CHECK(vk_.vkEndCommandBuffer(cmd));
}

void Presenter::present(const std::vector<uint32_t>& pixels, uint32_t width, uint32_t height,
                        std::vector<uint32_t>* capture, uint32_t* captureWidth, uint32_t* captureHeight) {
  int fbW = 0, fbH = 0;
  glfwGetFramebufferSize(window_, &fbW, &fbH);
  if (fbW <= 0 || fbH <= 0) {
    return;
  }
  VK_CHECK(vk_.vkWaitForFences(device_, 1, &frameDone_, VK_TRUE, UINT64_MAX));
  if (swapchain_ == VK_NULL_HANDLE || stale_ || uint32_t(fbW) != extent_.width || uint32_t(fbH) != extent_.height) {
    VK_CHECK(vk_.vkDeviceWaitIdle(device_));
    destroySwapchain();
    createSwapchain();
    stale_ = false;
    if (swapchain_ == VK_NULL_HANDLE) {
      return;
    }
  }
  VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
  ensureBuffer(upload_, uploadMemory_, uploadMapped_, uploadSize_, std::max<VkDeviceSize>(bytes, 4),
               VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(uploadMapped_, pixels.data(), bytes);
  if (swapRedBlue_) {
    swapRedBlue(static_cast<uint32_t*>(uploadMapped_), pixels.size());
  }
  bool capturing = capture != nullptr;
  if (capturing && !canCapture_) {
    throw Error("this window's Vulkan surface cannot be read back, so --window-capture cannot work here; use "
                "--screenshot for the rendered image");
  }
  if (capturing) {
    ensureBuffer(readback_, readbackMemory_, readbackMapped_, readbackSize_,
                 VkDeviceSize(extent_.width) * extent_.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  }

  uint32_t index = 0;
  VkResult acquired = vk_.vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, imageAcquired_, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = true;  // recreate at the next frame
    return;
  }
  if (acquired != VK_SUBOPTIMAL_KHR) {
    VK_CHECK(acquired);
  }
  VK_CHECK(vk_.vkResetFences(device_, 1, &frameDone_));
  record(commandBuffer_, index, width, height, capturing);
  VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &imageAcquired_;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commandBuffer_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &renderDone_[index];
  VK_CHECK(vk_.vkQueueSubmit(queue_, 1, &submit, frameDone_));
  VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  presentInfo.waitSemaphoreCount = 1;
  presentInfo.pWaitSemaphores = &renderDone_[index];
  presentInfo.swapchainCount = 1;
  presentInfo.pSwapchains = &swapchain_;
  presentInfo.pImageIndices = &index;
  VkResult presented = vk_.vkQueuePresentKHR(queue_, &presentInfo);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
  } else {
    VK_CHECK(presented);
  }
  if (capturing) {
    VK_CHECK(vk_.vkWaitForFences(device_, 1, &frameDone_, VK_TRUE, UINT64_MAX));
    const uint32_t* window = static_cast<const uint32_t*>(readbackMapped_);
    capture->assign(window, window + size_t(extent_.width) * extent_.height);
    if (swapRedBlue_) {
      swapRedBlue(capture->data(), capture->size());
    }
    *captureWidth = extent_.width;
    *captureHeight = extent_.height;
  }
}

}  // namespace wp
