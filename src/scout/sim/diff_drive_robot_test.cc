#include "scout/sim/diff_drive_robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "scout/common/error.h"
#include "scout/sim/random.h"
#include "scout/sim/world_painter.h"

namespace scout::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDt = 0.01;

// A 10 m x 10 m free room at 5 cm, walls beyond its border.
grid::OccupancyMap MakeRoom() {
  return MakeFilledMap(geometry::Box2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10)), 0.05,
                       grid::CellState::kFree);
}

// The room with a wall filling x >= 3 m.
grid::OccupancyMap MakeWallRoom() {
  grid::OccupancyMap map = MakeRoom();
  FillBox(geometry::Box2d(Eigen::Vector2d(3, 0), Eigen::Vector2d(10, 10)),
          grid::CellState::kOccupied, &map);
  return map;
}

// Options whose velocities reach any command within one step.
DiffDriveOptions InstantOptions() {
  DiffDriveOptions options;
  options.max_linear_accel_mps2 = 1e6;
  options.max_angular_accel_radps2 = 1e6;
  return options;
}

void ExpectPoseNear(const geometry::Rigid2d& actual, double x, double y, double theta,
                    double tolerance) {
  EXPECT_NEAR(actual.x(), x, tolerance);
  EXPECT_NEAR(actual.y(), y, tolerance);
  EXPECT_NEAR(geometry::NormalizeAngle(actual.theta() - theta), 0.0, tolerance);
}

TEST(IntegrateArc, StraightLineAndQuarterCircle) {
  ExpectPoseNear(IntegrateArc(geometry::Rigid2d(1, 2, kPi / 2), 0.5, 0.0, 2.0), 1, 3, kPi / 2,
                 1e-12);
  // Radius v / omega = 1 m, turning left by pi / 2.
  ExpectPoseNear(IntegrateArc(geometry::Rigid2d(0, 0, 0), 0.5, 0.5, kPi), 1, 1, kPi / 2, 1e-12);
  // Backwards while turning left: about the centre (0, -1), ending behind.
  ExpectPoseNear(IntegrateArc(geometry::Rigid2d(0, 0, 0), -0.5, 0.5, kPi), -1, -1, kPi / 2, 1e-12);
}

TEST(IntegrateArc, PiecesComposeToTheWhole) {
  const geometry::Rigid2d start(0.3, -0.2, 0.4);
  geometry::Rigid2d pose = start;
  for (int i = 0; i < 1000; ++i) pose = IntegrateArc(pose, 0.4, -0.7, 0.003);
  const geometry::Rigid2d whole = IntegrateArc(start, 0.4, -0.7, 3.0);
  ExpectPoseNear(pose, whole.x(), whole.y(), whole.theta(), 1e-10);
  // A tiny turn rate stays on the straight-line limit.
  ExpectPoseNear(IntegrateArc(start, 0.4, 1e-12, 3.0), 0.3 + 1.2 * std::cos(0.4),
                 -0.2 + 1.2 * std::sin(0.4), 0.4, 1e-10);
}

TEST(DiffDriveRobot, DrivesTheExactCircle) {
  const grid::OccupancyMap map = MakeRoom();
  DiffDriveRobot robot(map, InstantOptions(), geometry::Rigid2d(5, 4, 0));
  // v = 0.4 m/s, omega = 0.8 rad/s: a circle of radius 0.5 m about (5, 4.5).
  for (int i = 0; i < 250; ++i) EXPECT_FALSE(robot.Step(0.4, 0.8, kDt).blocked);
  const double turn = 0.8 * 2.5;
  ExpectPoseNear(robot.pose(), 5 + 0.5 * std::sin(turn), 4 + 0.5 * (1 - std::cos(turn)), turn,
                 1e-9);
  EXPECT_NEAR(robot.path_length_m(), 1.0, 1e-9);
}

TEST(DiffDriveRobot, StraightLineWithAccelerationRamp) {
  const grid::OccupancyMap map = MakeRoom();
  DiffDriveRobot robot(map, DiffDriveOptions{}, geometry::Rigid2d(2, 5, 0));
  for (int i = 0; i < 300; ++i) robot.Step(0.5, 0.0, kDt);
  // Speed k * 0.005 m/s over step k = 1..100, then 0.5 m/s for 200 steps.
  const double expected_m = 0.005 * kDt * (100 * 101 / 2) + 200 * 0.5 * kDt;
  ExpectPoseNear(robot.pose(), 2 + expected_m, 5, 0, 1e-9);
  EXPECT_NEAR(robot.path_length_m(), expected_m, 1e-9);
  EXPECT_DOUBLE_EQ(robot.linear_velocity_mps(), 0.5);
}

TEST(DiffDriveRobot, RespectsAccelerationAndSpeedLimits) {
  const grid::OccupancyMap map = MakeRoom();
  const DiffDriveOptions options;
  DiffDriveRobot robot(map, options, geometry::Rigid2d(5, 5, 0));
  std::mt19937_64 rng(11);
  double v = 0.0, omega = 0.0;
  int at_top_speed = 0;
  for (int i = 0; i < 3000; ++i) {
    // Commands beyond every limit, changing sign now and then.
    const double v_cmd = (i / 300) % 2 == 0 ? 5.0 : -5.0;
    const double omega_cmd = UniformReal(rng, -10.0, 10.0);
    // Stay inside the room: turn back towards its centre when far out.
    const Eigen::Vector2d to_center = Eigen::Vector2d(5, 5) - robot.pose().translation();
    robot.Step(to_center.norm() > 3.0 ? 0.0 : v_cmd, omega_cmd, kDt);
    const double dv = robot.linear_velocity_mps() - v;
    const double domega = robot.angular_velocity_radps() - omega;
    ASSERT_LE(std::abs(dv), options.max_linear_accel_mps2 * kDt + 1e-12);
    ASSERT_LE(std::abs(domega), options.max_angular_accel_radps2 * kDt + 1e-12);
    ASSERT_LE(std::abs(robot.linear_velocity_mps()), options.max_linear_speed_mps);
    ASSERT_LE(std::abs(robot.angular_velocity_radps()), options.max_angular_speed_radps);
    v = robot.linear_velocity_mps();
    omega = robot.angular_velocity_radps();
    at_top_speed += std::abs(v) == options.max_linear_speed_mps ? 1 : 0;
  }
  EXPECT_GT(at_top_speed, 100);
  EXPECT_EQ(robot.collisions(), 0);
}

TEST(DiffDriveRobot, BrakingTakesOneSecondFromTopSpeed) {
  const grid::OccupancyMap map = MakeRoom();
  DiffDriveRobot braking(map, DiffDriveOptions{}, geometry::Rigid2d(2, 5, 0));
  for (int i = 0; i < 200; ++i) braking.Step(0.5, 0.0, kDt);
  int steps_to_stop = 0;
  while (braking.linear_velocity_mps() > 0.0) {
    braking.Step(0.0, 0.0, kDt);
    ++steps_to_stop;
  }
  // 0.5 m/s at 0.5 m/s^2; round-off in the summed speed may need one more step.
  EXPECT_NEAR(steps_to_stop, 100, 1);
}

TEST(DiffDriveRobot, StopsAtTheWallAndCountsOneCollision) {
  const grid::OccupancyMap map = MakeWallRoom();
  const DiffDriveOptions options;
  DiffDriveRobot robot(map, options, geometry::Rigid2d(1, 5, 0));
  int first_block = -1;
  for (int i = 0; i < 1000; ++i) {
    const DiffDriveStepResult result = robot.Step(0.5, 0.0, kDt);
    if (result.blocked && first_block < 0) first_block = i;
    // The disc never overlaps the wall (x >= 3 m).
    ASSERT_LE(robot.pose().x(), 3.0 - options.radius_m);
  }
  ASSERT_GE(first_block, 0);
  // Stopped no farther than one substep (a quarter cell) from contact.
  EXPECT_GE(robot.pose().x(), 3.0 - options.radius_m - 0.25 * 0.05);
  EXPECT_NEAR(robot.pose().y(), 5.0, 1e-12);
  EXPECT_EQ(robot.linear_velocity_mps(), 0.0);
  // Pushing on for many steps is still the same collision.
  EXPECT_EQ(robot.collisions(), 1);
  EXPECT_GT(robot.blocked_steps(), 10);

  // Back off, then hit the wall again: a second collision.
  for (int i = 0; i < 200; ++i) robot.Step(-0.5, 0.0, kDt);
  EXPECT_LT(robot.pose().x(), 2.5);
  for (int i = 0; i < 400; ++i) robot.Step(0.5, 0.0, kDt);
  EXPECT_EQ(robot.collisions(), 2);
}

TEST(DiffDriveRobot, LongStepsDoNotTunnelThroughThinWalls) {
  grid::OccupancyMap map = MakeRoom();
  // A wall one cell thick at x in [2.5, 2.55).
  FillBox(geometry::Box2d(Eigen::Vector2d(2.5, 0), Eigen::Vector2d(2.55, 10)),
          grid::CellState::kOccupied, &map);
  const DiffDriveOptions options = InstantOptions();
  DiffDriveRobot robot(map, options, geometry::Rigid2d(2, 5, 0.1));
  // One 2 s step would end at x ~ 3, clear of the wall on its far side.
  EXPECT_TRUE(robot.Step(0.5, 0.0, 2.0).blocked);
  EXPECT_LE(robot.pose().x(), 2.5 - options.radius_m);
  EXPECT_GE(robot.pose().x(), 2.5 - options.radius_m - 0.25 * 0.05);
  EXPECT_NEAR(robot.pose().theta(), 0.1, 1e-12);
  EXPECT_EQ(robot.collisions(), 1);
}

TEST(DiffDriveRobot, RandomDrivingNeverOverlapsAnObstacle) {
  grid::OccupancyMap map = MakeRoom();
  // Pillars and a single-cell post to graze at every angle.
  FillBox(geometry::Box2d(Eigen::Vector2d(3, 3), Eigen::Vector2d(4, 4.2)),
          grid::CellState::kOccupied, &map);
  FillBox(geometry::Box2d(Eigen::Vector2d(6, 6), Eigen::Vector2d(6.05, 6.05)),
          grid::CellState::kOccupied, &map);
  FillBox(geometry::Box2d(Eigen::Vector2d(6.5, 2), Eigen::Vector2d(7.5, 3)),
          grid::CellState::kUnknown, &map);
  const DiffDriveOptions options;
  DiffDriveRobot robot(map, options, geometry::Rigid2d(5, 5, 0));
  std::mt19937_64 rng(21);
  double v_cmd = 0.5, omega_cmd = 0.0;
  for (int i = 0; i < 60000; ++i) {
    if (i % 50 == 0) {
      v_cmd = UniformReal(rng, -0.3, 0.6);
      omega_cmd = UniformReal(rng, -1.0, 1.0);
    }
    robot.Step(v_cmd, omega_cmd, kDt);
    ASSERT_GE(robot.collision_checker().ExactDistanceToObstacle(robot.pose().translation(), 1.0),
              options.radius_m - 1e-9)
        << "step " << i;
  }
  // The walk did hit things, so the stops were exercised.
  EXPECT_GT(robot.collisions(), 5);
  EXPECT_GT(robot.path_length_m(), 50.0);
}

TEST(DiffDriveRobot, StartOverlappingAnObstacleIsAnInputError) {
  const grid::OccupancyMap map = MakeWallRoom();
  EXPECT_THROW(DiffDriveRobot(map, DiffDriveOptions{}, geometry::Rigid2d(2.9, 5, 0)), InputError);
}

TEST(DiffDriveRobot, InvalidOptionsNameTheKey) {
  DiffDriveOptions options;
  options.max_angular_accel_radps2 = -1.0;
  try {
    CheckDiffDriveOptions(options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.max_angular_accel_radps2"), std::string::npos);
  }
  options = DiffDriveOptions{};
  options.collision_substep_cells = 2.0;
  EXPECT_THROW(CheckDiffDriveOptions(options), InputError);
  options.collision_substep_cells = 1e-9;  // would never finish a step
  EXPECT_THROW(CheckDiffDriveOptions(options), InputError);
  options = DiffDriveOptions{};
  options.radius_m = std::nan("");
  EXPECT_THROW(CheckDiffDriveOptions(options), InputError);
}

TEST(DiffDriveRobot, RejectsBadStepArguments) {
  const grid::OccupancyMap map = MakeRoom();
  DiffDriveRobot robot(map, DiffDriveOptions{}, geometry::Rigid2d(5, 5, 0));
  EXPECT_THROW(robot.Step(0.1, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(robot.Step(std::nan(""), 0.0, kDt), std::invalid_argument);
}

}  // namespace
}  // namespace scout::sim
