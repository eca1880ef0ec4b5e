#include "scout/sensor/laser_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace scout::sensor {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Four beams at -90, 0, 90 and 180 degrees.
LaserScan MakeScan(std::vector<float> ranges) {
  LaserScan scan;
  scan.angle_min_rad = -kPi / 2;
  scan.angle_increment_rad = kPi / 2;
  scan.range_min_m = 0.1f;
  scan.range_max_m = 8.f;
  scan.ranges = std::move(ranges);
  return scan;
}

TEST(ToRangeData, PlacesReturnsAtBeamAngles) {
  const RangeData data = ToRangeData(MakeScan({1.f, 2.f, 3.f, 4.f}), {});
  ASSERT_EQ(data.returns.size(), 4u);
  EXPECT_TRUE(data.misses.empty());
  EXPECT_NEAR(data.returns[0].x(), 0.0, 1e-6);
  EXPECT_NEAR(data.returns[0].y(), -1.0, 1e-6);
  EXPECT_NEAR(data.returns[1].x(), 2.0, 1e-6);
  EXPECT_NEAR(data.returns[1].y(), 0.0, 1e-6);
  EXPECT_NEAR(data.returns[2].y(), 3.0, 1e-6);
  EXPECT_NEAR(data.returns[3].x(), -4.0, 1e-6);
}

TEST(ToRangeData, BeamsWithoutReturnBecomeMissesOfRayLength) {
  RangeFilterOptions options;
  options.miss_ray_length_m = 5.0;
  const RangeData data = ToRangeData(MakeScan({kNaN, kInf, 8.f, 9.f}), options);
  EXPECT_TRUE(data.returns.empty());
  ASSERT_EQ(data.misses.size(), 4u);
  for (const Eigen::Vector2d& miss : data.misses) EXPECT_NEAR(miss.norm(), 5.0, 1e-9);
  EXPECT_NEAR(data.misses[1].x(), 5.0, 1e-6);
}

TEST(ToRangeData, ZeroRayLengthDropsMisses) {
  RangeFilterOptions options;
  options.miss_ray_length_m = 0.0;
  const RangeData data = ToRangeData(MakeScan({kNaN, 1.f, kInf, 8.f}), options);
  EXPECT_EQ(data.returns.size(), 1u);
  EXPECT_TRUE(data.misses.empty());
}

TEST(ToRangeData, DropsReturnsBelowMinimumRange) {
  RangeFilterOptions options;
  options.min_range_m = 0.5;
  // 0.05 is below the scan's own minimum, 0.3 below the filter's.
  const RangeData data = ToRangeData(MakeScan({0.05f, 0.3f, 0.5f, 1.f}), options);
  EXPECT_EQ(data.returns.size(), 2u);
  EXPECT_TRUE(data.misses.empty());
}

TEST(ToRangeData, FilterMaximumBelowScanMaximumTurnsFarReturnsIntoMisses) {
  RangeFilterOptions options;
  options.max_range_m = 3.0;
  options.miss_ray_length_m = 2.0;
  const RangeData data = ToRangeData(MakeScan({1.f, 2.9f, 3.f, 7.f}), options);
  EXPECT_EQ(data.returns.size(), 2u);
  ASSERT_EQ(data.misses.size(), 2u);
  EXPECT_NEAR(data.misses[0].norm(), 2.0, 1e-9);
}

TEST(ToRangeData, NoRayIsLongerThanTheLimitWhateverTheScanSays) {
  // A corrupt log: a range maximum of 1e20 m and a reading of 1e7 m.
  LaserScan scan = MakeScan({1.f, 1e7f, 150.f, kInf});
  scan.range_max_m = 1e20f;
  const RangeData data = ToRangeData(scan, {});  // no filter maximum
  ASSERT_EQ(data.returns.size(), 2u);
  EXPECT_NEAR(data.returns[1].norm(), 150.0, 1e-3);
  ASSERT_EQ(data.misses.size(), 2u);  // 1e7 m and +inf: no return
  EXPECT_NEAR(data.misses[0].norm(), 5.0, 1e-9);
}

TEST(ValidateRangeFilter, BoundsRayLengths) {
  RangeFilterOptions options;
  EXPECT_NO_THROW(Validate(options));  // +inf maximum: the scan's own
  options.max_range_m = kMaxRayLength_m;
  EXPECT_NO_THROW(Validate(options));
  options.max_range_m = 1e6;
  EXPECT_THROW(Validate(options), std::invalid_argument);
  options.max_range_m = 15.0;
  options.miss_ray_length_m = 1e9;
  EXPECT_THROW(Validate(options), std::invalid_argument);
}

TEST(ToRangeData, RejectsNegativeOptions) {
  RangeFilterOptions options;
  options.min_range_m = -1.0;
  EXPECT_THROW(ToRangeData(MakeScan({1.f}), options), std::invalid_argument);
}

}  // namespace
}  // namespace scout::sensor
