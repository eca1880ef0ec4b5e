#include "scout/sim/lidar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scout/common/error.h"
#include "scout/sim/ray_caster.h"
#include "scout/sim/world_painter.h"

namespace scout::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// A 5 m x 5 m free room, origin at (0, 0), with a wall filling x >= 3 m.
World MakeWallWorld() {
  World world;
  world.name = "wall";
  world.map = MakeFilledMap(geometry::Box2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(5, 5)), 0.05,
                            grid::CellState::kFree);
  FillBox(geometry::Box2d(Eigen::Vector2d(3, 0), Eigen::Vector2d(5, 5)), grid::CellState::kOccupied,
          &world.map);
  return world;
}

// One beam per degree, so beam k looks k - 90 degrees off the heading.
LidarOptions OneDegreeOptions() {
  LidarOptions options;
  options.beams = 181;
  return options;
}

LidarOptions NoiselessOptions() {
  LidarOptions options = OneDegreeOptions();
  options.range_noise_stddev_m = 0.0;
  return options;
}

TEST(Lidar, DefaultBeamsAreHalfADegreeApartOverTheFieldOfView) {
  std::mt19937_64 rng(1);
  const sensor::LaserScan scan =
      Lidar().Scan(MakeWallWorld(), geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng);
  ASSERT_EQ(scan.ranges.size(), 361u);
  EXPECT_NEAR(scan.angle_min_rad, -std::numbers::pi / 2.0, 1e-6);
  EXPECT_NEAR(scan.angle_increment_rad, std::numbers::pi / 360.0, 1e-6);
}

TEST(Lidar, RangeToWallIsExact) {
  const World world = MakeWallWorld();
  const Lidar lidar(NoiselessOptions());
  std::mt19937_64 rng(1);
  const sensor::LaserScan scan = lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng);
  ASSERT_EQ(scan.ranges.size(), 181u);
  EXPECT_NEAR(scan.angle_min_rad, -kPi / 2, 1e-6);
  EXPECT_NEAR(scan.angle_increment_rad, kPi / 180, 1e-6);
  // Beam 90 looks straight ahead at the wall 2 m away; beam 135 at 45 degrees.
  EXPECT_NEAR(scan.ranges[90], 2.0, 1e-5);
  EXPECT_NEAR(scan.ranges[135], 2.0 * std::sqrt(2.0), 1e-5);
}

TEST(Lidar, RayCastHitsWallAtCellBorder) {
  const World world = MakeWallWorld();
  EXPECT_NEAR(CastRay(world.map, Eigen::Vector2d(1.0, 2.5), 0.0, 8.0), 2.0, 1e-12);
  EXPECT_NEAR(CastRay(world.map, Eigen::Vector2d(1.23, 2.5), 0.0, 8.0), 1.77, 1e-12);
  // Looking back (-x) the ray leaves the map at x = 0, where unknown begins.
  EXPECT_NEAR(CastRay(world.map, Eigen::Vector2d(1.0, 2.5), kPi, 8.0), 1.0, 1e-12);
  EXPECT_EQ(CastRay(world.map, Eigen::Vector2d(3.5, 2.5), 0.0, 8.0), 0.0);
}

TEST(Lidar, BeyondRangeIsInfinity) {
  const World world = MakeWallWorld();
  LidarOptions options = NoiselessOptions();
  options.range_max_m = 1.5;
  const Lidar lidar(options);
  std::mt19937_64 rng(1);
  const sensor::LaserScan scan = lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng);
  EXPECT_TRUE(std::isinf(scan.ranges[90]));
  // Beam 0 looks along -y at the map border 2.5 m away.
  EXPECT_TRUE(std::isinf(scan.ranges[0]));
}

TEST(Lidar, UnknownCellsAreOpaque) {
  World world = MakeWallWorld();
  FillBox(geometry::Box2d(Eigen::Vector2d(2, 0), Eigen::Vector2d(2.5, 5)),
          grid::CellState::kUnknown, &world.map);
  const Lidar lidar(NoiselessOptions());
  std::mt19937_64 rng(1);
  const sensor::LaserScan scan = lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng);
  EXPECT_NEAR(scan.ranges[90], 1.0, 1e-5);
}

TEST(Lidar, HeadingRotatesBeams) {
  const World world = MakeWallWorld();
  const Lidar lidar(NoiselessOptions());
  std::mt19937_64 rng(1);
  // Facing +y, the rightmost beam (-90 degrees) looks along +x.
  const sensor::LaserScan scan = lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, kPi / 2), 0.0, rng);
  EXPECT_NEAR(scan.ranges[0], 2.0, 1e-5);
}

TEST(Lidar, NoiseHasConfiguredSpread) {
  const World world = MakeWallWorld();
  LidarOptions options = OneDegreeOptions();
  options.range_noise_stddev_m = 0.02;
  const Lidar lidar(options);
  std::mt19937_64 rng(5);
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (int i = 0; i < 2000; ++i) {
    const sensor::LaserScan scan = lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng);
    const double error = scan.ranges[90] - 2.0;
    sum += error;
    sum_sq += error * error;
    ++n;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 0.02, 0.002);
}

TEST(Lidar, SameRngStateGivesSameScan) {
  const World world = MakeWallWorld();
  const Lidar lidar(LidarOptions{});
  std::mt19937_64 a(9), b(9);
  const geometry::Rigid2d pose(1.0, 2.5, 0.3);
  EXPECT_EQ(lidar.Scan(world, pose, 0.0, a).ranges, lidar.Scan(world, pose, 0.0, b).ranges);
}

TEST(Lidar, FullDropoutReportsNoReturns) {
  const World world = MakeWallWorld();
  LidarOptions options;
  options.dropout_probability = 1.0;
  const Lidar lidar(options);
  std::mt19937_64 rng(1);
  for (float r : lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng).ranges) {
    EXPECT_TRUE(std::isnan(r));
  }
}

TEST(Lidar, DropoutRateMatchesProbability) {
  const World world = MakeWallWorld();
  LidarOptions options;
  options.dropout_probability = 0.1;
  const Lidar lidar(options);
  std::mt19937_64 rng(3);
  int dropped = 0, total = 0;
  for (int i = 0; i < 200; ++i) {
    for (float r : lidar.Scan(world, geometry::Rigid2d(1.0, 2.5, 0.0), 0.0, rng).ranges) {
      dropped += std::isnan(r) ? 1 : 0;
      ++total;
    }
  }
  // 36200 beams: the binomial sd of the rate is 0.0016.
  EXPECT_NEAR(static_cast<double>(dropped) / total, 0.1, 0.006);
}

TEST(Lidar, DropoutsLeaveTheOtherBeamsUnchanged) {
  const World world = MakeWallWorld();
  LidarOptions with_dropouts = OneDegreeOptions();
  with_dropouts.dropout_probability = 0.3;
  std::mt19937_64 a(4), b(4);
  const geometry::Rigid2d pose(1.0, 2.5, 0.2);
  const sensor::LaserScan dropped = Lidar(with_dropouts).Scan(world, pose, 0.0, a);
  const sensor::LaserScan full = Lidar(OneDegreeOptions()).Scan(world, pose, 0.0, b);
  int kept = 0;
  for (size_t k = 0; k < full.ranges.size(); ++k) {
    if (std::isnan(dropped.ranges[k])) continue;
    EXPECT_EQ(dropped.ranges[k], full.ranges[k]) << k;
    ++kept;
  }
  EXPECT_GT(kept, 90);
  EXPECT_LT(kept, 160);
}

TEST(Lidar, RejectsInvalidOptions) {
  LidarOptions options;
  options.beams = 0;
  EXPECT_THROW(Lidar{options}, InputError);
  options = LidarOptions{};
  options.fov_deg = 400.0;
  EXPECT_THROW(Lidar{options}, InputError);
}

}  // namespace
}  // namespace scout::sim
