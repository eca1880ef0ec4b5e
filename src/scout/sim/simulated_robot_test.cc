#include "scout/sim/simulated_robot.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scout/common/error.h"
#include "scout/sim/make_world.h"
#include "scout/sim/world_painter.h"

namespace scout::sim {
namespace {

// A 6 m x 4 m free room with a wall filling x >= 4 m; start at (1, 2).
World MakeWallWorld() {
  World world;
  world.name = "wall";
  world.map = MakeFilledMap(geometry::Box2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(6, 4)), 0.05,
                            grid::CellState::kFree);
  FillBox(geometry::Box2d(Eigen::Vector2d(4, 0), Eigen::Vector2d(6, 4)), grid::CellState::kOccupied,
          &world.map);
  world.start = Eigen::Vector2d(1, 2);
  return world;
}

struct Recording {
  std::vector<sensor::LaserScan> scans;
  std::vector<sensor::Odometry> odometry;
  std::vector<geometry::Rigid2d> true_poses_at_odometry;
};

// Drives forward-left for 'steps' steps of 'dt_s', reading sensors after each.
Recording Drive(SimulatedRobot* robot, int steps, double dt_s) {
  Recording r;
  const auto read = [&] {
    if (auto scan = robot->MaybeScan()) r.scans.push_back(*scan);
    if (auto odometry = robot->MaybeOdometry()) {
      r.odometry.push_back(*odometry);
      r.true_poses_at_odometry.push_back(robot->true_pose());
    }
  };
  read();
  for (int i = 0; i < steps; ++i) {
    robot->Step(0.3, 0.2, dt_s);
    read();
  }
  return r;
}

TEST(SimulatedRobot, SensorRatesAndTimestamps) {
  const World world = MakeWallWorld();
  SimulatedRobotOptions options;
  options.odometry_rate_hz = 50.0;
  SimulatedRobot robot(world, options, 1);
  const Recording r = Drive(&robot, 100, 0.01);
  EXPECT_NEAR(robot.sim_time_s(), 1.0, 1e-12);
  // t = 0, 0.1, ..., 1.0 and t = 0, 0.02, ..., 1.0.
  ASSERT_EQ(r.scans.size(), 11u);
  ASSERT_EQ(r.odometry.size(), 51u);
  for (size_t k = 0; k < r.scans.size(); ++k) {
    EXPECT_NEAR(r.scans[k].time_s, 0.1 * k, 1e-9);
    EXPECT_EQ(r.scans[k].ranges.size(), 361u);
  }
  for (size_t k = 0; k < r.odometry.size(); ++k) EXPECT_NEAR(r.odometry[k].time_s, 0.02 * k, 1e-9);
  EXPECT_EQ(robot.OdometryReading().time_s, r.odometry.back().time_s);
}

TEST(SimulatedRobot, StepsLongerThanAPeriodTakeTheFirstStepAtOrAfterEachDueTime) {
  const World world = MakeWallWorld();
  SimulatedRobotOptions options;
  options.odometry_rate_hz = 50.0;
  SimulatedRobot robot(world, options, 1);
  // 0.03 s steps: scans due every 0.1 s are taken at 0, 0.12, 0.21, 0.3, ...
  const Recording r = Drive(&robot, 100, 0.03);
  ASSERT_EQ(r.scans.size(), 31u);
  for (size_t k = 0; k < r.scans.size(); ++k) {
    const double due_s = 0.1 * k;
    EXPECT_GE(r.scans[k].time_s, due_s - 1e-9);
    EXPECT_LT(r.scans[k].time_s, due_s + 0.03 - 1e-9);
  }
  // Odometry is due every 0.02 s, faster than the steps: one sample per step.
  EXPECT_EQ(r.odometry.size(), 101u);
}

TEST(SimulatedRobot, ScansSeeTheTrueWorldFromTheTruePose) {
  const World world = MakeWallWorld();
  SimulatedRobotOptions options;
  options.lidar.range_noise_stddev_m = 0.0;
  SimulatedRobot robot(world, options, 1);
  for (int i = 0; i < 37; ++i) robot.Step(0.4, 0.0, 0.01);
  for (int i = 0; i < 13; ++i) robot.Step(0.4, 0.0, 0.01);
  const std::optional<sensor::LaserScan> scan = robot.MaybeScan();
  ASSERT_TRUE(scan.has_value());
  EXPECT_NEAR(scan->time_s, 0.5, 1e-9);
  // The middle beam looks straight at the wall x = 4.
  EXPECT_NEAR(scan->ranges[scan->ranges.size() / 2], 4.0 - robot.true_pose().x(), 1e-5);
  EXPECT_FALSE(robot.MaybeScan().has_value());
}

TEST(SimulatedRobot, ZeroOdometryNoiseEqualsTruth) {
  const World world = MakeWallWorld();
  SimulatedRobotOptions options;
  options.odometry = OdometryNoiseOptions{0, 0, 0, 0};
  SimulatedRobot robot(world, options, 3);
  const Recording r = Drive(&robot, 500, 0.01);
  for (size_t k = 0; k < r.odometry.size(); ++k) {
    const geometry::Rigid2d& odometry = r.odometry[k].pose;
    ASSERT_NEAR((odometry.translation() - r.true_poses_at_odometry[k].translation()).norm(), 0.0,
                1e-9);
  }
}

TEST(SimulatedRobot, SameSeedSameReadings) {
  const World world = MakeWallWorld();
  SimulatedRobot a(world, SimulatedRobotOptions{}, 5);
  SimulatedRobot b(world, SimulatedRobotOptions{}, 5);
  SimulatedRobot c(world, SimulatedRobotOptions{}, 6);
  const Recording ra = Drive(&a, 300, 0.01);
  const Recording rb = Drive(&b, 300, 0.01);
  const Recording rc = Drive(&c, 300, 0.01);
  ASSERT_EQ(ra.scans.size(), rb.scans.size());
  for (size_t k = 0; k < ra.scans.size(); ++k) EXPECT_EQ(ra.scans[k].ranges, rb.scans[k].ranges);
  EXPECT_EQ(ra.odometry.back().pose.translation(), rb.odometry.back().pose.translation());
  EXPECT_NE(ra.scans.back().ranges, rc.scans.back().ranges);
  EXPECT_NE(ra.odometry.back().pose.translation(), rc.odometry.back().pose.translation());
  // Noise never touches the truth.
  EXPECT_EQ(a.true_pose().translation(), c.true_pose().translation());
}

TEST(SimulatedRobot, CountsCollisionsAndTruePathLength) {
  const World world = MakeWallWorld();
  SimulatedRobot robot(world, SimulatedRobotOptions{}, 1);
  for (int i = 0; i < 1000; ++i) robot.Step(0.5, 0.0, 0.01);
  EXPECT_EQ(robot.collisions(), 1);
  EXPECT_NEAR(robot.true_pose().x(), 4.0 - 0.2, 0.25 * 0.05);
  EXPECT_NEAR(robot.path_length_m(), robot.true_pose().x() - 1.0, 1e-9);
}

TEST(SimulatedRobot, InvalidOptionsAreInputErrors) {
  const World world = MakeWallWorld();
  SimulatedRobotOptions options;
  options.scan_rate_hz = 0.0;
  EXPECT_THROW(SimulatedRobot(world, options, 1), InputError);
  options = SimulatedRobotOptions{};
  options.lidar.dropout_probability = 2.0;
  EXPECT_THROW(SimulatedRobot(world, options, 1), InputError);
  options = SimulatedRobotOptions{};
  options.robot.radius_m = 1.5;  // does not fit at the start
  EXPECT_THROW(SimulatedRobot(world, options, 1), InputError);
}

// Wanders the generated office with a crude bumper controller and reports
// the cost of a 10 ms step including 10 Hz scans and 20 Hz odometry.
TEST(SimulatedRobot, WandersTheOfficeWithoutErrors) {
  const World world = MakeWorld("office", 1);
  SimulatedRobot robot(world, SimulatedRobotOptions{}, 1);
  const auto begin = std::chrono::steady_clock::now();
  const int steps = 20000;
  int scans = 0;
  double turn_until_s = -1.0;
  for (int i = 0; i < steps; ++i) {
    const std::optional<sensor::LaserScan> scan = robot.MaybeScan();
    if (scan) {
      ++scans;
      // Turn for a while when something is close ahead.
      const float ahead = scan->ranges[90];
      if (!std::isnan(ahead) && ahead < 0.6) turn_until_s = robot.sim_time_s() + 1.0;
    }
    const bool turning = robot.sim_time_s() < turn_until_s;
    robot.Step(turning ? 0.0 : 0.5, turning ? 0.8 : 0.0, 0.01);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::printf("office: %.1f m in %.0f s sim, %d collisions, %.2f us per step\n",
              robot.path_length_m(), robot.sim_time_s(), robot.collisions(), 1e6 * seconds / steps);
  // The robot alone (no sensors) circling at its start, 0.3 m radius.
  DiffDriveRobot bare(world.map, DiffDriveOptions{}, geometry::Rigid2d(world.start, 0.0));
  const auto bare_begin = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) bare.Step(0.3, 1.0, 0.01);
  const double bare_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - bare_begin).count();
  std::printf("office: DiffDriveRobot::Step alone %.3f us per 10 ms step (%d blocked)\n",
              1e6 * bare_seconds / steps, bare.blocked_steps());
  EXPECT_EQ(scans, 2000);
  EXPECT_GT(robot.path_length_m(), 5.0);
}

}  // namespace
}  // namespace scout::sim
