// Vulkan instance, device and compute queue, with the validation layer on request.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <volk.h>

#include "render/device_limits.h"

namespace wp {

struct VulkanDeviceInfo {
  std::string name;
  std::string type;    // "discrete GPU", "integrated GPU", "CPU", ...
  bool gpu = false;    // a discrete, integrated or virtual GPU (not a CPU implementation such as lavapipe)
  int rank = 0;        // preference when no --device is given: discrete, integrated, virtual GPU, CPU, other
  std::string missing;  // what it lacks to run the stages (Vulkan 1.1, subgroup operations...); empty: nothing
  std::string driver;  // driver name and version text
  uint32_t apiVersion = 0;
  uint64_t deviceLocalBytes = 0;
  DeviceLimits limits;  // as the device reports them (no testing cap)
  uint32_t maxTexelBufferElements = 0;
};

// A Vulkan 1.1 instance with `extensions` (and, with `validation`, the Khronos validation
// layer with synchronization validation and debug utils); loads volk's instance functions
// for it. Throws wp::Error when there is no loader, driver or (requested) layer.
VkInstance createVulkanInstance(bool validation, const std::vector<const char*>& extensions);
// Prints and counts (validationErrorCount) the validation layer's warnings and errors on
// `instance`, which must have been created with validation.
VkDebugUtilsMessengerEXT createValidationMessenger(VkInstance instance);

// Lists every Vulkan device; throws wp::Error when there is no loader or no device.
std::vector<VulkanDeviceInfo> listVulkanDevices();

// The index of the best-ranked device of `devices` that lacks nothing, or -1: the device a
// render takes without --device (VulkanContext), and the one `--backend auto` weighs.
int mostCapableUsableDevice(const std::vector<VulkanDeviceInfo>& devices);

class VulkanContext {
public:
  // deviceIndex < 0 picks the most capable device (discrete, then integrated, virtual, CPU).
  // With `validation`, the Khronos validation layer runs with synchronization validation and
  // every message it reports is printed and counted (see validationErrorCount).
  VulkanContext(int deviceIndex, bool validation);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  // Index of a memory type allowed by typeBits that has all `required` flags; prefers one
  // that also has `preferred`. Throws when none exists.
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred = 0) const;

  // Whether the device is the CPU itself (lavapipe): its device memory is the process's own.
  bool onCpu() const { return properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

  // Records commands with `record` into a one-time command buffer, submits it and waits.
  template <typename Record>
  void runOnce(Record&& record) {
    VkCommandBuffer cmd = beginOnce();
    record(cmd);
    endOnce(cmd);
  }

  // Messages of severity error reported by the validation layer so far (all contexts).
  static uint32_t validationErrorCount();

  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memoryProperties{};
  DeviceLimits limits;  // the device's, with the testing cap (withBufferCap)
  bool timestampsSupported = false;

private:
  void destroy();
  VkCommandBuffer beginOnce();
  void endOnce(VkCommandBuffer cmd);

  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

}  // namespace wp
