// An OpenCL buffer that releases itself.
#pragma once

#include <CL/cl.h>

#include <cstdint>

namespace wp {

// Whose memory a buffer is: the driver's own allocation, or, for a device that runs on this
// CPU (PoCL), a block of wavepath's in huge pages (core/huge_pages.h) that the driver uses in
// place (CL_MEM_USE_HOST_PTR) and that is freed when the driver lets the buffer go. PoCL's own
// blocks are touched page by page, a fault each: 106,000 faults in a render of the instanced
// scene before, and a fault costs several microseconds in a virtual machine.
enum class OpenClMemory { driver, hostHugePages };

class OpenClBuffer {
public:
  OpenClBuffer() = default;
  // A size under 16 bytes allocates a 16-byte placeholder, so the buffer can still be a
  // kernel argument; `data`, if given, is `size` bytes copied in (the rest zero). Buffers
  // smaller than a huge page always take the driver's memory.
  OpenClBuffer(cl_context context, cl_mem_flags flags, uint64_t size, const void* data = nullptr,
               OpenClMemory memory = OpenClMemory::driver);
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
