// Vulkan result names and the error thrown by VK_CHECK.
#include "backend/vulkan/vk_check.h"

#include <string>

#include "core/error.h"

namespace wp::vk {

const char* resultName(VkResult result) {
  switch (result) {
#define WP_RESULT(name) \
  case name: return #name;
    WP_RESULT(VK_SUCCESS)
    WP_RESULT(VK_NOT_READY)
    WP_RESULT(VK_TIMEOUT)
    WP_RESULT(VK_INCOMPLETE)
    WP_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    WP_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    WP_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    WP_RESULT(VK_ERROR_DEVICE_LOST)
    WP_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    WP_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    WP_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    WP_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    WP_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    WP_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    WP_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    WP_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    WP_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    WP_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
    WP_RESULT(VK_SUBOPTIMAL_KHR)
#undef WP_RESULT
    default: return "VK_ERROR_UNKNOWN";
  }
}

void check(VkResult result, const char* call, const char* file, int line) {
  if (result == VK_SUCCESS) {
    return;
  }
  std::string hint = result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY
                         ? "; lower --max-paths or the image size"
                     : result == VK_ERROR_DEVICE_LOST ? "; the GPU driver reset the device"
                                                      : "; check the Vulkan driver installation";
  throw Error(std::string("Vulkan call ") + call + " failed with " + resultName(result) + " at " + file + ":" +
              std::to_string(line) + hint);
}

}  // namespace wp::vk
