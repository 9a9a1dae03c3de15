// An OpenCL context and in-order command queue (with profiling) on the chosen device.
#pragma once

#include <CL/cl.h>

#include "backend/opencl/opencl_devices.h"

namespace wp {

class OpenClContext {
public:
  // deviceIndex < 0 picks the most capable device (see chooseOpenClDevice).
  explicit OpenClContext(int deviceIndex);
  ~OpenClContext();
  OpenClContext(const OpenClContext&) = delete;
  OpenClContext& operator=(const OpenClContext&) = delete;

  OpenClDeviceInfo device;
  cl_context context = nullptr;
  cl_command_queue queue = nullptr;
};

}  // namespace wp
