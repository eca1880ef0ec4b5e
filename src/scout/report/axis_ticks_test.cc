#include "scout/report/axis_ticks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::report {
namespace {

TEST(NiceTicks, KnownAnswers) {
  AxisTicks t = NiceTicks(0, 97, 5);
  EXPECT_EQ(t.step, 20);
  EXPECT_EQ(t.ticks, (std::vector<double>{0, 20, 40, 60, 80, 100}));
  t = NiceTicks(0, 1, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_EQ(t.ticks, (std::vector<double>{0, 0.2, 0.4, 0.6, 0.8, 1.0}));
  t = NiceTicks(99.12, 100, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_DOUBLE_EQ(t.lo, 99.0);
  EXPECT_DOUBLE_EQ(t.hi, 100.0);
  EXPECT_EQ(t.ticks.size(), 6u);
  t = NiceTicks(-3, 7, 5);
  EXPECT_EQ(t.step, 2);
  EXPECT_EQ(t.ticks, (std::vector<double>{-4, -2, 0, 2, 4, 6, 8}));
  t = NiceTicks(0, 12345, 6);
  EXPECT_EQ(t.step, 2000);
  EXPECT_EQ(t.hi, 14000);
}

TEST(NiceTicks, FlatRangeIsWidenedAroundItsValue) {
  const AxisTicks t = NiceTicks(5, 5, 5);
  EXPECT_LT(t.lo, 5);
  EXPECT_GT(t.hi, 5);
  EXPECT_GE(t.ticks.size(), 3u);
  const AxisTicks zero = NiceTicks(0, 0, 5);
  EXPECT_LT(zero.lo, 0);
  EXPECT_GT(zero.hi, 0);
}

TEST(NiceTicks, TicksCoverTheRangeAndAreRoundMultiples) {
  for (const auto& [lo, hi] : {std::pair{0.013, 0.57}, {-120.0, 3.0}, {1e5, 3.3e6}, {7.0, 7.2}}) {
    const AxisTicks t = NiceTicks(lo, hi, 5);
    EXPECT_LE(t.lo, lo);
    EXPECT_GE(t.hi, hi);
    EXPECT_GE(t.ticks.size(), 3u);
    EXPECT_LE(t.ticks.size(), 12u);
    for (const double tick : t.ticks) {
      const double k = tick / t.step;
      EXPECT_NEAR(k, std::round(k), 1e-6) << tick << " step " << t.step;
    }
  }
}

TEST(LogTicks, DecadesAndFineTicksInOneDecade) {
  AxisTicks t = LogTicks(3, 45000);
  EXPECT_EQ(t.ticks, (std::vector<double>{1, 10, 100, 1000, 10000, 100000}));
  EXPECT_EQ(t.lo, 1);
  EXPECT_EQ(t.hi, 100000);
  t = LogTicks(20, 80);
  EXPECT_EQ(t.ticks, (std::vector<double>{10, 20, 50, 100}));
}

TEST(FormatTick, DecimalsFollowTheStepAndLargeValuesAreAbbreviated) {
  EXPECT_EQ(FormatTick(0.4, 0.2), "0.4");
  EXPECT_EQ(FormatTick(99.2, 0.2), "99.2");
  EXPECT_EQ(FormatTick(0.05, 0.05), "0.05");
  EXPECT_EQ(FormatTick(40, 20), "40");
  EXPECT_EQ(FormatTick(12000, 2000), "12k");
  EXPECT_EQ(FormatTick(3500000, 500000), "3.5M");
  EXPECT_EQ(FormatTick(1000, 0), "1000");
  EXPECT_EQ(FormatTick(100000, 0), "100k");
  EXPECT_EQ(FormatTick(10500, 500), "10.5k");
  EXPECT_EQ(FormatTick(0.01, 0), "0.01");
  EXPECT_EQ(FormatTick(-0.0, 1), "0");
}

TEST(TickLabels, OneAbbreviationPerAxis) {
  EXPECT_EQ(TickLabels(NiceTicks(0, 12000, 3)),
            (std::vector<std::string>{"0", "5k", "10k", "15k"}));
  EXPECT_EQ(TickLabels(NiceTicks(0, 8000, 4)),
            (std::vector<std::string>{"0", "2000", "4000", "6000", "8000"}));
  EXPECT_EQ(TickLabels(NiceTicks(0, 2.5e6, 5)),
            (std::vector<std::string>{"0", "0.5M", "1.0M", "1.5M", "2.0M", "2.5M"}));
  EXPECT_EQ(TickLabels(LogTicks(1, 1e5)),
            (std::vector<std::string>{"1", "10", "100", "1000", "10k", "100k"}));
}

}  // namespace
}  // namespace scout::report
