// OpenCL context and command queue creation.
#include "backend/opencl/opencl_context.h"

#include "backend/opencl/cl_check.h"

namespace wp {

OpenClContext::OpenClContext(int deviceIndex) : device(chooseOpenClDevice(deviceIndex)) {
  cl_context_properties properties[] = {CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(device.platform),
                                        0};
  cl_int result = CL_SUCCESS;
  context = clCreateContext(properties, 1, &device.device, nullptr, nullptr, &result);
  CL_CHECK(result);
  // Kernel timestamps (PassResult::kernelMs) come from profiling events.
  queue = clCreateCommandQueue(context, device.device, CL_QUEUE_PROFILING_ENABLE, &result);
  if (result != CL_SUCCESS) {
    clReleaseContext(context);
  }
  CL_CHECK(result);
}

OpenClContext::~OpenClContext() {
  clFinish(queue);
  clReleaseCommandQueue(queue);
  clReleaseContext(context);
}

}  // namespace wp
