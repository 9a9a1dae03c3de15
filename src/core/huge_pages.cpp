// Transparent huge pages for large blocks of the process's memory.
#include "core/huge_pages.h"

#include <sys/mman.h>

#include <cstdlib>

namespace wp {

void adviseHugePages(void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = roundUpToHugePage(begin);
  const std::uintptr_t end = roundDownToHugePage(begin + bytes);
  if (data == nullptr || bytes < kHugePageBytes || end <= first) {
    return;
  }
  // The result is ignored on purpose: a refusal leaves the block as it was, in 4 KiB pages.
  (void)madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
}

void* allocateHugePages(std::size_t bytes) {
  const std::size_t rounded = roundUpToHugePage(bytes);
  if (rounded < bytes) {  // the rounding overflowed
    return nullptr;
  }
  void* block = std::aligned_alloc(kHugePageBytes, rounded);
  adviseHugePages(block, rounded);
  return block;
}

}  // namespace wp
