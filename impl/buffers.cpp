#include "impl/buffers.hpp"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace circles::impl::detail {
namespace {

std::size_t whole_huge_pages(std::size_t bytes) noexcept { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }

}  // namespace

void* allocate_buffer(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= kHugePage) {
    // A mapping one huge page longer than needed has a kHugePage-aligned start within its first huge page;
    // what lies before that start and after the block's whole huge pages is given back at once.
    const std::size_t size = whole_huge_pages(bytes);
    if (size < bytes || size + kHugePage < size) throw std::bad_alloc();
    void* const mapped = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto begin = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t start = (begin + kHugePage - 1) & ~std::uintptr_t{kHugePage - 1};
    if (start > begin) munmap(mapped, start - begin);
    if (const std::size_t after = begin + kHugePage - start; after > 0)
      munmap(reinterpret_cast<void*>(start + size), after);
    void* const block = reinterpret_cast<void*>(start);
    (void)madvise(block, size, MADV_HUGEPAGE);  // advice: refused, the block is still good
    return block;
  }
#endif
  return ::operator new(bytes);
}

void deallocate_buffer(void* block, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= kHugePage) {
    munmap(block, whole_huge_pages(bytes));
    return;
  }
#endif
  ::operator delete(block);
}

}  // namespace circles::impl::detail
