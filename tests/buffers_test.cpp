// impl/buffers.hpp: Buffer<T> holds what a std::vector holds, and its blocks of 2 MiB and more start on a
// huge page's boundary, so that the kernel can back all of them with huge pages.
#include "impl/buffers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <new>
#include <numeric>
#include <string>
#include <vector>

namespace circles::impl {
namespace {

std::uintptr_t offset_in_huge_page(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % kHugePage; }

TEST(buffers, a_buffer_grown_past_2_mib_starts_on_a_huge_page_and_keeps_its_elements) {
  Buffer<std::uint64_t> v(1000);
  std::iota(v.begin(), v.end(), std::uint64_t{7});
  v.resize(std::size_t{1} << 20);  // 8 MiB
  EXPECT_EQ(offset_in_huge_page(v.data()), 0u);
  ASSERT_EQ(v.size(), std::size_t{1} << 20);
  for (std::size_t k = 0; k < 1000; ++k) ASSERT_EQ(v[k], 7 + k);
  for (std::size_t k = 1000; k < v.size(); ++k) ASSERT_EQ(v[k], 0u);
  // Blocks just at and just under the threshold, and an odd size above it (rounded up to whole huge pages).
  Buffer<char> at(kHugePage), under(kHugePage - 1, 'u'), odd(3 * kHugePage + 12345, 'o'), mapped(kMappedFrom);
  EXPECT_EQ(offset_in_huge_page(at.data()), 0u);
  EXPECT_EQ(offset_in_huge_page(mapped.data()), 0u);
  EXPECT_EQ(offset_in_huge_page(odd.data()), 0u);
  EXPECT_EQ(odd.back(), 'o');
  EXPECT_EQ(under.back(), 'u');
}

TEST(buffers, a_mapping_given_back_serves_the_next_request_of_its_size_as_it_was_left) {
  BufferAllocator<unsigned char> allocator;
  const std::size_t bytes = 3 * kHugePage;
  unsigned char* const first = allocator.allocate(bytes);
  first[0] = 42;
  first[bytes - 1] = 43;
  allocator.deallocate(first, bytes);
  unsigned char* const again = allocator.allocate(bytes);
  EXPECT_EQ(again, first);
  // Its pages as they were: a new mapping would read 0.
  EXPECT_EQ(again[0], 42);
  EXPECT_EQ(again[bytes - 1], 43);
  allocator.deallocate(again, bytes);
}

TEST(buffers, a_smaller_request_takes_a_kept_mapping_cut_to_its_size) {
  BufferAllocator<unsigned char> allocator;
  unsigned char* const kept = allocator.allocate(3 * kHugePage);
  kept[0] = 42;
  allocator.deallocate(kept, 3 * kHugePage);
  unsigned char* const smaller = allocator.allocate(2 * kHugePage);
  EXPECT_EQ(smaller, kept);
  EXPECT_EQ(smaller[0], 42);
  // Cut to two huge pages: given back as two, kept as two, and a request of three cannot take it.
  allocator.deallocate(smaller, 2 * kHugePage);
  unsigned char* const larger = allocator.allocate(3 * kHugePage);
  EXPECT_EQ(larger[0], 0);  // a new mapping, zeroed
  EXPECT_EQ(offset_in_huge_page(larger), 0u);
  larger[3 * kHugePage - 1] = 1;  // all of it is mapped
  allocator.deallocate(larger, 3 * kHugePage);
}

TEST(buffers, elements_that_own_memory_are_moved_not_lost) {
  Buffer<std::string> v{"a string long enough to live on the heap, not in the object", "b"};
  v.reserve(1u << 17);  // 4 MiB of std::string
  EXPECT_GE(v.capacity(), 1u << 17);
  EXPECT_EQ(std::vector<std::string>(v.begin(), v.end()),
            (std::vector<std::string>{"a string long enough to live on the heap, not in the object", "b"}));
}

TEST(buffers, a_block_too_large_to_map_is_a_bad_alloc_not_a_crash) {
  BufferAllocator<double> allocator;
  EXPECT_THROW((void)allocator.allocate(std::numeric_limits<std::size_t>::max() / 4), std::bad_array_new_length);
  EXPECT_THROW((void)allocator.allocate(std::size_t{1} << 60), std::bad_alloc);  // 2^63 bytes: no mapping
}

}  // namespace
}  // namespace circles::impl
