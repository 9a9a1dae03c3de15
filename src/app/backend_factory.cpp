// Backend creation by name, and the choice `--backend auto` makes.
#include "app/backend_factory.h"

#include <cstdlib>

#include "backend/opencl/opencl_backend.h"
#include "backend/vulkan/vulkan_backend.h"
#include "core/error.h"

namespace wp {
namespace {

// The GPU Vulkan renders on without --device, or null where that device is not a GPU (a
// usable GPU always ranks above a CPU implementation).
const VulkanDeviceInfo* usableVulkanGpu(const std::vector<VulkanDeviceInfo>& vulkan) {
  const int best = mostCapableUsableDevice(vulkan);
  return best >= 0 && vulkan[best].gpu ? &vulkan[best] : nullptr;
}

// The devices a backend has here: none where it has no loader, driver or device.
std::vector<VulkanDeviceInfo> vulkanDevicesOrNone() {
  try {
    return listVulkanDevices();
  } catch (const Error&) {
    return {};
  }
}

std::vector<OpenClDeviceInfo> openClDevicesOrNone() {
  try {
    return listOpenClDevices();
  } catch (const Error&) {
    return {};
  }
}

}  // namespace

AutoBackend autoBackend(const std::vector<VulkanDeviceInfo>& vulkan, const std::vector<OpenClDeviceInfo>& openCl) {
  if (const VulkanDeviceInfo* gpu = usableVulkanGpu(vulkan)) return {"vulkan", "Vulkan has a GPU, " + gpu->name};
  const int bestIndex = mostCapableUsableDevice(openCl);  // the device OpenCL would take
  const OpenClDeviceInfo* best = bestIndex >= 0 ? &openCl[bestIndex] : nullptr;
  if (!best) return {"vulkan", openCl.empty() ? "OpenCL has no device" : "OpenCL has no usable device"};
  const std::string vulkanLacks = vulkan.empty() ? "Vulkan has no device" : "Vulkan has no GPU";
  const std::string why = best->type == "CPU" ? ", which traces faster than a Vulkan CPU device" : "";
  return {"opencl", vulkanLacks + ", and OpenCL has " + best->name + why};
}

std::string defaultBackendWord() {
  const char* environment = std::getenv("WAVEPATH_BACKEND");
  const std::string word = environment && *environment ? environment : "auto";
  if (word != "auto" && word != "vulkan" && word != "opencl") {
    throw Error("WAVEPATH_BACKEND is '" + word + "', not a backend; set it to vulkan, opencl or auto, or unset it");
  }
  return word;
}

std::string chooseBackendName(const std::string& flag) {
  const std::string name = flag.empty() ? defaultBackendWord() : flag;
  if (name != "auto") return name;
  // A GPU on Vulkan settles it without asking OpenCL, whose platforms take longer to list.
  const std::vector<VulkanDeviceInfo> vulkan = vulkanDevicesOrNone();
  if (usableVulkanGpu(vulkan)) return "vulkan";
  return autoBackend(vulkan, openClDevicesOrNone()).name;
}

std::unique_ptr<Backend> createBackend(const BackendChoice& choice) {
  if (choice.name == "vulkan") {
    return std::make_unique<VulkanBackend>(choice.device, choice.validate);
  }
  if (choice.name == "opencl") {
    ClDispatch dispatch = choice.clDispatch == "max" ? ClDispatch::Max : ClDispatch::Readback;
    return std::make_unique<OpenClBackend>(choice.device, dispatch, choice.validate);
  }
  throw Error("unknown backend '" + choice.name + "'; use --backend vulkan, opencl or auto");
}

void checkValidation(const BackendChoice& choice) {
  if (choice.name == "vulkan" && VulkanContext::validationErrorCount() > 0) {
    throw Error("the Vulkan validation layer reported " + std::to_string(VulkanContext::validationErrorCount()) +
                " errors (printed above); no image was written");
  }
}

}  // namespace wp
