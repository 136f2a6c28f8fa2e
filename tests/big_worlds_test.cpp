// The big families (properties/boundaries.hpp, gen::big_world): each world keeps the promise its family makes,
// decided here on the world itself, exactly (impl::intersect_exact, held equal to (3) by tests/predicate_test.cpp):
// the sizes around every power of two, the crowded circles and cells, the spread of the radii, the rows, the
// contacts across index bits and across the borders of the index, x and y orders, the changing contacts of a
// chain; and every world stays within its limit of circles, finite, with r >= 0.
#include "impl/engine.hpp"
#include "impl/predicate.hpp"
#include "properties/boundaries.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace {

namespace properties = circles::properties;
using properties::Circles;
using properties::Family;

constexpr Family kBig[] = {Family::sizes,     Family::crowds,     Family::cell_crowds,   Family::radius_spread,
                           Family::long_rows, Family::index_bits, Family::order_borders, Family::big_chains};

Circles world(Family family, std::uint64_t round, std::size_t max = properties::kDefaultMaxCircles,
              std::uint64_t seed = 1) {
  return properties::gen::big_world(family, round, max, rc::Random(seed * 1000 + round));
}

bool touch(const Circles& w, std::size_t a, std::size_t b) {
  return circles::impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4]);
}

// Each circle's contacts, ascending: candidates from a sweep along x (two circles that touch are at most the two
// largest diameters apart in x), each decided exactly.
std::vector<std::vector<std::size_t>> contacts(const Circles& w) {
  std::vector<std::size_t> order(w.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return w[a][0] < w[b][0]; });
  double largest = 0;
  for (const auto& c : w) largest = std::max(largest, c[4]);
  std::vector<std::vector<std::size_t>> out(w.size());
  for (std::size_t s = 0; s < order.size(); ++s)
    for (std::size_t t = s + 1; t < order.size() && w[order[t]][0] - w[order[s]][0] <= 2.5 * largest; ++t)
      if (touch(w, order[s], order[t])) {
        out[order[s]].push_back(order[t]);
        out[order[t]].push_back(order[s]);
      }
  for (auto& c : out) std::sort(c.begin(), c.end());
  return out;
}

// The least of the circles `of` in the resolved order (impl::World::precedes: (px, py, vx, vy, r) exactly, then
// the index).
std::size_t least(const circles::impl::World& w, const std::vector<std::size_t>& of) {
  return *std::min_element(of.begin(), of.end(), [&](std::size_t a, std::size_t b) { return w.precedes(a, b); });
}

TEST(big_world, every_world_is_bigger_than_a_small_familys_and_within_its_limit_finite_with_r_at_least_0) {
  for (const std::size_t max : {std::size_t{1}, std::size_t{320}, std::size_t{1000}, properties::kDefaultMaxCircles})
    for (const Family family : kBig)
      for (std::uint64_t round = 0; round < 24; ++round) {
        const Circles w = world(family, round, max);
        ASSERT_GT(w.size(), 8u) << properties::name(family);
        ASSERT_LE(w.size(), std::max(max, properties::kMinMaxCircles)) << properties::name(family) << " round " << round;
        for (const auto& c : w) {
          for (const double x : c) ASSERT_TRUE(std::isfinite(x)) << properties::name(family);
          ASSERT_GE(c[4], 0);
        }
      }
}

TEST(big_world, is_the_same_for_the_same_stream_and_round_and_differs_for_another_stream) {
  for (const Family family : kBig) {
    EXPECT_EQ(world(family, 3), world(family, 3)) << properties::name(family);
    EXPECT_NE(world(family, 3, properties::kDefaultMaxCircles, 1), world(family, 3, properties::kDefaultMaxCircles, 2))
        << properties::name(family);
  }
}

TEST(big_world, is_a_family_of_the_resolved_profile_only_and_is_big) {
  for (const Family family : kBig) {
    EXPECT_TRUE(properties::is_big(family));
    const auto literal = properties::families(properties::Profile::literal);
    EXPECT_EQ(std::find(literal.begin(), literal.end(), family), literal.end());
    const auto resolved = properties::families(properties::Profile::resolved);
    EXPECT_NE(std::find(resolved.begin(), resolved.end(), family), resolved.end());
  }
  EXPECT_FALSE(properties::is_big(Family::zero_radius));
  EXPECT_EQ(properties::steps_to_decide(Family::big_chains), 10u);
}

TEST(sizes, crosses_every_power_of_two_from_16_to_4096_in_its_first_nine_rounds_then_each_side_of_them) {
  for (std::uint64_t round = 0; round < 9; ++round)
    EXPECT_EQ(world(Family::sizes, round).size(), (std::size_t{16} << round) + 1);
  std::set<std::size_t> later;
  for (std::uint64_t round = 9; round < 40; ++round) later.insert(world(Family::sizes, round).size());
  for (const std::size_t n : {15u, 16u, 17u, 31u, 32u, 33u}) EXPECT_TRUE(later.contains(n)) << n;
  // The last circles always touch another: a loop that leaves out a remainder of the index order shows.
  for (std::uint64_t round = 0; round < 12; ++round) {
    const Circles w = world(Family::sizes, round);
    const auto c = contacts(w);
    for (std::size_t k = w.size() - 3; k < w.size(); ++k) EXPECT_FALSE(c[k].empty()) << "round " << round;
  }
}

TEST(crowds, hubs_touched_by_9_to_257_circles_have_their_least_contact_at_the_9th_the_last_and_the_first_rank) {
  std::set<std::size_t> counts;
  for (std::uint64_t round = 0; round < 8; ++round) {
    const Circles w = world(Family::crowds, round);
    const auto c = contacts(w);
    const circles::impl::World ordered(w);
    bool ninth = false, last = false, first = false;  // the least contact's rank among a hub's contacts
    for (std::size_t k = 0; k < w.size(); ++k) {
      if (c[k].size() < 9) continue;
      counts.insert(c[k].size());
      const std::size_t l = least(ordered, c[k]);
      const auto rank = static_cast<std::size_t>(std::find(c[k].begin(), c[k].end(), l) - c[k].begin());
      ninth = ninth || rank == 8;
      last = last || rank == c[k].size() - 1;
      first = first || rank == 0;
      EXPECT_NE(w[l][3], w[k][3]);  // taking another contact's velocity would show
    }
    EXPECT_TRUE(ninth && last && first) << "round " << round;
  }
  EXPECT_EQ(*counts.begin(), 9u);
  EXPECT_EQ(*counts.rbegin(), 257u);
}

TEST(cell_crowds, an_aligned_square_of_a_power_of_two_holds_from_5_to_1000_centres) {
  std::vector<std::size_t> crowded;  // per round, the most centres in an aligned square of side 2^-4 … 2^8
  for (std::uint64_t round = 0; round < 9; ++round) {
    const Circles w = world(Family::cell_crowds, round);
    std::size_t most = 0;
    for (int e = -4; e <= 8; ++e) {
      std::map<std::pair<double, double>, std::size_t> cells;
      for (const auto& c : w) most = std::max(most, ++cells[{std::floor(std::ldexp(c[0], -e)), std::floor(std::ldexp(c[1], -e))}]);
    }
    crowded.push_back(most);
  }
  EXPECT_GE(crowded.front(), 5u);
  EXPECT_GE(*std::max_element(crowded.begin(), crowded.end()), 1000u);
}

TEST(radius_spread, radii_span_six_decimal_orders_with_the_big_circles_last_each_touching_small_ones) {
  for (std::uint64_t round = 0; round < 6; ++round) {
    const Circles w = world(Family::radius_spread, round);
    double smallest = INFINITY, largest = 0;
    for (const auto& c : w) smallest = std::min(smallest, c[4]), largest = std::max(largest, c[4]);
    EXPECT_GE(largest / smallest, 1e6) << "round " << round;
    const auto c = contacts(w);
    std::size_t big = 0;
    for (std::size_t k = w.size(); k-- > 0 && w[k][4] >= 1024;) {
      ++big;
      EXPECT_FALSE(c[k].empty()) << "round " << round << ", circle " << k;
    }
    EXPECT_GE(big, 2u);
    for (std::size_t k = 0; k + big < w.size(); ++k) EXPECT_LE(w[k][4], 1) << "round " << round;
  }
}

TEST(long_rows, rows_of_tangent_circles_reach_2048_wide_and_come_transposed) {
  std::size_t widest = 0;
  bool tall = false, wide = false;
  for (std::uint64_t round = 0; round < 12; ++round) {
    const Circles w = world(Family::long_rows, round);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const auto& c : w) x0 = std::min(x0, c[0]), x1 = std::max(x1, c[0]), y0 = std::min(y0, c[1]), y1 = std::max(y1, c[1]);
    const double d = 2 * w[0][4];
    const double along = std::max(x1 - x0, y1 - y0) / d + 1, across = std::min(x1 - x0, y1 - y0) / d + 1;
    EXPECT_LE(across, 2) << "round " << round;
    widest = std::max(widest, static_cast<std::size_t>(along));
    (x1 - x0 > y1 - y0 ? wide : tall) = true;
    const auto c = contacts(w);
    for (std::size_t k = 0; k < w.size(); ++k) EXPECT_FALSE(c[k].empty());
  }
  EXPECT_EQ(widest, 2048u);
  EXPECT_TRUE(wide && tall);
}

// Circle c's least contact i >= 2^b, and c also touches i mod 2^b, whose velocity differs.
std::size_t high_bit_contacts(const Circles& w, std::size_t bits) {
  const std::size_t low = std::size_t{1} << bits;
  const auto c = contacts(w);
  const circles::impl::World ordered(w);
  std::size_t found = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (c[k].empty()) continue;
    const std::size_t i = least(ordered, c[k]);
    found += i >= low && std::binary_search(c[k].begin(), c[k].end(), i % low) && w[i % low][3] != w[i][3];
  }
  return found;
}

TEST(index_bits, the_least_contact_past_2_to_the_8_sits_beside_a_contact_that_differs_only_in_its_high_bits) {
  for (std::uint64_t round = 0; round < 6; ++round) {
    const Circles w = world(Family::index_bits, round);
    EXPECT_GT(w.size(), 256u);
    EXPECT_GE(high_bit_contacts(w, 8), 3u) << "round " << round;
  }
}

TEST(index_bits, crosses_2_to_the_16_when_the_limit_allows) {
  const Circles w = world(Family::index_bits, 1, 70000);
  EXPECT_GT(w.size(), 65536u);
  EXPECT_GE(high_bit_contacts(w, 16), 3u);
  EXPECT_LE(world(Family::index_bits, 1).size(), 256u + 64u);  // by default only 2^8
}

// The ranks in `key` order (then by index) of the circles.
std::vector<std::size_t> by(const Circles& w, std::size_t field) {
  std::vector<std::size_t> order(w.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return w[a][field] < w[b][field]; });
  return order;
}

TEST(order_borders, a_contact_crosses_every_eighth_border_of_the_index_x_and_y_orders) {
  for (std::uint64_t round = 0; round < 8; ++round) {
    const Circles w = world(Family::order_borders, round);
    const std::size_t n = w.size();
    const std::vector<std::size_t> x = by(w, 0), y = by(w, 1);
    for (std::size_t f = 1; f < 8; ++f) {
      const std::size_t b = n * f / 8;
      EXPECT_TRUE(touch(w, b - 1, b)) << "index border " << b << ", round " << round;
      EXPECT_TRUE(touch(w, x[b - 1], x[b])) << "x border " << b << ", round " << round;
      EXPECT_TRUE(touch(w, y[b - 1], y[b])) << "y border " << b << ", round " << round;
    }
  }
}

TEST(big_chains, contacts_change_within_the_three_steps_of_a_chain) {
  for (std::uint64_t round = 0; round < 6; ++round) {
    Circles w = world(Family::big_chains, round);
    const auto before = contacts(w);
    for (int step = 0; step < 3; ++step) w = circles::impl::step_all_pairs(circles::impl::World{w}).circles();
    EXPECT_NE(contacts(w), before) << "round " << round;
  }
}

}  // namespace
