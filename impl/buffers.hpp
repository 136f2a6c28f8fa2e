// The engines' big buffers: per-circle columns, keys, orders and pair lists, each megabytes at 10^6 circles.
//
// A buffer the kernel backs with 4 KiB pages costs one page fault per 4 KiB the first time it is written: at
// 10^6 circles an engine's first step writes about 100 MB of new buffers, 25,000 faults, and on a virtual
// machine they were about half of that step's time. Linux backs a range with 2 MiB pages (transparent huge
// pages) when the program asks for it with madvise(MADV_HUGEPAGE), as Debian's kernels are configured to
// (/sys/kernel/mm/transparent_hugepage/enabled: "madvise"), but only for the 2 MiB-aligned pieces of a
// mapping: malloc's large blocks start 16 bytes into a mapping at any 4 KiB boundary, so the advice reached
// only their inner whole 2 MiB pieces, and an 8 MB column still took about 500 small faults at its ends.
// Buffer<T> is a std::vector whose allocator maps blocks of kMappedFrom and more on their own, aligned to
// kHugePage and rounded up to a whole number of them, advised before anything is written: one fault per
// 2 MiB, and fewer TLB misses in the steps' gathers. Smaller blocks come from operator new, as std::allocator's
// do. A mapping given back is kept for the next requests, which it serves with its pages backed already when
// it holds them, and is unmapped at the first request that no kept mapping holds (buffers.cpp, Kept). The
// mapping and the advice change no value: a kernel that ignores the advice (or a system without
// mmap, where every block comes from operator new) gives the same results.
#pragma once

#include <cstddef>
#include <limits>
#include <new>
#include <vector>

namespace circles::impl {

namespace detail {
// kMappedFrom bytes or more: a mapping of its own, aligned and advised; less: operator new. `bytes` must be the
// same in both calls of a block.
void* allocate_buffer(std::size_t bytes);
void deallocate_buffer(void* block, std::size_t bytes) noexcept;
}  // namespace detail

// x86-64's huge page.
inline constexpr std::size_t kHugePage = std::size_t{1} << 21;
// The least block that gets a mapping of its own: from operator new, a block of 512 KiB costs 128 faults of
// 4 KiB pages as it is first written (a pair list's slot marks, a byte a circle, cost 256 at 10^6 circles);
// mapped, it costs one fault and at most 1.5 MiB of memory beyond the block.
inline constexpr std::size_t kMappedFrom = kHugePage / 4;

template <class T>
class BufferAllocator {
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "operator new's alignment must suffice");

 public:
  using value_type = T;
  BufferAllocator() noexcept = default;
  template <class U>
  BufferAllocator(const BufferAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(detail::allocate_buffer(n * sizeof(T)));
  }
  void deallocate(T* block, std::size_t n) noexcept { detail::deallocate_buffer(block, n * sizeof(T)); }

  template <class U>
  bool operator==(const BufferAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using Buffer = std::vector<T, BufferAllocator<T>>;

}  // namespace circles::impl
