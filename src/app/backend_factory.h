// Chooses and creates the compute backend: the one place that knows which backends exist.
#pragma once

#include <memory>
#include <string>

#include "render/backend.h"

namespace wp {

struct BackendChoice {
  std::string name = "vulkan";  // "vulkan" or "opencl"
  int device = -1;              // index into that backend's device list; < 0: the most capable
  bool validate = false;        // Vulkan: the Khronos validation layer; OpenCL: see OpenClBackend
  std::string clDispatch = "readback";  // OpenCL queue sizing: "readback" or "max" (see ClDispatch)
};

// Creates the backend `choice` names on its device; throws wp::Error when it cannot.
std::unique_ptr<Backend> createBackend(const BackendChoice& choice);

// Throws wp::Error when validation, if on, found errors during the render (the Vulkan
// layer's messages are printed as they come).
void checkValidation(const BackendChoice& choice);

}  // namespace wp
