// The global operator new and delete of the executables that link this file (wavepath, and the
// tests that check it): blocks of at least kLargeBlockBytes, which are the scene's arrays, the
// BVH's, the packed buffers and the images, ask for huge pages (huge_pages.h) before anything
// touches them, so that a block of 64 MiB costs 32 page faults instead of 16,384.
//
// glibc's malloc hands out blocks this large from fresh mmap'ed or brk'ed memory that nothing
// has touched yet, which is when the advice counts; free() takes them back as any other.
// Debian's glibc advises its own blocks behind a tunable (GLIBC_TUNABLES=
// glibc.malloc.hugetlb=1), but tunables are read from the environment before main, so an
// executable cannot set its own.
//
// Under AddressSanitizer its own operator new stays: it checks new against delete.
#include <cstdlib>
#include <new>

#include "core/huge_pages.h"

// GCC says so with __SANITIZE_ADDRESS__, clang 14 only through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define WP_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WP_ADDRESS_SANITIZER 1
#endif
#endif

#if !defined(WP_ADDRESS_SANITIZER)

namespace {

// Smaller blocks come from memory malloc has touched before, or are too small to matter.
constexpr std::size_t kLargeBlockBytes = wp::kHugePageBytes;

void* allocate(std::size_t bytes) {
  return bytes < kLargeBlockBytes ? std::malloc(bytes) : wp::allocateHugePages(bytes);
}

}  // namespace

void* operator new(std::size_t bytes) {
  if (bytes == 0) {
    bytes = 1;
  }
  for (;;) {
    if (void* block = allocate(bytes)) {
      return block;
    }
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) {
      throw std::bad_alloc();
    }
    handler();
  }
}

void* operator new[](std::size_t bytes) { return ::operator new(bytes); }

void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  try {
    return ::operator new(bytes);
  } catch (...) {
    return nullptr;
  }
}

void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
  return ::operator new(bytes, std::nothrow);
}

void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { std::free(block); }

#endif
