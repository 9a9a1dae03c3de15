// OpenCL device enumeration, requirements and default choice.
#include "backend/opencl/opencl_devices.h"

#include <CL/cl_ext.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "backend/opencl/cl_check.h"
#include "core/device_rank.h"
#include "core/error.h"
#include "shaders/common/layout.h"

namespace wp {
namespace {

std::string deviceString(cl_device_id device, cl_device_info param) {
  size_t size = 0;
  CL_CHECK(clGetDeviceInfo(device, param, 0, nullptr, &size));
  std::string text(size, '\0');
  CL_CHECK(clGetDeviceInfo(device, param, size, text.data(), nullptr));
  text.resize(text.find('\0') == std::string::npos ? text.size() : text.find('\0'));
  return text;
}

template <typename T>
T deviceValue(cl_device_id device, cl_device_info param) {
  T value{};
  CL_CHECK(clGetDeviceInfo(device, param, sizeof(T), &value, nullptr));
  return value;
}

std::string platformName(cl_platform_id platform) {
  size_t size = 0;
  CL_CHECK(clGetPlatformInfo(platform, CL_PLATFORM_NAME, 0, nullptr, &size));
  std::string text(size, '\0');
  CL_CHECK(clGetPlatformInfo(platform, CL_PLATFORM_NAME, size, text.data(), nullptr));
  text.resize(text.find('\0') == std::string::npos ? text.size() : text.find('\0'));
  return text;
}

OpenClDeviceInfo describe(cl_platform_id platform, cl_device_id device) {
  OpenClDeviceInfo info;
  info.platform = platform;
  info.device = device;
  info.platformName = platformName(platform);
  info.name = deviceString(device, CL_DEVICE_NAME);
  info.driverVersion = deviceString(device, CL_DRIVER_VERSION);
  info.version = deviceString(device, CL_DEVICE_VERSION);
  info.languageVersion = deviceString(device, CL_DEVICE_OPENCL_C_VERSION);
  info.computeUnits = deviceValue<cl_uint>(device, CL_DEVICE_MAX_COMPUTE_UNITS);
  info.globalMemoryBytes = deviceValue<cl_ulong>(device, CL_DEVICE_GLOBAL_MEM_SIZE);
  info.maxAllocationBytes = deviceValue<cl_ulong>(device, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  info.maxWorkGroupSize = deviceValue<size_t>(device, CL_DEVICE_MAX_WORK_GROUP_SIZE);
  info.compilerAvailable = deviceValue<cl_bool>(device, CL_DEVICE_COMPILER_AVAILABLE) == CL_TRUE;
  cl_device_type type = deviceValue<cl_device_type>(device, CL_DEVICE_TYPE);
  if (type & CL_DEVICE_TYPE_GPU) {
    info.type = "GPU";
    info.rank = 3;
  } else if (type & CL_DEVICE_TYPE_ACCELERATOR) {
    info.type = "accelerator";
    info.rank = 2;
  } else if (type & CL_DEVICE_TYPE_CPU) {
    info.type = "CPU";
    info.rank = 1;
  } else {
    info.type = "other";
  }
  return info;
}

// The (major, minor) of a version string "OpenCL C 1.2 ..." after `prefix`, or (0, 0).
std::pair<int, int> versionAfter(const std::string& text, const std::string& prefix) {
  int major = 0;
  int minor = 0;
  if (text.rfind(prefix, 0) != 0 || std::sscanf(text.c_str() + prefix.size(), "%d.%d", &major, &minor) != 2) {
    return {0, 0};
  }
  return {major, minor};
}

}  // namespace

constexpr const char* kPoclWorkGroupMethod = "POCL_WORK_GROUP_METHOD";

std::string poclWorkGroupMethod() {
  const char* method = std::getenv(kPoclWorkGroupMethod);
  return method != nullptr ? method : "";
}

std::vector<OpenClDeviceInfo> listOpenClDevices() {
  // PoCL 3.1 (Debian 12), left to itself, runs a work-group as a loop over its work-items that
  // it vectorizes ("loopvec"), and the traversal's loops diverge from one work-item to the
  // next: with the binary BVH, on the Cornell box (512x512, 64 spp, 2 cores) extend took
  // 31.1 s and connect 17.2 s so, 5.0 s and 2.2 s with POCL_WORK_GROUP_METHOD=auto, the whole
  // render 58.6 s against 17.7 s. "auto" is a name every PoCL knows (3.1 has no "cbs": it
  // warns once per kernel and falls back to "auto"), and later PoCLs choose by the kernel.
  // Set before PoCL starts; a method the user set wins, and other drivers ignore the variable.
  setenv(kPoclWorkGroupMethod, "auto", /*overwrite=*/0);
  cl_uint platformCount = 0;
  cl_int result = clGetPlatformIDs(0, nullptr, &platformCount);
  if (result == CL_PLATFORM_NOT_FOUND_KHR || (result == CL_SUCCESS && platformCount == 0)) {
    throw Error("no OpenCL platform found; install pocl-opencl-icd (CPU) or a GPU's OpenCL driver, or use --backend "
                "vulkan");
  }
  CL_CHECK(result);
  std::vector<cl_platform_id> platforms(platformCount);
  CL_CHECK(clGetPlatformIDs(platformCount, platforms.data(), nullptr));
  std::vector<OpenClDeviceInfo> devices;
  for (cl_platform_id platform : platforms) {
    cl_uint count = 0;
    result = clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &count);
    if (result == CL_DEVICE_NOT_FOUND || count == 0) {
      continue;
    }
    CL_CHECK(result);
    std::vector<cl_device_id> ids(count);
    CL_CHECK(clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, count, ids.data(), nullptr));
    for (cl_device_id id : ids) {
      devices.push_back(describe(platform, id));
    }
  }
  return devices;
}

std::string missingRequirement(const OpenClDeviceInfo& device) {
  if (versionAfter(device.languageVersion, "OpenCL C ") < std::pair(1, 2)) {
    return "OpenCL C 1.2 (it has '" + device.languageVersion + "')";
  }
  if (!device.compilerAvailable) {
    return "an OpenCL C compiler";
  }
  if (device.maxWorkGroupSize < WP_WORKGROUP_SIZE) {
    return "work-groups of " + std::to_string(WP_WORKGROUP_SIZE) + " work items";
  }
  return "";
}

int mostCapableUsableDevice(const std::vector<OpenClDeviceInfo>& devices) {
  return mostCapableUsable(devices, [](const OpenClDeviceInfo& d) { return missingRequirement(d).empty(); });
}

OpenClDeviceInfo chooseOpenClDevice(int index) {
  std::vector<OpenClDeviceInfo> devices = listOpenClDevices();
  if (devices.empty()) {
    throw Error("the OpenCL platforms have no devices; install pocl-opencl-icd (CPU) or a GPU's OpenCL driver, or use "
                "--backend vulkan");
  }
  if (index >= static_cast<int>(devices.size())) {
    throw Error("--device " + std::to_string(index) + " does not exist: there are " + std::to_string(devices.size()) +
                " OpenCL devices; run 'wavepath devices' to list them");
  }
  // None usable: the first, whose missing requirement the error below names.
  const int chosen = index >= 0 ? index : std::max(0, mostCapableUsableDevice(devices));
  const OpenClDeviceInfo& device = devices[chosen];
  std::string missing = missingRequirement(device);
  if (!missing.empty()) {
    throw Error("OpenCL device '" + device.name + "' lacks " + missing +
                "; pick another with --device (see 'wavepath devices') or update its driver");
  }
  return device;
}

}  // namespace wp
