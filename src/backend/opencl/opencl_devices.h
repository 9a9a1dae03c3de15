// OpenCL platforms and devices: listing them for `wavepath devices` and choosing one.
#pragma once

#include <CL/cl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wp {

struct OpenClDeviceInfo {
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  std::string platformName;
  std::string name;
  std::string type;           // "GPU", "CPU", "accelerator", ...
  std::string driverVersion;  // CL_DRIVER_VERSION
  std::string version;        // CL_DEVICE_VERSION, e.g. "OpenCL 3.0 PoCL ..."
  std::string languageVersion;  // CL_DEVICE_OPENCL_C_VERSION, e.g. "OpenCL C 1.2 PoCL"
  uint32_t computeUnits = 0;
  uint64_t globalMemoryBytes = 0;
  uint64_t maxAllocationBytes = 0;
  size_t maxWorkGroupSize = 0;
  bool compilerAvailable = false;
  int rank = 0;  // preference when no --device is given: GPU, accelerator, CPU, other
};

// Every device of every platform, in the ICD loader's platform order; `wavepath devices`
// numbers them from 0 in this order and --device indexes it. Throws wp::Error when no
// platform is installed.
std::vector<OpenClDeviceInfo> listOpenClDevices();

// PoCL's way of running a work-group's work-items (POCL_WORK_GROUP_METHOD), which its
// compiled kernels depend on: set to "auto" by listOpenClDevices unless the user chose one
// (opencl_devices.cpp says why), and part of the program cache's key.
std::string poclWorkGroupMethod();

// What `device` lacks to run the stage kernels (OpenCL C 1.2, a compiler, workgroups of
// WP_WORKGROUP_SIZE), or an empty string.
std::string missingRequirement(const OpenClDeviceInfo& device);

// The index of the best-ranked device of `devices` that meets the requirements, or -1: the
// device a render takes without --device (chooseOpenClDevice), and the one `--backend auto`
// weighs.
int mostCapableUsableDevice(const std::vector<OpenClDeviceInfo>& devices);

// The device --device `index` names (index < 0: the most capable one that meets the
// requirements). Throws wp::Error when it does not exist or lacks a requirement.
OpenClDeviceInfo chooseOpenClDevice(int index);

}  // namespace wp
