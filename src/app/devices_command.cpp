// `wavepath devices`: lists the devices each backend can render on.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "backend/vulkan/vulkan_context.h"

namespace wp {

CLI::App* addDevicesCommand(CLI::App& app) {
  return app.add_subcommand("devices", "List the devices wavepath can render on (use the index with --device)");
}

int runDevices() {
  std::vector<VulkanDeviceInfo> devices = listVulkanDevices();
  std::printf("Vulkan devices:\n");
  for (size_t i = 0; i < devices.size(); ++i) {
    const VulkanDeviceInfo& d = devices[i];
    std::printf("  %zu: %s (%s), Vulkan %u.%u, %s, %.1f GiB device-local memory\n", i, d.name.c_str(), d.type.c_str(),
                VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion), d.driver.c_str(),
                double(d.deviceLocalBytes) / (1024.0 * 1024.0 * 1024.0));
  }
  return 0;
}

}  // namespace wp
