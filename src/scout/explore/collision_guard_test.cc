#include "scout/explore/collision_guard.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "scout/explore/collision_guard_test_util.h"

namespace scout::explore {
namespace {

constexpr double kRadius = 0.2;

// Drives the command in small steps, each guarded by 'guard' (obstacles
// moved into the new robot frame), and returns the closest approach; 'end'
// (if given) gets where the robot ends up.
template <typename Guard>
double ClosestApproachGuardedBy(const Guard& guard, const VelocityCommand& command,
                                const std::vector<Eigen::Vector2d>& obstacles, double duration_s,
                                Eigen::Vector2d* end = nullptr) {
  Eigen::Vector2d pos(0, 0);
  double heading = 0.0;
  double closest = 1e9;
  const double dt = 0.01;
  for (double t = 0; t < duration_s; t += dt) {
    std::vector<Eigen::Vector2d> local;
    const Eigen::Rotation2Dd to_robot(-heading);
    for (const Eigen::Vector2d& p : obstacles) local.push_back(to_robot * (p - pos));
    const GuardedCommand g = guard(command, local);
    heading += g.command.angular_radps * dt;
    pos += g.command.linear_mps * dt * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    for (const Eigen::Vector2d& p : obstacles) closest = std::min(closest, (p - pos).norm());
  }
  if (end) *end = pos;
  return closest;
}

// The same for the forward guard with 'options'.
double ClosestApproach(const VelocityCommand& command,
                       const std::vector<Eigen::Vector2d>& obstacles,
                       const CollisionGuardOptions& options, double duration_s) {
  return ClosestApproachGuardedBy(
      [&](const VelocityCommand& c, const std::vector<Eigen::Vector2d>& local) {
        return GuardCommand(c, local, kRadius, options);
      },
      command, obstacles, duration_s);
}

TEST(CollisionGuardTest, FreeWayAndBackwardAndTurningCommandsPassUnchanged) {
  const std::vector<Eigen::Vector2d> behind = {{-0.3, 0.0}, {0.0, 0.5}, {0.0, -0.5}};
  const GuardedCommand g = GuardCommand({0.5, 0.2}, behind, kRadius, {});
  EXPECT_FALSE(g.limited);
  EXPECT_DOUBLE_EQ(g.command.linear_mps, 0.5);
  EXPECT_DOUBLE_EQ(g.command.angular_radps, 0.2);
  const std::vector<Eigen::Vector2d> ahead = {{0.25, 0.0}};
  EXPECT_FALSE(GuardCommand({-0.1, 0.0}, ahead, kRadius, {}).limited);  // backing away
  EXPECT_FALSE(GuardCommand({0.0, 1.0}, ahead, kRadius, {}).limited);   // on the spot
  CollisionGuardOptions off;
  off.horizon_s = 0.0;
  EXPECT_FALSE(GuardCommand({0.5, 0.0}, ahead, kRadius, off).limited);
}

TEST(CollisionGuardTest, SlowsDownAndStopsBeforeAPostAhead) {
  CollisionGuardOptions o;
  o.steer_max_curvature_per_m = 0.0;  // only slowing down
  const std::vector<Eigen::Vector2d> post = {{1.0, 0.05}};
  const GuardedCommand near = GuardCommand({0.5, 0.0}, post, kRadius, o);
  // 1 m away, 0.77 m of free travel at most: 0.5 m/s over 1 s fits.
  EXPECT_FALSE(near.limited);
  const GuardedCommand closer = GuardCommand({0.5, 0.0}, {{0.5, 0.05}}, kRadius, o);
  EXPECT_TRUE(closer.limited);
  EXPECT_FALSE(closer.stopped);
  EXPECT_LT(closer.command.linear_mps, 0.5);
  const GuardedCommand touching = GuardCommand({0.5, 0.6}, {{0.235, 0.0}}, kRadius, o);
  EXPECT_TRUE(touching.stopped);
  EXPECT_EQ(touching.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(touching.command.angular_radps, 0.6);  // still turns as the follower does
  // Driven to the end, it never comes within the clearance.
  EXPECT_GE(ClosestApproach({0.5, 0.0}, post, o, 5.0), kRadius + o.clearance_m - 0.011);
}

TEST(CollisionGuardTest, AStoppedRobotTurnsAwayFromWhatStopsItAndDrivesOn) {
  // The office, seed 12: a wall 1 cm from the disc on the right, bending
  // away ahead; the follower aims straight along its path. No arc keeps the
  // clearance, so the robot stops; turning away, it gets free and drives on.
  std::vector<Eigen::Vector2d> wall;
  for (double x = -0.3; x <= 1.5; x += 0.01) wall.push_back({x, -0.21 - 0.42 * std::max(x, 0.0)});
  const VelocityCommand along_path{0.5, 0.002};
  const GuardedCommand g = GuardCommand(along_path, wall, kRadius, {}, 1.0);
  EXPECT_TRUE(g.stopped);
  EXPECT_EQ(g.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(g.command.angular_radps, 0.5);  // left, away from the wall
  // A wall corner ahead-left (seed 13): turns right.
  std::vector<Eigen::Vector2d> corner;
  for (double t = 0.0; t <= 0.5; t += 0.01) corner.push_back({0.16 - 0.6 * t, 0.17 + 0.6 * t});
  EXPECT_DOUBLE_EQ(GuardCommand(along_path, corner, kRadius, {}, 1.0).command.angular_radps, -0.5);
  // Driven with the guard for 3 s: the robot leaves, never touching the wall.
  // Keeping the follower's turn, it stands still.
  const auto drive = [&](const CollisionGuardOptions& o, double* closest) {
    Eigen::Vector2d end;
    *closest = ClosestApproachGuardedBy(
        [&](const VelocityCommand& c, const std::vector<Eigen::Vector2d>& local) {
          return GuardCommand(c, local, kRadius, o, 1.0);
        },
        along_path, wall, 3.0, &end);
    return end.norm();
  };
  double closest = 0.0;
  EXPECT_GT(drive({}, &closest), 0.5);
  EXPECT_GE(closest, kRadius);
  CollisionGuardOptions keep_turn;
  keep_turn.stop_turn_radps = 0.0;
  EXPECT_LT(drive(keep_turn, &closest), 0.01);
}

TEST(CollisionGuardTest, AStoppedRobotDoesNotTurnTowardWhatStopsIt) {
  // willow-garage, seed 2 (visible gain): a return 3 cm from the disc
  // ahead-left, the follower turning left toward its path. Turning left puts
  // the return ahead (the way clears only after 150 degrees); turning
  // right clears it after about 20. The robot turns right.
  const std::vector<Eigen::Vector2d> ahead_left = {{0.10, 0.21}, {0.12, 0.20}};
  const VelocityCommand toward{0.5, 0.5};
  const GuardedCommand g = GuardCommand(toward, ahead_left, kRadius, {}, 1.0);
  EXPECT_TRUE(g.stopped);
  EXPECT_EQ(g.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(g.command.angular_radps, -0.5);
  // Mirrored: a return ahead-right, the follower turning right: turns left.
  const GuardedCommand m =
      GuardCommand({0.5, -0.5}, {{0.10, -0.21}, {0.12, -0.20}}, kRadius, {}, 1.0);
  EXPECT_TRUE(m.stopped);
  EXPECT_DOUBLE_EQ(m.command.angular_radps, 0.5);
  // A wall straight across the way clears about as soon either way: the
  // follower's decisive turn is kept, whichever way it goes.
  std::vector<Eigen::Vector2d> wall;
  for (double y = -1.0; y <= 1.0; y += 0.02) wall.push_back({0.235, y});
  EXPECT_DOUBLE_EQ(GuardCommand({0.5, 0.6}, wall, kRadius, {}, 1.0).command.angular_radps, 0.6);
  EXPECT_DOUBLE_EQ(GuardCommand({0.5, -0.6}, wall, kRadius, {}, 1.0).command.angular_radps, -0.6);
}

TEST(CollisionGuardTest, SteersTheNearestClearArcAwayFromAPost) {
  // A post 0.5 m ahead, slightly left: the straight arc would be slowed.
  const GuardedCommand g = GuardCommand({0.5, 0.0}, {{0.5, 0.05}}, kRadius, {}, 1.0);
  EXPECT_TRUE(g.steered);
  EXPECT_FALSE(g.limited);
  EXPECT_LT(g.command.angular_radps, 0.0);  // to the right, away from it
  EXPECT_LE(std::abs(g.command.angular_radps), 1.0 + 1e-12);
  // Within the curvature limit: at most 2 / m away from the commanded arc.
  EXPECT_LE(std::abs(g.command.angular_radps / g.command.linear_mps), 2.0 + 1e-9);
  // The steered arc itself is clear: guarding it again changes nothing.
  const GuardedCommand again = GuardCommand(g.command, {{0.5, 0.05}}, kRadius, {}, 1.0);
  EXPECT_FALSE(again.steered || again.limited);
}

TEST(CollisionGuardTest, SlowsDownWhenNoNearbyArcIsClear) {
  // A wall across the way 0.4 m ahead: no arc within 2 / m clears it.
  std::vector<Eigen::Vector2d> wall;
  for (double y = -2.0; y <= 2.0; y += 0.05) wall.push_back({0.4, y});
  const GuardedCommand g = GuardCommand({0.5, 0.0}, wall, kRadius, {}, 1.0);
  EXPECT_FALSE(g.steered);
  EXPECT_TRUE(g.limited);
  EXPECT_LT(g.command.linear_mps, 0.5);
}

TEST(CollisionGuardTest, SlidesAlongAWallItConvergesOn) {
  // A wall 0.26 m to the right, turning toward the path's heading by 5
  // degrees: without steering the robot stops against it.
  std::vector<Eigen::Vector2d> wall;
  const double a = 5.0 * M_PI / 180.0;
  for (double s = -1.0; s <= 3.0; s += 0.05) {
    wall.push_back({s * std::cos(a), -0.26 + s * std::sin(a)});
  }
  CollisionGuardOptions off;
  off.steer_max_curvature_per_m = 0.0;
  EXPECT_TRUE(GuardCommand({0.5, 0.0}, wall, kRadius, off).limited);
  const GuardedCommand g = GuardCommand({0.5, 0.0}, wall, kRadius, {}, 1.0);
  EXPECT_TRUE(g.steered);
  EXPECT_GT(g.command.angular_radps, 0.0);  // away from the wall
  EXPECT_NEAR(g.command.linear_mps, 0.5, 1e-12);
}

TEST(CollisionGuardTest, LetsTheRobotPassBesideAWall) {
  // A wall parallel to the heading, 0.3 m to the left: the disc keeps 0.1 m.
  std::vector<Eigen::Vector2d> wall;
  for (double x = -1.0; x <= 3.0; x += 0.05) wall.push_back({x, 0.3});
  const GuardedCommand g = GuardCommand({0.5, 0.0}, wall, kRadius, {});
  EXPECT_FALSE(g.limited);
}

TEST(CollisionGuardTest, BackingUpStopsBeforeAWallBehindAndIgnoresWhatIsAhead) {
  CollisionGuardOptions o;
  const std::vector<Eigen::Vector2d> ahead = {{0.25, 0.0}, {0.3, 0.1}};
  const GuardedCommand away = GuardBackward({-0.15, 0.2}, ahead, kRadius, o);
  EXPECT_FALSE(away.limited);
  EXPECT_DOUBLE_EQ(away.command.linear_mps, -0.15);
  EXPECT_DOUBLE_EQ(away.command.angular_radps, 0.2);
  // Forward and turning-only commands are GuardCommand's, not this one's.
  EXPECT_FALSE(GuardBackward({0.5, 0.0}, ahead, kRadius, o).limited);
  EXPECT_FALSE(GuardBackward({0.0, 1.0}, {{-0.21, 0.0}}, kRadius, o).limited);
  // A post 0.4 m behind: 0.17 m of free travel, less than 0.25 m/s for 1 s.
  const GuardedCommand slowed = GuardBackward({-0.25, 0.0}, {{-0.4, 0.0}}, kRadius, o);
  EXPECT_TRUE(slowed.limited);
  EXPECT_FALSE(slowed.stopped);
  EXPECT_LT(slowed.command.linear_mps, 0.0);
  EXPECT_GT(slowed.command.linear_mps, -0.25);
  EXPECT_FALSE(slowed.steered);
  // Touching it: stopped, still turning.
  const GuardedCommand stopped = GuardBackward({-0.15, 0.3}, {{-0.235, 0.0}}, kRadius, o);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(stopped.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(stopped.command.angular_radps, 0.3);
}

// Backing along an arc: a post behind-left is hit when the rear swings left,
// that is when the robot backs while turning clockwise (negative rate).
TEST(CollisionGuardTest, BackingAlongAnArcChecksTheSideItSwingsTo) {
  CollisionGuardOptions o;
  const std::vector<Eigen::Vector2d> behind_left = {{-0.35, 0.3}};
  EXPECT_TRUE(GuardBackward({-0.3, -1.0}, behind_left, kRadius, o).limited);
  EXPECT_FALSE(GuardBackward({-0.3, 1.0}, behind_left, kRadius, o).limited);
}

RC_GTEST_PROP(CollisionGuardProperty, NeverBacksIntoAnObstacle, ()) {
  const int n = *rc::gen::inRange(1, 20);
  std::vector<Eigen::Vector2d> obstacles;
  for (int i = 0; i < n; ++i) {
    const double angle = *rc::gen::inRange(0, 629) * 0.01;  // all around
    const double range = 0.25 + *rc::gen::inRange(0, 200) * 0.01;
    obstacles.push_back(range * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  const VelocityCommand command{-*rc::gen::inRange(1, 31) * 0.01,
                                *rc::gen::inRange(-100, 101) * 0.01};
  const double closest = ClosestApproachGuardedBy(
      [](const VelocityCommand& c, const std::vector<Eigen::Vector2d>& local) {
        const GuardedCommand g = GuardBackward(c, local, kRadius, {});
        RC_ASSERT(g.command.linear_mps <= 0.0);
        return g;
      },
      command, obstacles, 3.0);
  RC_ASSERT(closest >= kRadius);
}

RC_GTEST_PROP(CollisionGuardProperty, NeverDrivesIntoAnObstacle, ()) {
  // Random obstacles outside the disc plus clearance; any forward command.
  const std::vector<Eigen::Vector2d> obstacles = testing::RandomObstaclesAhead();
  const VelocityCommand command = testing::RandomForwardCommand();
  CollisionGuardOptions o;
  o.steer_max_curvature_per_m = *rc::gen::element(0.0, 2.0, 4.0);
  const double closest = ClosestApproach(command, obstacles, o, 3.0);
  RC_ASSERT(closest >= kRadius);
}

}  // namespace
}  // namespace scout::explore
