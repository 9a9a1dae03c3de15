// Vulkan instance, device selection, compute queue and validation messages.
#include "backend/vulkan/vulkan_context.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>

#include "backend/vulkan/vk_check.h"
#include "core/device_rank.h"
#include "core/error.h"

namespace wp {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
std::atomic<uint32_t> gValidationErrors{0};

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  bool isError = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  if (isError) {
    ++gValidationErrors;
  }
  std::fprintf(stderr, "wavepath: vulkan validation %s: %s\n", isError ? "error" : "warning", data->pMessage);
  return VK_FALSE;
}

void initLoader() {
  static bool loaded = false;
  if (loaded) {
    return;
  }
  if (volkInitialize() != VK_SUCCESS) {
    throw Error("the Vulkan loader (libvulkan.so.1) was not found; install libvulkan1 and a driver "
                "(mesa-vulkan-drivers for lavapipe)");
  }
  loaded = true;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& layer : layers) {
    if (std::strcmp(layer.layerName, name) == 0) {
      return true;
    }
  }
  return false;
}

}  // namespace

VkInstance createVulkanInstance(bool validation, const std::vector<const char*>& requiredExtensions) {
  initLoader();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "wavepath";
  app.apiVersion = VK_API_VERSION_1_1;

  std::vector<const char*> layers;
  std::vector<const char*> extensions = requiredExtensions;
  VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  if (validation) {
    if (!hasLayer(kValidationLayer)) {
      throw Error(std::string("validation was requested but the layer ") + kValidationLayer +
                  " is not installed; install vulkan-validationlayers or unset WAVEPATH_VALIDATION");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validation ? &features : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED) {
    throw Error("no Vulkan driver could be loaded (" + std::string(vk::resultName(result)) +
                "); install mesa-vulkan-drivers (lavapipe) or a GPU driver");
  }
  VK_CHECK(result);
  volkLoadInstanceOnly(instance);
  return instance;
}

VkDebugUtilsMessengerEXT createValidationMessenger(VkInstance instance) {
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDebugUtilsMessengerEXT(instance, &messengerInfo, nullptr, &messenger));
  return messenger;
}

namespace {

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  if (devices.empty()) {
    throw Error("no Vulkan device found; install mesa-vulkan-drivers (lavapipe) or a GPU driver");
  }
  return devices;
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

// Index of a queue family with compute, or -1.
int computeQueueFamily(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

// The stages need Vulkan 1.1 with subgroup ballot, vote and arithmetic in compute shaders
// (queue appends, traversal); returns what is missing, or an empty string.
std::string missingRequirement(VkPhysicalDevice device) {
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(device, &props);
  if (props.properties.apiVersion < VK_API_VERSION_1_1) {
    return "Vulkan 1.1";
  }
  if (computeQueueFamily(device) < 0) {
    return "a compute queue";
  }
  const VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
  if (!(subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) ||
      (subgroup.supportedOperations & needed) != needed) {
    return "subgroup ballot, vote and arithmetic in compute shaders";
  }
  return "";
}

const ByteLimit& smaller(const ByteLimit& a, const ByteLimit& b) { return a.bytes <= b.bytes ? a : b; }

VulkanDeviceInfo describe(VkPhysicalDevice device) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  driver.pNext = &maintenance3;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &driver;
  vkGetPhysicalDeviceProperties2(device, &props);
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(device, &memory);
  VulkanDeviceInfo info;
  info.name = props.properties.deviceName;
  info.type = typeName(props.properties.deviceType);
  info.rank = typeRank(props.properties.deviceType);
  info.gpu = info.rank >= typeRank(VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU);
  info.missing = missingRequirement(device);
  info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  info.apiVersion = props.properties.apiVersion;
  uint64_t largestHeap = 0;
  for (uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
    if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) {
      info.deviceLocalBytes += memory.memoryHeaps[i].size;
      largestHeap = std::max<uint64_t>(largestHeap, memory.memoryHeaps[i].size);
    }
  }
  // Every buffer is one allocation, from the device-local heap where there is one.
  const VkPhysicalDeviceLimits& l = props.properties.limits;
  const ByteLimit allocation{maintenance3.maxMemoryAllocationSize, "maxMemoryAllocationSize"};
  info.limits.device = "Vulkan device '" + info.name + "'";
  info.limits.writable = smaller({l.maxStorageBufferRange, "maxStorageBufferRange"}, allocation);
  info.limits.sceneArray = allocation;
  info.limits.memory = {largestHeap, "its device-local heap"};
  info.maxTexelBufferElements = l.maxTexelBufferElements;
  return info;
}

}  // namespace

std::vector<VulkanDeviceInfo> listVulkanDevices() {
  VkInstance instance = createVulkanInstance(false, {});
  std::vector<VulkanDeviceInfo> infos;
  try {
    for (VkPhysicalDevice device : physicalDevices(instance)) {
      infos.push_back(describe(device));
    }
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  return infos;
}

int mostCapableUsableDevice(const std::vector<VulkanDeviceInfo>& devices) {
  return mostCapableUsable(devices, [](const VulkanDeviceInfo& d) { return d.missing.empty(); });
}

VulkanContext::VulkanContext(int deviceIndex, bool validation) {
  instance = createVulkanInstance(validation, {});
  try {
    if (validation) {
      messenger_ = createValidationMessenger(instance);
    }

    std::vector<VkPhysicalDevice> devices = physicalDevices(instance);
    if (deviceIndex >= static_cast<int>(devices.size())) {
      throw Error("--device " + std::to_string(deviceIndex) + " does not exist: there are " +
                  std::to_string(devices.size()) + " Vulkan devices; run 'wavepath devices' to list them");
    }
    int best = deviceIndex;
    if (best < 0) {
      std::vector<VulkanDeviceInfo> infos;
      for (VkPhysicalDevice device : devices) infos.push_back(describe(device));
      // None usable: the first, whose missing requirement the error below names.
      best = std::max(0, mostCapableUsableDevice(infos));
    }
    physicalDevice = devices[best];
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
    const VulkanDeviceInfo info = describe(physicalDevice);
    limits = withBufferCap(info.limits);
    if (!info.missing.empty()) {
      throw Error(std::string("Vulkan device '") + properties.deviceName + "' lacks " + info.missing +
                  "; pick another with --device (see 'wavepath devices') or update its driver");
    }
    queueFamily = static_cast<uint32_t>(computeQueueFamily(physicalDevice));

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    timestampsSupported = families[queueFamily].timestampValidBits > 0 && properties.limits.timestampPeriod > 0.0f;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    VK_CHECK(vkCreateDevice(physicalDevice, &deviceInfo, nullptr, &device));
    volkLoadDevice(device);
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
  } catch (...) {
    destroy();
    throw;
  }
}

VulkanContext::~VulkanContext() { destroy(); }

void VulkanContext::destroy() {
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    if (commandPool != VK_NULL_HANDLE) {
      vkDestroyCommandPool(device, commandPool, nullptr);
    }
    vkDestroyDevice(device, nullptr);
    device = VK_NULL_HANDLE;
  }
  if (messenger_ != VK_NULL_HANDLE) {
    vkDestroyDebugUtilsMessengerEXT(instance, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance != VK_NULL_HANDLE) {
    vkDestroyInstance(instance, nullptr);
    instance = VK_NULL_HANDLE;
  }
}

uint32_t VulkanContext::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
  int fallback = -1;
  for (uint32_t i = 0; i < memoryProperties.memoryTypeCount; ++i) {
    VkMemoryPropertyFlags flags = memoryProperties.memoryTypes[i].propertyFlags;
    if (!(typeBits & (1u << i)) || (flags & required) != required) {
      continue;
    }
    if ((flags & preferred) == preferred) {
      return i;
    }
    if (fallback < 0) {
      fallback = static_cast<int>(i);
    }
  }
  if (fallback < 0) {
    throw Error(std::string("Vulkan device '") + properties.deviceName +
                "' has no suitable memory type for a buffer; try another --device");
  }
  return static_cast<uint32_t>(fallback);
}

VkCommandBuffer VulkanContext::beginOnce() {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = commandPool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  return cmd;
}

void VulkanContext::endOnce(VkCommandBuffer cmd) {
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkQueueSubmit(queue, 1, &submit, VK_NULL_HANDLE));
  VK_CHECK(vkQueueWaitIdle(queue));
  vkFreeCommandBuffers(device, commandPool, 1, &cmd);
}

uint32_t VulkanContext::validationErrorCount() { return gValidationErrors.load(); }

}  // namespace wp
