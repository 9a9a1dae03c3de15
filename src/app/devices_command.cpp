// `wavepath devices`: lists the devices each backend can render on, numbered as --device
// counts them with that backend. A backend without devices is said to have none; the
// command fails only when neither has one.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "app/backend_factory.h"
#include "app/commands.h"
#include "backend/opencl/opencl_devices.h"
#include "backend/vulkan/vulkan_context.h"
#include "core/error.h"

namespace wp {
namespace {

double gibibytes(uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0 * 1024.0); }

// Prints the Vulkan devices and returns them.
std::vector<VulkanDeviceInfo> printVulkanDevices() {
  std::printf("Vulkan devices:\n");
  std::vector<VulkanDeviceInfo> devices;
  try {
    devices = listVulkanDevices();
  } catch (const Error& e) {
    std::printf("  none: %s\n", e.what());
    return {};
  }
  for (size_t i = 0; i < devices.size(); ++i) {
    const VulkanDeviceInfo& d = devices[i];
    std::printf("  %zu: %s (%s), Vulkan %u.%u, %s, %.1f GiB device-local memory%s\n", i, d.name.c_str(),
                d.type.c_str(), VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion),
                d.driver.c_str(), gibibytes(d.deviceLocalBytes),
                d.missing.empty() ? "" : ("; unusable: lacks " + d.missing).c_str());
    std::printf("     buffers: %s written (%s), %s read (maxMemoryAllocationSize), %u texels (maxTexelBufferElements)\n",
                byteSize(d.limits.writable.bytes).c_str(), d.limits.writable.name.c_str(),
                byteSize(d.limits.sceneArray.bytes).c_str(), d.maxTexelBufferElements);
  }
  return devices;
}

// Prints the OpenCL devices of every platform and returns them.
std::vector<OpenClDeviceInfo> printOpenClDevices() {
  std::printf("OpenCL devices:\n");
  std::vector<OpenClDeviceInfo> devices;
  try {
    devices = listOpenClDevices();
  } catch (const Error& e) {
    std::printf("  none: %s\n", e.what());
    return {};
  }
  if (devices.empty()) {
    std::printf("  none: the OpenCL platforms have no devices\n");
  }
  for (size_t i = 0; i < devices.size(); ++i) {
    const OpenClDeviceInfo& d = devices[i];
    std::string missing = missingRequirement(d);
    std::printf("  %zu: %s (%s) on %s, %u compute units, %.1f GiB global memory, buffers up to %s, driver %s%s\n", i,
                d.name.c_str(), d.type.c_str(), d.platformName.c_str(), d.computeUnits, gibibytes(d.globalMemoryBytes),
                byteSize(d.maxAllocationBytes).c_str(), d.driverVersion.c_str(),
                missing.empty() ? "" : ("; unusable: lacks " + missing).c_str());
  }
  return devices;
}

}  // namespace

CLI::App* addDevicesCommand(CLI::App& app) {
  return app.add_subcommand("devices",
                            "List the Vulkan and OpenCL devices wavepath can render on (use the index with --device)");
}

int runDevices() {
  const std::string word = defaultBackendWord();  // a bad WAVEPATH_BACKEND fails before the lists
  const std::vector<VulkanDeviceInfo> vulkan = printVulkanDevices();
  const std::vector<OpenClDeviceInfo> openCl = printOpenClDevices();
  if (vulkan.empty() && openCl.empty()) {
    std::fflush(stdout);
    throw Error("no Vulkan or OpenCL device found; install mesa-vulkan-drivers (lavapipe) or pocl-opencl-icd, or a "
                "GPU driver");
  }
  const AutoBackend chosen = autoBackend(vulkan, openCl);
  auto title = [](const std::string& backend) { return backend == "vulkan" ? "Vulkan" : "OpenCL"; };
  if (word == "auto") {
    std::printf("Renders without --backend run on %s (--backend auto: %s)\n", title(chosen.name),
                chosen.reason.c_str());
  } else {
    std::printf("Renders without --backend run on %s (WAVEPATH_BACKEND); --backend auto would pick %s: %s\n",
                title(word), title(chosen.name), chosen.reason.c_str());
  }
  return 0;
}

}  // namespace wp
