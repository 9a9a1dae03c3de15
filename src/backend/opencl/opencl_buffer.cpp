// OpenCL buffer ownership.
#include "backend/opencl/opencl_buffer.h"

#include <array>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "backend/opencl/cl_check.h"
#include "core/error.h"
#include "core/huge_pages.h"
#include "render/device_limits.h"

namespace wp {

namespace {
// Placeholder size for empty buffers: one 16-byte element.
constexpr uint64_t kMinimumSize = 16;
}  // namespace

OpenClBuffer::OpenClBuffer(cl_context context, cl_mem_flags flags, uint64_t size, const void* data,
                           OpenClMemory memory)
    : size_(size < kMinimumSize ? kMinimumSize : size) {
  cl_int result = CL_SUCCESS;
  bool copy = data != nullptr && size > 0;
  if (memory == OpenClMemory::hostHugePages && size_ >= kHugePageBytes) {
    void* block = allocateHugePages(size_);
    if (block == nullptr) {
      throw Error("out of memory for an OpenCL buffer of " + byteSize(size_) +
                  "; render fewer pixels or paths at once (--max-paths), or a smaller scene");
    }
    if (copy) {
      std::memcpy(block, data, size);
    }
    mem_ = clCreateBuffer(context, flags | CL_MEM_USE_HOST_PTR, size_, block, &result);
    if (result == CL_SUCCESS) {
      result = clSetMemObjectDestructorCallback(
          mem_, [](cl_mem, void* released) { std::free(released); }, block);
      if (result != CL_SUCCESS) {  // nothing would free the block: release both here
        clReleaseMemObject(std::exchange(mem_, nullptr));
      }
    }
    if (result != CL_SUCCESS) {
      std::free(block);
      CL_CHECK(result);
    }
    return;
  }
  // CL_MEM_COPY_HOST_PTR copies the whole buffer: a placeholder larger than the data is
  // filled from a zeroed copy, never from past the end of `data`.
  std::array<unsigned char, kMinimumSize> padded{};
  if (copy && size < size_) {
    std::memcpy(padded.data(), data, size);
    data = padded.data();
  }
  mem_ = clCreateBuffer(context, flags | (copy ? CL_MEM_COPY_HOST_PTR : 0), size_, copy ? const_cast<void*>(data) : nullptr,
                        &result);
  CL_CHECK(result);
}

OpenClBuffer::~OpenClBuffer() {
  if (mem_ != nullptr) {
    clReleaseMemObject(mem_);
  }
}

OpenClBuffer::OpenClBuffer(OpenClBuffer&& other) noexcept
    : mem_(std::exchange(other.mem_, nullptr)), size_(std::exchange(other.size_, 0)) {}

OpenClBuffer& OpenClBuffer::operator=(OpenClBuffer&& other) noexcept {
  if (this != &other) {
    if (mem_ != nullptr) {
      clReleaseMemObject(mem_);
    }
    mem_ = std::exchange(other.mem_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

}  // namespace wp
