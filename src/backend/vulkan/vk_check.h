// VK_CHECK: turns a failed Vulkan call into a wp::Error naming the call, file:line and result.
#pragma once

#include <volk.h>

namespace wp::vk {

const char* resultName(VkResult result);
// Throws wp::Error when result is not VK_SUCCESS.
void check(VkResult result, const char* call, const char* file, int line);

}  // namespace wp::vk

#define VK_CHECK(call) ::wp::vk::check((call), #call, __FILE__, __LINE__)
