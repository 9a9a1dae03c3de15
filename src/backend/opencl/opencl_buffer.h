// An OpenCL buffer that releases itself.
#pragma once

#include <CL/cl.h>

#include <cstdint>

namespace wp {

class OpenClBuffer {
public:
  OpenClBuffer() = default;
  // A size under 16 bytes allocates a 16-byte placeholder, so the buffer can still be a
  // kernel argument; `data`, if given, is `size` bytes copied in (the rest zero).
  OpenClBuffer(cl_context context, cl_mem_flags flags, uint64_t size, const void* data = nullptr);
  ~OpenClBuffer();
  OpenClBuffer(OpenClBuffer&& other) noexcept;
  OpenClBuffer& operator=(OpenClBuffer&& other) noexcept;
  OpenClBuffer(const OpenClBuffer&) = delete;
  OpenClBuffer& operator=(const OpenClBuffer&) = delete;

  cl_mem handle() const { return mem_; }
  // The handle's address, as clSetKernelArg wants it.
  const cl_mem* argument() const { return &mem_; }
  uint64_t size() const { return size_; }

private:
  cl_mem mem_ = nullptr;
  uint64_t size_ = 0;
};

}  // namespace wp
