// Chooses and creates the compute backend: the one place that knows which backends exist.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "backend/opencl/opencl_devices.h"
#include "backend/vulkan/vulkan_context.h"
#include "render/backend.h"

namespace wp {

struct BackendChoice {
  std::string name = "vulkan";  // "vulkan" or "opencl" (chooseBackendName resolves "auto")
  int device = -1;              // index into that backend's device list; < 0: the most capable
  bool validate = false;        // Vulkan: the Khronos validation layer; OpenCL: see OpenClBackend
  std::string clDispatch = "readback";  // OpenCL queue sizing: "readback" or "max" (see ClDispatch)
};

// The backend `--backend auto` renders on, and why, in words for `wavepath devices`.
struct AutoBackend {
  std::string name;    // "vulkan" or "opencl"
  std::string reason;
};

// What `auto` picks from the devices each backend offers (either list may be empty): Vulkan
// where it has a usable GPU, which runs the stages fastest (on an NVIDIA H200 1.2-1.3x OpenCL);
// otherwise OpenCL where it has a usable device, a GPU with an OpenCL driver alone or a CPU
// through PoCL, whose traversal runs a ray per thread where lavapipe's SIMD lanes wait for
// each other (1.1-1.8x lavapipe's speed on the benchmark's scenes: docs/performance.md);
// otherwise Vulkan, whose CPU device (lavapipe) or error line then serves.
AutoBackend autoBackend(const std::vector<VulkanDeviceInfo>& vulkan, const std::vector<OpenClDeviceInfo>& openCl);

// --backend's word where the flag is not given: the environment's WAVEPATH_BACKEND ("vulkan",
// "opencl" or "auto") where set, so a machine or a farm's jobs can fix it, else "auto".
// Throws wp::Error for any other WAVEPATH_BACKEND.
std::string defaultBackendWord();

// The backend a command runs on: `flag` (--backend's "vulkan", "opencl" or "auto"; empty
// when not given, then defaultBackendWord), with "auto" resolved by autoBackend from the
// devices found here.
std::string chooseBackendName(const std::string& flag);

// Creates the backend `choice` names on its device; throws wp::Error when it cannot.
std::unique_ptr<Backend> createBackend(const BackendChoice& choice);

// Throws wp::Error when validation, if on, found errors during the render (the Vulkan
// layer's messages are printed as they come).
void checkValidation(const BackendChoice& choice);

}  // namespace wp
