// OpenCL error names and the error thrown by CL_CHECK.
#include "backend/opencl/cl_check.h"

#include <CL/cl_ext.h>

#include <string>

#include "core/error.h"

namespace wp::cl {

const char* errorName(cl_int error) {
  switch (error) {
#define WP_ERROR(name) \
  case name: return #name;
    WP_ERROR(CL_SUCCESS)
    WP_ERROR(CL_DEVICE_NOT_FOUND)
    WP_ERROR(CL_DEVICE_NOT_AVAILABLE)
    WP_ERROR(CL_COMPILER_NOT_AVAILABLE)
    WP_ERROR(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    WP_ERROR(CL_OUT_OF_RESOURCES)
    WP_ERROR(CL_OUT_OF_HOST_MEMORY)
    WP_ERROR(CL_PROFILING_INFO_NOT_AVAILABLE)
    WP_ERROR(CL_MEM_COPY_OVERLAP)
    WP_ERROR(CL_BUILD_PROGRAM_FAILURE)
    WP_ERROR(CL_MAP_FAILURE)
    WP_ERROR(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
    WP_ERROR(CL_COMPILE_PROGRAM_FAILURE)
    WP_ERROR(CL_LINKER_NOT_AVAILABLE)
    WP_ERROR(CL_LINK_PROGRAM_FAILURE)
    WP_ERROR(CL_INVALID_VALUE)
    WP_ERROR(CL_INVALID_DEVICE_TYPE)
    WP_ERROR(CL_INVALID_PLATFORM)
    WP_ERROR(CL_INVALID_DEVICE)
    WP_ERROR(CL_INVALID_CONTEXT)
    WP_ERROR(CL_INVALID_QUEUE_PROPERTIES)
    WP_ERROR(CL_INVALID_COMMAND_QUEUE)
    WP_ERROR(CL_INVALID_HOST_PTR)
    WP_ERROR(CL_INVALID_MEM_OBJECT)
    WP_ERROR(CL_INVALID_BINARY)
    WP_ERROR(CL_INVALID_BUILD_OPTIONS)
    WP_ERROR(CL_INVALID_PROGRAM)
    WP_ERROR(CL_INVALID_PROGRAM_EXECUTABLE)
    WP_ERROR(CL_INVALID_KERNEL_NAME)
    WP_ERROR(CL_INVALID_KERNEL_DEFINITION)
    WP_ERROR(CL_INVALID_KERNEL)
    WP_ERROR(CL_INVALID_ARG_INDEX)
    WP_ERROR(CL_INVALID_ARG_VALUE)
    WP_ERROR(CL_INVALID_ARG_SIZE)
    WP_ERROR(CL_INVALID_KERNEL_ARGS)
    WP_ERROR(CL_INVALID_WORK_DIMENSION)
    WP_ERROR(CL_INVALID_WORK_GROUP_SIZE)
    WP_ERROR(CL_INVALID_WORK_ITEM_SIZE)
    WP_ERROR(CL_INVALID_GLOBAL_OFFSET)
    WP_ERROR(CL_INVALID_EVENT_WAIT_LIST)
    WP_ERROR(CL_INVALID_EVENT)
    WP_ERROR(CL_INVALID_OPERATION)
    WP_ERROR(CL_INVALID_BUFFER_SIZE)
    WP_ERROR(CL_INVALID_GLOBAL_WORK_SIZE)
    WP_ERROR(CL_INVALID_PROPERTY)
    WP_ERROR(CL_PLATFORM_NOT_FOUND_KHR)
#undef WP_ERROR
    default: return "an unknown OpenCL error";
  }
}

void check(cl_int error, const char* call, const char* file, int line) {
  if (error == CL_SUCCESS) {
    return;
  }
  std::string hint =
      error == CL_MEM_OBJECT_ALLOCATION_FAILURE || error == CL_OUT_OF_RESOURCES || error == CL_OUT_OF_HOST_MEMORY
          ? "; lower --max-paths or the image size"
      : error == CL_DEVICE_NOT_AVAILABLE ? "; the device is busy or disabled, pick another with --device"
                                         : "; check the OpenCL driver installation ('clinfo' lists what it finds)";
  throw Error(std::string("OpenCL call ") + call + " failed with " + errorName(error) + " (" + std::to_string(error) +
              ") at " + file + ":" + std::to_string(line) + hint);
}

}  // namespace wp::cl
