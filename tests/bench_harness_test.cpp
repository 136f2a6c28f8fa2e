// The benchmark programs' names (bench/harness.hpp): coverage as scripts/benchmarks' coverage_label writes it,
// which tests/benchmarks_script_test.py holds to the same labels, so that every name the script asks for is
// one the programs register.
#include "bench/harness.hpp"

#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace circles::bench {
namespace {

using circles::testing::thrown;

// A whole percent, or one decimal: 1.5% is "1.5" (not "0.15"), 12.5% is "12.5".
TEST(bench_harness, names_a_coverage_in_whole_percent_or_one_decimal_as_scripts_benchmarks_does) {
  EXPECT_EQ(coverage_percent(0.001), "0.1");
  EXPECT_EQ(coverage_percent(0.01), "1");
  EXPECT_EQ(coverage_percent(0.015), "1.5");
  EXPECT_EQ(coverage_percent(0.10), "10");
  EXPECT_EQ(coverage_percent(0.125), "12.5");
  EXPECT_EQ(coverage_percent(0.40), "40");
  EXPECT_EQ(configuration_name("double_engine", 0.015, 2, 1000), "double_engine/coverage:1.5/threads:2/n:1000");
}

// 0.05% would be named as 0.1% is: refused, saying why.
TEST(bench_harness, refuses_a_coverage_finer_than_a_tenth_of_a_percent) {
  const auto finer = thrown<std::invalid_argument>([] { coverage_percent(0.0005); });
  ASSERT_TRUE(finer);
  EXPECT_STREQ(finer->what(),
               "coverage 0.05%: finer than a tenth of a percent, which benchmark names do not tell apart");
  EXPECT_TRUE(thrown<std::invalid_argument>([] { coverage_percent(0.0015 + 0.0001 / 3); }));
  const auto negative = thrown<std::invalid_argument>([] { coverage_percent(-0.1); });
  ASSERT_TRUE(negative);
  EXPECT_STREQ(negative->what(), "coverage -0.1: expected a fraction of the area, 0 or more");
  EXPECT_TRUE(thrown<std::invalid_argument>([] { coverage_percent(std::numeric_limits<double>::quiet_NaN()); }));
}

}  // namespace
}  // namespace circles::bench
