// Transparent huge pages for large blocks of the process's memory.
//
// Every 4 KiB page of a fresh block costs a page fault when it is first written, and in a
// virtual machine each fault is also an exit to the hypervisor: on the 2-core VMs of this
// project a fault costs several microseconds, and the big instanced scene faulted 210,000
// times (820 MB) in a render of 14 s, about a second of it (docs/performance.md). Debian's
// kernels give huge pages (2 MiB, one fault each) only to memory that asks for them
// (/sys/kernel/mm/transparent_hugepage/enabled is `madvise`), so large blocks ask.
#pragma once

#include <cstddef>
#include <cstdint>

namespace wp {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

// `value` (a size or an address) rounded down and up to a multiple of kHugePageBytes; up
// wraps to 0 past the largest multiple.
constexpr std::uintptr_t roundDownToHugePage(std::uintptr_t value) { return value & ~(kHugePageBytes - 1); }
constexpr std::uintptr_t roundUpToHugePage(std::uintptr_t value) {
  return roundDownToHugePage(value + kHugePageBytes - 1);
}

// Asks the kernel to back the whole huge pages inside [data, data + bytes) with huge pages
// when they are first touched (madvise MADV_HUGEPAGE); the pages at either end that the block
// shares with other memory keep their size. Advice only: it changes no contents, and where the
// kernel refuses (huge pages disabled, memory that is not the process's own anonymous memory,
// as a GPU driver's mapping) nothing changes. Pages already touched keep their 4 KiB.
void adviseHugePages(void* data, std::size_t bytes);

// A block of at least `bytes`, aligned to a huge page and rounded up to whole ones, advised
// before anything touches it, so that all of it can be huge pages (a block malloc hands out
// starts 16 bytes into its mapping, and the partial huge pages at either end would stay in
// 4 KiB pages). Released with std::free; nullptr when there is no memory. The head that the
// alignment skips is address space only, never touched.
void* allocateHugePages(std::size_t bytes);

}  // namespace wp
