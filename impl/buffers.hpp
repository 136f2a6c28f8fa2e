// The engines' big buffers: per-circle columns, keys, orders and pair lists, each megabytes at 10^6 circles.
//
// A buffer the kernel backs with 4 KiB pages costs one page fault per 4 KiB the first time it is written: at
// 10^6 circles an engine's first step writes about 100 MB of new buffers, 25,000 faults, and on a virtual
// machine they were about half of that step's time. Linux backs a range with 2 MiB pages (transparent huge
// pages) when the program asks for it with madvise(MADV_HUGEPAGE), as Debian's kernels are configured to
// (/sys/kernel/mm/transparent_hugepage/enabled: "madvise"): one fault per 2 MiB, and fewer TLB misses in the
// steps' gathers. These helpers obtain new memory for a vector, ask for huge pages, and only then write it.
// The advice changes no value: a kernel that ignores it (or has no such call) gives the same results.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

namespace circles::impl {

// Asks the kernel to back the whole 2 MiB pages of [data, data + bytes) with huge pages. Ignores ranges under
// 2 MiB, kernels without transparent huge pages and every failure: it is advice.
void advise_huge_pages(void* data, std::size_t bytes) noexcept;

// v.reserve(n), with the new memory advised before any element is written to it (the elements kept are moved
// there after the advice).
template <class T>
void reserve_buffer(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T> fresh;
  fresh.reserve(n);
  advise_huge_pages(fresh.data(), fresh.capacity() * sizeof(T));
  fresh.insert(fresh.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(fresh);
}

// v.resize(n) likewise; new elements are value-initialized, as resize does.
template <class T>
void resize_buffer(std::vector<T>& v, std::size_t n) {
  reserve_buffer(v, n);
  v.resize(n);
}

}  // namespace circles::impl
