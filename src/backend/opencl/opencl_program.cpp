// Program build: cache lookup, compile from source with the log on failure, cache store.
#include "backend/opencl/opencl_program.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "backend/opencl/cl_check.h"
#include "core/error.h"
#include "core/log.h"
#include "opencl/opencl_source.h"

namespace wp {
namespace {

constexpr const char* kExtraSourceVariable = "WAVEPATH_CL_EXTRA_SOURCE";

std::string buildLog(cl_program program, cl_device_id device) {
  size_t size = 0;
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
  std::string log(size, '\0');
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n' || log.back() == ' ')) {
    log.pop_back();
  }
  return log;
}

std::vector<unsigned char> programBinary(cl_program program) {
  size_t size = 0;
  CL_CHECK(clGetProgramInfo(program, CL_PROGRAM_BINARY_SIZES, sizeof(size), &size, nullptr));
  std::vector<unsigned char> binary(size);
  unsigned char* data = binary.data();
  if (size > 0) {
    CL_CHECK(clGetProgramInfo(program, CL_PROGRAM_BINARIES, sizeof(data), &data, nullptr));
  }
  return binary;
}

// The cache key: everything the binary depends on.
std::string cacheKey(const OpenClDeviceInfo& device, const std::string& options, const std::string& source) {
  char sourceHash[17];
  std::snprintf(sourceHash, sizeof(sourceHash), "%016llx", static_cast<unsigned long long>(fnv1a64(source)));
  return "wavepath OpenCL program\nplatform: " + device.platformName + "\ndevice: " + device.name +
         "\ndevice version: " + device.version + "\ndriver: " + device.driverVersion + "\noptions: " + options +
         "\npocl work-group method: " + poclWorkGroupMethod() +
         "\nsource: " + sourceHash + " " + std::to_string(source.size()) + "\n";
}

std::string programSource() {
  std::string source = kOpenClSource;
  const char* extra = std::getenv(kExtraSourceVariable);
  if (extra != nullptr && *extra != '\0') {
    source += "\n#line 1 \"" + std::string(kExtraSourceVariable) + "\"\n" + extra + "\n";
  }
  return source;
}

}  // namespace

OpenClProgram::OpenClProgram(const OpenClContext& context, const std::string& options)
    : cache_(ProgramCache::defaultDirectory(), cacheKey(context.device, options, programSource())) {
  std::vector<unsigned char> cached = cache_.load();
  if (!cached.empty() && buildFromBinary(context, cached, options)) {
    return;
  }
  note("compiling the OpenCL kernels for '" + context.device.name + "', once per device and driver" +
       (cache_.file().empty() ? std::string(" if WAVEPATH_CACHE_DIR names a cache directory")
                              : "; later runs load them from " + cache_.file().parent_path().string()));
  buildFromSource(context, programSource(), options);
  compiled_ = true;
}

void OpenClProgram::cacheBinary() {
  if (compiled_) {
    compiled_ = false;
    cache_.store(programBinary(program_));
  }
}

OpenClProgram::~OpenClProgram() {
  if (program_ != nullptr) {
    clReleaseProgram(program_);
  }
}

bool OpenClProgram::buildFromBinary(const OpenClContext& context, const std::vector<unsigned char>& binary,
                                    const std::string& options) {
  const unsigned char* data = binary.data();
  size_t size = binary.size();
  cl_int status = CL_SUCCESS;
  cl_int result = CL_SUCCESS;
  cl_program program =
      clCreateProgramWithBinary(context.context, 1, &context.device.device, &size, &data, &status, &result);
  if (result != CL_SUCCESS || status != CL_SUCCESS) {
    if (program != nullptr) {
      clReleaseProgram(program);
    }
    return false;
  }
  if (clBuildProgram(program, 1, &context.device.device, options.c_str(), nullptr, nullptr) != CL_SUCCESS) {
    clReleaseProgram(program);
    return false;
  }
  program_ = program;
  return true;
}

void OpenClProgram::buildFromSource(const OpenClContext& context, const std::string& source,
                                    const std::string& options) {
  const char* text = source.c_str();
  size_t size = source.size();
  cl_int result = CL_SUCCESS;
  program_ = clCreateProgramWithSource(context.context, 1, &text, &size, &result);
  CL_CHECK(result);
  result = clBuildProgram(program_, 1, &context.device.device, options.c_str(), nullptr, nullptr);
  if (result == CL_SUCCESS) {
    return;
  }
  std::string log = result == CL_BUILD_PROGRAM_FAILURE ? buildLog(program_, context.device.device) : "";
  clReleaseProgram(program_);
  program_ = nullptr;
  if (result == CL_BUILD_PROGRAM_FAILURE) {
    std::fprintf(stderr, "%s\n", log.empty() ? "(the OpenCL compiler gave no log)" : log.c_str());
    const char* extra = std::getenv(kExtraSourceVariable);
    throw Error("the OpenCL kernels failed to build for '" + context.device.name + "' (compiler log above)" +
                (extra != nullptr && *extra != '\0' ? std::string("; ") + kExtraSourceVariable + " is set, unset it"
                                                    : "; update the device's OpenCL driver or use --backend vulkan"));
  }
  CL_CHECK(result);
}

}  // namespace wp
