// impl/buffers.hpp: growing a buffer through the huge-page advice keeps what it held, as reserve and resize do.
#include "impl/buffers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace circles::impl {
namespace {

TEST(buffers, a_buffer_grown_past_2_mib_keeps_its_elements_and_value_initializes_the_new_ones) {
  std::vector<std::uint64_t> v(1000);
  std::iota(v.begin(), v.end(), std::uint64_t{7});
  resize_buffer(v, std::size_t{1} << 20);  // 8 MiB: advised
  ASSERT_EQ(v.size(), std::size_t{1} << 20);
  for (std::size_t k = 0; k < 1000; ++k) ASSERT_EQ(v[k], 7 + k);
  for (std::size_t k = 1000; k < v.size(); ++k) ASSERT_EQ(v[k], 0u);
  const std::uint64_t* data = v.data();
  resize_buffer(v, 10);  // shrinking neither moves nor frees
  EXPECT_EQ(v.data(), data);
  EXPECT_EQ(v.size(), 10u);
}

TEST(buffers, elements_that_own_memory_are_moved_not_lost) {
  std::vector<std::string> v{"a string long enough to live on the heap, not in the object", "b"};
  reserve_buffer(v, 1u << 17);  // 4 MiB of std::string
  EXPECT_GE(v.capacity(), 1u << 17);
  EXPECT_EQ(v, (std::vector<std::string>{"a string long enough to live on the heap, not in the object", "b"}));
}

TEST(buffers, advice_on_any_range_is_harmless) {
  advise_huge_pages(nullptr, 0);
  advise_huge_pages(nullptr, std::size_t{1} << 30);
  std::vector<char> small(100, 'x');
  advise_huge_pages(small.data(), small.size());
  EXPECT_EQ(small, std::vector<char>(100, 'x'));
}

}  // namespace
}  // namespace circles::impl
