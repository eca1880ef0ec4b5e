#include "scout/sensor/motion_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace scout::sensor {
namespace {

using geometry::Rigid2d;

TEST(MotionFilterTest, AcceptsFirstPoseThenOnlyAfterEnoughMotionOrTime) {
  MotionFilter filter(MotionFilterOptions{});
  EXPECT_TRUE(filter.Accept(0.0, Rigid2d(0.0, 0.0, 0.0)));
  EXPECT_FALSE(filter.Accept(1.0, Rigid2d(0.1, 0.0, 0.0)));
  EXPECT_FALSE(filter.Accept(2.0, Rigid2d(0.19, 0.0, 0.0)));
  EXPECT_TRUE(filter.Accept(2.5, Rigid2d(0.0, 0.21, 0.0)));  // 0.21 m from the first
  // Distances are measured from the last *accepted* pose.
  EXPECT_FALSE(filter.Accept(3.0, Rigid2d(0.1, 0.21, 0.0)));
  EXPECT_TRUE(filter.Accept(3.5, Rigid2d(0.0, 0.21, 1.1 * std::numbers::pi / 180.0)));
  EXPECT_FALSE(filter.Accept(8.4, Rigid2d(0.0, 0.21, 1.1 * std::numbers::pi / 180.0)));
  EXPECT_TRUE(filter.Accept(8.5, Rigid2d(0.0, 0.21, 1.1 * std::numbers::pi / 180.0)));
  EXPECT_EQ(filter.num_accepted(), 4);
  EXPECT_EQ(filter.num_total(), 8);
}

TEST(MotionFilterTest, TurnAcrossMinusPiCountsAsSmall) {
  MotionFilter filter(MotionFilterOptions{});
  EXPECT_TRUE(filter.Accept(0.0, Rigid2d(0.0, 0.0, std::numbers::pi - 0.001)));
  EXPECT_FALSE(filter.Accept(0.1, Rigid2d(0.0, 0.0, -std::numbers::pi + 0.001)));
}

TEST(MotionFilterTest, RejectsInvalidOptionsNamingThem) {
  MotionFilterOptions options;
  options.max_distance_m = -1.0;
  try {
    MotionFilter filter(options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_distance_m"), std::string::npos);
  }
  options = {};
  options.max_time_s = std::nan("");
  EXPECT_THROW(MotionFilter{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scout::sensor
