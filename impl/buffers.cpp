#include "impl/buffers.hpp"

#include <array>
#include <cstdint>
#include <mutex>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace circles::impl::detail {
namespace {

std::size_t whole_huge_pages(std::size_t bytes) noexcept { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }

#if defined(__linux__) && defined(MADV_HUGEPAGE)
// Mappings given back, kept for the requests after them: a rebuild gives back its old pair list before its
// sort and then asks for a new one, a growing buffer gives back its old block, and a kept mapping is memory
// whose pages are backed already, where a new one costs a zeroed page at each first write (on a virtual
// machine, the host's fault too). A request takes the smallest kept mapping that holds it, its tail beyond the request unmapped; one
// that none holds gives back every kept mapping before it maps anew. So the buffers' memory and the kept
// mappings together never exceed the most the buffers held at a new mapping: the peak is what it would be
// without them.
class Kept {
 public:
  // A kept mapping of `size` bytes (a multiple of kHugePage), or nullptr after giving back every kept one.
  void* take(std::size_t size) noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::size_t best = count_;
    for (std::size_t k = 0; k < count_; ++k)
      if (blocks_[k].size >= size && (best == count_ || blocks_[k].size < blocks_[best].size)) best = k;
    if (best == count_) {
      for (std::size_t k = 0; k < count_; ++k) munmap(blocks_[k].block, blocks_[k].size);
      count_ = 0;
      return nullptr;
    }
    const Block taken = blocks_[best];
    blocks_[best] = blocks_[--count_];
    if (taken.size > size) munmap(static_cast<char*>(taken.block) + size, taken.size - size);
    return taken.block;
  }
  // Keeps the mapping, or gives it back when kKept are kept already.
  void give(void* block, std::size_t size) noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (count_ == kKept) {
      munmap(block, size);
      return;
    }
    blocks_[count_++] = {block, size};
  }

 private:
  // A rebuild gives back its pair list (a block per chunk) and the guided sort's long lists before it asks
  // again; its other scratch stays with its owners (impl/cell_layout.hpp).
  static constexpr std::size_t kKept = 4;
  struct Block {
    void* block;
    std::size_t size;
  };
  std::mutex mutex_;
  std::array<Block, kKept> blocks_{};
  std::size_t count_ = 0;
};

Kept& kept() noexcept {
  static Kept* const k = new Kept;  // never destroyed: a static Buffer may give its block back at exit
  return *k;
}
#endif

}  // namespace

void* allocate_buffer(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= kMappedFrom) {
    // A mapping one huge page longer than needed has a kHugePage-aligned start within its first huge page;
    // what lies before that start and after the block's whole huge pages is given back at once.
    const std::size_t size = whole_huge_pages(bytes);
    if (size < bytes || size + kHugePage < size) throw std::bad_alloc();
    if (void* const block = kept().take(size)) return block;
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
  if (bytes >= kMappedFrom) {
    kept().give(block, whole_huge_pages(bytes));
    return;
  }
#endif
  ::operator delete(block);
}

}  // namespace circles::impl::detail
