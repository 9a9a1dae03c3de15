// Huge pages for large blocks (core/huge_pages.h): which memory asks the kernel for them. The
// advice shows in /proc/self/smaps as the flag `hg` of the mapping that holds the memory,
// whatever the machine's huge page setting, so these tests read it there; whether the kernel
// then grants huge pages, and what that saves, is the benchmark's to measure.
#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "backend/opencl/cl_check.h"
#include "backend/opencl/opencl_buffer.h"
#include "backend/opencl/opencl_context.h"
#include "backend/vulkan/vulkan_buffer.h"
#include "backend/vulkan/vulkan_context.h"
#include "core/huge_pages.h"

namespace wp::test {
namespace {

struct Mapping {
  uintptr_t begin = 0, end = 0;
  bool hugePagesAdvised = false;  // VmFlags has `hg`
};

// The mapping of /proc/self/smaps that holds `address`; fails the test if none does.
Mapping mappingOf(const void* address) {
  const auto at = reinterpret_cast<uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  Mapping current;
  bool found = false;
  while (std::getline(smaps, line)) {
    uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-') {  // a mapping's first line
      if (found) break;
      current = {begin, end, false};
      found = at >= begin && at < end;
    } else if (found && line.rfind("VmFlags:", 0) == 0) {
      current.hugePagesAdvised = (line + " ").find(" hg ") != std::string::npos;
    }
  }
  EXPECT_TRUE(found) << "no mapping holds " << address;
  return current;
}

// Fresh anonymous memory of `bytes`, unmapped at the end of the test.
struct AnonymousMemory {
  explicit AnonymousMemory(size_t bytes) : bytes(bytes) {
    data = static_cast<char*>(mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0));
    EXPECT_NE(data, MAP_FAILED);
  }
  ~AnonymousMemory() { munmap(data, bytes); }
  char* data;
  size_t bytes;
};

char* firstHugePageIn(char* data) {
  return reinterpret_cast<char*>(roundUpToHugePage(reinterpret_cast<uintptr_t>(data)));
}

TEST(HugePages, AreAdvisedForTheWholeHugePagesInsideABlockAndNoWhereElse) {
  AnonymousMemory memory(4 * kHugePageBytes);
  // A block that starts a page into the memory and ends a page before its end: the whole huge
  // pages inside it get the advice, the partial ones at either end (shared, in a real heap,
  // with other blocks) do not.
  char* block = memory.data + 4096;
  const size_t bytes = memory.bytes - 2 * 4096;
  adviseHugePages(block, bytes);
  char* inside = firstHugePageIn(block);
  const Mapping advised = mappingOf(inside);
  EXPECT_TRUE(advised.hugePagesAdvised);
  EXPECT_EQ(advised.begin, reinterpret_cast<uintptr_t>(inside));
  EXPECT_EQ(advised.end % kHugePageBytes, 0u);
  EXPECT_LE(advised.end, reinterpret_cast<uintptr_t>(block + bytes));
  if (inside != memory.data) {
    EXPECT_FALSE(mappingOf(memory.data).hugePagesAdvised);
  }
  EXPECT_FALSE(mappingOf(memory.data + memory.bytes - 1).hugePagesAdvised);
}

TEST(HugePages, AreNotAdvisedForABlockSmallerThanOne) {
  AnonymousMemory memory(2 * kHugePageBytes);
  adviseHugePages(firstHugePageIn(memory.data), kHugePageBytes - 4096);
  EXPECT_FALSE(mappingOf(firstHugePageIn(memory.data)).hugePagesAdvised);
  adviseHugePages(nullptr, 4 * kHugePageBytes);  // nothing to advise, and no crash
}

TEST(LargeAllocations, AreWholeHugePagesAdvisedBeforeAnythingTouchesThem) {
  // This executable links wp_large_allocations, as wavepath does: operator new itself.
  const size_t bytes = 3 * kHugePageBytes + 100;
  std::unique_ptr<char[]> block(new char[bytes]);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(block.get()) % kHugePageBytes, 0u);
  const Mapping mapping = mappingOf(block.get());
  EXPECT_TRUE(mapping.hugePagesAdvised);
  // The last partial huge page is the block's too: the size is rounded up to whole ones.
  EXPECT_GE(mapping.end, reinterpret_cast<uintptr_t>(block.get()) + 4 * kHugePageBytes);
  block[bytes - 1] = 1;  // writable to the end
}

TEST(VulkanBufferOnTheCpu, AsksForHugePagesForItsMemory) {
  // lavapipe's device memory is a block of the process's heap that the first upload or stage
  // touches page by page.
  VulkanContext context(-1, false);
  ASSERT_TRUE(context.onCpu()) << "this test needs lavapipe as the Vulkan device (got "
                               << context.properties.deviceName << ")";
  for (bool hostVisible : {true, false}) {
    VulkanBuffer buffer(context, 4 * kHugePageBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hostVisible);
    std::vector<char> bytes(buffer.size(), 1);
    buffer.upload(bytes.data(), bytes.size());
    std::vector<char> back;
    VulkanBuffer staging;
    buffer.download(bytes.size(), staging, [&](const void* data) {
      const char* first = static_cast<const char*>(data);
      back.assign(first, first + bytes.size());
      EXPECT_TRUE(mappingOf(firstHugePageIn(const_cast<char*>(first))).hugePagesAdvised) << hostVisible;
    });
    EXPECT_EQ(back, bytes);
  }
}

TEST(OpenClBufferOnTheCpu, IsHugePagesOfOursThatTheDriverUsesInPlace) {
  // PoCL's own allocation is touched page by page; CL_MEM_USE_HOST_PTR has it work in ours.
  OpenClContext context(-1);
  ASSERT_EQ(context.device.type, "CPU") << "this test needs PoCL as the OpenCL device (got "
                                        << context.device.name << ")";
  std::vector<uint32_t> words(4 * kHugePageBytes / sizeof(uint32_t) - 3);
  for (size_t i = 0; i < words.size(); ++i) words[i] = uint32_t(i * 2654435761u);
  const size_t bytes = words.size() * sizeof(uint32_t);
  OpenClBuffer buffer(context.context, CL_MEM_READ_WRITE, bytes, words.data(), OpenClMemory::hostHugePages);
  cl_int result = CL_SUCCESS;
  void* mapped = clEnqueueMapBuffer(context.queue, buffer.handle(), CL_TRUE, CL_MAP_READ, 0, bytes, 0, nullptr,
                                    nullptr, &result);
  CL_CHECK(result);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(mapped) % kHugePageBytes, 0u) << "the driver copied the block";
  EXPECT_TRUE(mappingOf(mapped).hugePagesAdvised);
  EXPECT_EQ(std::memcmp(mapped, words.data(), bytes), 0);
  CL_CHECK(clEnqueueUnmapMemObject(context.queue, buffer.handle(), mapped, 0, nullptr, nullptr));
  CL_CHECK(clFinish(context.queue));
}

}  // namespace
}  // namespace wp::test
