// Backend creation by name.
#include "app/backend_factory.h"

#include "backend/opencl/opencl_backend.h"
#include "backend/vulkan/vulkan_backend.h"
#include "core/error.h"

namespace wp {

std::unique_ptr<Backend> createBackend(const BackendChoice& choice) {
  if (choice.name == "vulkan") {
    return std::make_unique<VulkanBackend>(choice.device, choice.validate);
  }
  if (choice.name == "opencl") {
    ClDispatch dispatch = choice.clDispatch == "max" ? ClDispatch::Max : ClDispatch::Readback;
    return std::make_unique<OpenClBackend>(choice.device, dispatch, choice.validate);
  }
  throw Error("unknown backend '" + choice.name + "'; use --backend vulkan or --backend opencl");
}

void checkValidation(const BackendChoice& choice) {
  if (choice.name == "vulkan" && VulkanContext::validationErrorCount() > 0) {
    throw Error("the Vulkan validation layer reported " + std::to_string(VulkanContext::validationErrorCount()) +
                " errors (printed above); no image was written");
  }
}

}  // namespace wp
