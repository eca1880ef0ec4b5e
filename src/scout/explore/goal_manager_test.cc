#include "scout/explore/goal_manager.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// What the exploration loop hands the goal manager at time 't'.
ExploreInput InputAt(double t, const Eigen::Vector2d& robot, const grid::OccupancyMap& map,
                     const std::vector<Eigen::Vector2d>& frontier, bool changed) {
  ExploreInput in;
  in.time_s = t;
  in.robot_pose = geometry::Rigid2d(robot, 0.0);
  in.map = &map;
  in.frontier = &frontier;
  in.map_changed = changed;
  return in;
}

// A walled room, known free for x <= 40, unknown beyond: one frontier column.
struct Room {
  MapBuilder b{60, 40};
  std::vector<Eigen::Vector2d> frontier;
  Room() {
    b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
    frontier = b.FrontierPoints();
  }
  ExploreInput Input(double t, const Eigen::Vector2d& robot, bool changed) const {
    return InputAt(t, robot, b.map(), frontier, changed);
  }
};

// The robots of these tests often stand still on purpose (a goal that makes
// no progress): the stuck recovery is off unless a test turns it on.
GoalManagerOptions NoStuckRecovery() {
  GoalManagerOptions o;
  o.stuck_timeout_s = 0.0;
  return o;
}

GoalManager MakeManager(const GoalManagerOptions& o = NoStuckRecovery(),
                        std::string_view policy = "scout") {
  return GoalManager(o, {}, {}, {}, MakeGoalPolicy(policy, {}));
}

TEST(GoalManagerTest, IdleUntilStartedAndStopsOnRequest) {
  Room room;
  GoalManager gm = MakeManager();
  EXPECT_EQ(gm.Update(room.Input(0, room.b.At(10, 20), true)).state, ExploreState::kIdle);
  gm.Start();
  const ExploreStatus driving = gm.Update(room.Input(0.1, room.b.At(10, 20), false));
  EXPECT_EQ(driving.state, ExploreState::kDriving);
  ASSERT_TRUE(driving.goal.has_value());
  EXPECT_NEAR(driving.goal->x(), room.b.At(40, 0).x(), 1e-9);  // a frontier point
  EXPECT_GT(driving.command.linear_mps + std::abs(driving.command.angular_radps), 0.0);
  gm.Stop();
  const ExploreStatus stopped = gm.Update(room.Input(0.2, room.b.At(10, 20), false));
  EXPECT_EQ(stopped.state, ExploreState::kIdle);
  EXPECT_EQ(stopped.command.linear_mps, 0.0);
  EXPECT_FALSE(stopped.goal.has_value());
}

TEST(GoalManagerTest, SendsTheRobotToAStandOffInKnownFreeSpace) {
  // The goal is a frontier point next to unknown space, where a wall may
  // stand: the robot is sent to the last path point whose disc is known free.
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  const ExploreStatus s = gm.Update(room.Input(0, room.b.At(10, 20), true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_TRUE(s.goal && s.target);
  ASSERT_FALSE(s.path.empty());
  EXPECT_EQ(s.path.back(), *s.target);
  EXPECT_GT((*s.goal - *s.target).norm(), 0.1);
  EXPECT_LE((*s.goal - *s.target).norm(), 0.5 + 1e-9);
  // Unknown starts at x = 4.1 m; the 0.2 m disc stays clear of it.
  EXPECT_LE(s.target->x() + 0.2, 4.1 + 1e-9);

  GoalManagerOptions at_goal = NoStuckRecovery();
  at_goal.max_stand_off_m = 0.0;
  GoalManager direct = MakeManager(at_goal);
  direct.Start();
  const ExploreStatus d = direct.Update(room.Input(0, room.b.At(10, 20), true));
  ASSERT_TRUE(d.goal && d.target);
  EXPECT_LE((*d.goal - *d.target).norm(), 0.1 + 1e-9);  // at most the goal snap
}

TEST(GoalManagerTest, ScoutsStandOffKeepsAMarginFromUnknownSpace) {
  // Unknown starts at x = 4.1 m. Without the margin the stop is the last
  // path point whose 0.2 m disc is known free (x in (3.85, 3.9]); Scout's
  // policy stops 0.1 m farther back, the baselines where they did.
  Room room;
  const auto target_x = [&room](const GoalManagerOptions& o, std::string_view policy) {
    GoalManager gm = MakeManager(o, policy);
    gm.Start();
    const ExploreStatus s = gm.Update(room.Input(0, room.b.At(10, 20), true));
    EXPECT_EQ(s.state, ExploreState::kDriving) << policy;
    return s.target ? s.target->x() : std::nan("");
  };
  GoalManagerOptions o = NoStuckRecovery();
  o.stand_off_unknown_margin_m = 0.1;
  const double scout_x = target_x(o, "scout");
  EXPECT_LE(scout_x + 0.3, 4.1 + 1e-9);
  EXPECT_GT(scout_x + 0.3, 4.1 - 0.05 - 1e-9);
  const double nearest_x = target_x(o, "nearest");
  EXPECT_LE(nearest_x + 0.2, 4.1 + 1e-9);
  EXPECT_GT(nearest_x + 0.2, 4.1 - 0.05 - 1e-9);
  o.stand_off_unknown_margin_m = 0.0;
  EXPECT_NEAR(target_x(o, "scout"), nearest_x, 1e-9);
  // A margin no point within the back-off keeps: the stop as without it.
  o.stand_off_unknown_margin_m = 0.5;
  EXPECT_NEAR(target_x(o, "scout"), nearest_x, 1e-9);
}

TEST(GoalManagerTest, PassesOverGoalsWhosePathRunsIntoWhatTheLidarSees) {
  // A corridor known free from x = 10 to 40 (cells), unknown at both ends:
  // the nearer frontier (right) is the better goal. The latest scan sees a
  // wall across the corridor 0.5 m to the right, which the map does not
  // have (a map fused from a misplaced submap).
  MapBuilder b{60, 20};
  b.Wall(0, 0, 59, 19).Fill(1, 1, 58, 18, grid::CellState::kUnknown).Free(10, 1, 40, 18);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const Eigen::Vector2d robot = b.At(30, 10);
  const auto wall_across = [](double dx) {
    std::vector<Eigen::Vector2d> returns;
    for (double dy = -1.0; dy <= 1.0; dy += 0.05) returns.emplace_back(dx, dy);
    return returns;
  };
  const std::vector<Eigen::Vector2d> right = wall_across(0.5);
  std::vector<Eigen::Vector2d> both = wall_across(-0.5);
  both.insert(both.end(), right.begin(), right.end());
  // The corridor's own walls as the lidar sees them.
  std::vector<Eigen::Vector2d> on_the_walls;
  for (double dx = -1.0; dx <= 1.0; dx += 0.05) {
    on_the_walls.emplace_back(dx, b.At(0, 0).y() - robot.y());
    on_the_walls.emplace_back(dx, b.At(0, 19).y() - robot.y());
  }
  const auto first_goal = [&](const std::vector<Eigen::Vector2d>& returns, double radius_m,
                              std::string_view policy, int* contradicted) {
    GoalManagerOptions o = NoStuckRecovery();
    o.scan_check_radius_m = radius_m;
    GoalManager gm = MakeManager(o, policy);
    gm.Start();
    ExploreInput in = InputAt(0, robot, b.map(), frontier, true);
    in.obstacles = &returns;
    const ExploreStatus s = gm.Update(in);
    EXPECT_EQ(s.state, ExploreState::kDriving);
    if (contradicted) *contradicted = gm.counters().goals_contradicted;
    return s.goal.value_or(Eigen::Vector2d(NAN, NAN));
  };
  int contradicted = 0;
  EXPECT_GT(first_goal({}, 0.15, "scout", nullptr).x(), robot.x());
  EXPECT_GT(first_goal(on_the_walls, 0.15, "scout", &contradicted).x(), robot.x());
  EXPECT_EQ(contradicted, 0);
  // The scan blocks the way right: the left end is taken instead.
  EXPECT_LT(first_goal(right, 0.15, "scout", &contradicted).x(), robot.x());
  EXPECT_GT(contradicted, 0);
  // Blocked both ways (local SLAM holding the pose off looks like this):
  // the best goal, as without the check.
  EXPECT_GT(first_goal(both, 0.15, "scout", &contradicted).x(), robot.x());
  EXPECT_GT(contradicted, 1);
  // Off, or for a baseline policy: the best goal whatever the scan sees.
  EXPECT_GT(first_goal(right, 0.0, "scout", nullptr).x(), robot.x());
  EXPECT_GT(first_goal(right, 0.15, "nearest", &contradicted).x(), robot.x());
  EXPECT_EQ(contradicted, 0);
}

TEST(GoalManagerTest, TheScanCheckCanUseTheScansOfTheLastSeconds) {
  // As above, but the latest scan sees nothing across the corridor: the
  // wall to the right was seen by the scans of the last seconds (the robot
  // has turned away from it).
  MapBuilder b{60, 20};
  b.Wall(0, 0, 59, 19).Fill(1, 1, 58, 18, grid::CellState::kUnknown).Free(10, 1, 40, 18);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const Eigen::Vector2d robot = b.At(30, 10);
  std::vector<Eigen::Vector2d> remembered;
  for (double dy = -1.0; dy <= 1.0; dy += 0.05) remembered.emplace_back(0.5, dy);
  const std::vector<Eigen::Vector2d> latest;
  const auto first_goal = [&](double memory_s, bool memory_given) {
    GoalManagerOptions o = NoStuckRecovery();
    o.scan_check_memory_s = memory_s;
    GoalManager gm = MakeManager(o);
    gm.Start();
    ExploreInput in = InputAt(0, robot, b.map(), frontier, true);
    in.obstacles = &latest;
    if (memory_given) in.scan_check_returns = [&remembered] { return remembered; };
    const ExploreStatus s = gm.Update(in);
    EXPECT_EQ(s.state, ExploreState::kDriving);
    return s.goal.value_or(Eigen::Vector2d(NAN, NAN));
  };
  EXPECT_LT(first_goal(10.0, true).x(), robot.x());
  // Memory off, or none given: the best goal, right.
  EXPECT_GT(first_goal(0.0, true).x(), robot.x());
  EXPECT_GT(first_goal(10.0, false).x(), robot.x());
}

TEST(GoalManagerTest, ProgressTimeoutMarksTheGoalFailedAndPicksAnother) {
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);  // the robot never moves
  const ExploreStatus first = gm.Update(room.Input(0, robot, true));
  ASSERT_EQ(first.state, ExploreState::kDriving);
  for (double t = 1; t <= 30; t += 1) {
    ASSERT_EQ(gm.Update(room.Input(t, robot, false)).state, ExploreState::kDriving) << t;
  }
  const ExploreStatus failed = gm.Update(room.Input(30.5, robot, false));
  EXPECT_EQ(failed.state, ExploreState::kFailed);
  EXPECT_EQ(failed.command.linear_mps, 0.0);
  EXPECT_EQ(gm.counters().goals_failed, 1);
  ASSERT_EQ(failed.blacklisted.size(), 1u);
  EXPECT_EQ(failed.blacklisted[0], *first.goal);

  const ExploreStatus next = gm.Update(room.Input(31, robot, false));
  EXPECT_EQ(next.state, ExploreState::kDriving);
  ASSERT_TRUE(next.goal.has_value());
  EXPECT_GT((*next.goal - *first.goal).norm(), 0.5);  // outside the blacklist radius
  EXPECT_EQ(gm.counters().goals_issued, 2);
}

TEST(GoalManagerTest, StuckRobotBacksUpReselectsAndFailsTheGoalTheSecondTime) {
  Room room;
  GoalManagerOptions o;  // recovery on, defaults: 3 s, 0.3 m back at 0.15 m/s
  GoalManager gm = MakeManager(o);
  gm.Start();
  Eigen::Vector2d robot = room.b.At(10, 20);
  const ExploreStatus first = gm.Update(room.Input(0, robot, true));
  ASSERT_EQ(first.state, ExploreState::kDriving);
  ASSERT_GT(first.command.linear_mps, 0.0);
  // Pressed against something: commanded forward, not moving.
  const auto get_stuck = [&](double t0) {
    ExploreStatus s;
    for (double t = t0 + 0.5; t < t0 + o.stuck_timeout_s; t += 0.5) {
      s = gm.Update(room.Input(t, robot, false));
      EXPECT_GT(s.command.linear_mps, 0.0) << t;
    }
    s = gm.Update(room.Input(t0 + o.stuck_timeout_s, robot, false));
    EXPECT_LT(s.command.linear_mps, 0.0);
    // Backing up until 0.3 m away.
    robot.x() -= 0.2;
    s = gm.Update(room.Input(t0 + o.stuck_timeout_s + 1.5, robot, false));
    EXPECT_EQ(s.state, ExploreState::kDriving);
    EXPECT_LT(s.command.linear_mps, 0.0);
    robot.x() -= 0.15;
    return gm.Update(room.Input(t0 + o.stuck_timeout_s + 2.5, robot, false));
  };
  // The first time, the goal is selected afresh: the same one, nothing
  // else in this room has changed.
  ExploreStatus s = get_stuck(0.0);
  EXPECT_EQ(gm.counters().recoveries, 1);
  EXPECT_EQ(s.state, ExploreState::kPlanning);
  EXPECT_EQ(gm.counters().goals_failed, 0);
  EXPECT_EQ(gm.counters().stuck_reselections, 1);
  EXPECT_TRUE(s.blacklisted.empty());
  const double t1 = o.stuck_timeout_s + 3.0;
  s = gm.Update(room.Input(t1, robot, false));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_TRUE(s.goal.has_value());
  EXPECT_LT((*s.goal - *first.goal).norm(), 1e-9);
  // The second time, it fails.
  s = get_stuck(t1);
  EXPECT_EQ(gm.counters().recoveries, 2);
  EXPECT_EQ(s.state, ExploreState::kFailed);
  EXPECT_EQ(gm.counters().goals_failed, 1);
  EXPECT_EQ(gm.counters().stuck_reselections, 1);
  ASSERT_EQ(s.blacklisted.size(), 1u);
  EXPECT_EQ(s.blacklisted[0], *first.goal);
}

TEST(GoalManagerTest, BackingUpStopsAtAWallTheMapShowsBehind) {
  Room room;
  for (const bool blind : {false, true}) {
    GoalManagerOptions o;  // stuck recovery on
    if (blind) o.back_up_look_behind_m = 0.0;
    GoalManager gm = MakeManager(o);
    gm.Start();
    // Facing the frontier (+x), its disc 2 cm from the room's wall behind it.
    const Eigen::Vector2d robot(0.32, 2.05);
    ExploreStatus s = gm.Update(room.Input(0, robot, true));
    ASSERT_EQ(s.state, ExploreState::kDriving);
    ASSERT_GT(s.command.linear_mps, 0.0);
    for (double t = 0.5; t < o.stuck_timeout_s; t += 0.5)
      s = gm.Update(room.Input(t, robot, false));
    s = gm.Update(room.Input(o.stuck_timeout_s, robot, false));
    ASSERT_EQ(gm.counters().recoveries, 1);
    s = gm.Update(room.Input(o.stuck_timeout_s + 0.1, robot, false));
    if (blind) {
      EXPECT_LT(s.command.linear_mps, 0.0) << "reverses into the wall";
      EXPECT_EQ(gm.counters().back_ups_blocked, 0);
    } else {
      // No reverse command; the back-up is over and the goal selected afresh.
      EXPECT_EQ(s.state, ExploreState::kPlanning);
      EXPECT_GE(s.command.linear_mps, 0.0);
      EXPECT_EQ(gm.counters().back_ups_blocked, 1);
      EXPECT_EQ(gm.counters().stuck_reselections, 1);
    }
  }
  // Past an obstacle the map already has under the disc (its error: the
  // robot stands there), backing up is not blocked.
  Room overlapped = room;
  overlapped.b.Wall(9, 21, 9, 21);  // 0.14 m behind-left of the robot's centre
  GoalManagerOptions o;
  GoalManager gm = MakeManager(o);
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);
  ExploreStatus s = gm.Update(overlapped.Input(0, robot, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  for (double t = 0.5; t <= o.stuck_timeout_s; t += 0.5) {
    s = gm.Update(overlapped.Input(t, robot, false));
  }
  ASSERT_EQ(gm.counters().recoveries, 1);
  s = gm.Update(overlapped.Input(o.stuck_timeout_s + 0.6, robot, false));
  EXPECT_LT(s.command.linear_mps, 0.0);
  EXPECT_EQ(gm.counters().back_ups_blocked, 0);
}

// The lidar sees only ahead: a wall the recent scans saw behind the robot,
// which its map does not have (misplaced), stops backing up before the disc
// reaches it, unless the scan memory is off.
TEST(GoalManagerTest, BackingUpStopsAtAWallTheRecentScansSawBehind) {
  Room room;
  // A wall across the robot's back, 0.25 m behind its centre: the disc keeps
  // 0.05 m, so 0.15 m/s over the guard's 1 s horizon would reach it.
  std::vector<Eigen::Vector2d> wall_behind;
  for (double y = -0.4; y <= 0.4; y += 0.02) wall_behind.emplace_back(-0.25, y);
  for (const double memory_s : {10.0, 0.0}) {
    GoalManagerOptions o;  // stuck recovery on
    o.guard.memory_s = memory_s;
    GoalManager gm = MakeManager(o);
    gm.Start();
    const Eigen::Vector2d robot = room.b.At(10, 20);  // no mapped wall within 0.45 m
    int asked = 0;
    auto input = [&](double t, bool changed) {
      ExploreInput in = room.Input(t, robot, changed);
      in.recent_returns = [&] {
        ++asked;
        return wall_behind;
      };
      return in;
    };
    ExploreStatus s = gm.Update(input(0, true));
    ASSERT_EQ(s.state, ExploreState::kDriving);
    for (double t = 0.5; t < o.stuck_timeout_s; t += 0.5) s = gm.Update(input(t, false));
    EXPECT_EQ(asked, 0) << "the memory is read only when backing up";
    s = gm.Update(input(o.stuck_timeout_s, false));
    ASSERT_EQ(gm.counters().recoveries, 1);
    if (memory_s > 0.0) {
      EXPECT_GT(asked, 0);
      // Slowed to what stops the disc before the wall, never past it.
      EXPECT_LE(s.command.linear_mps, 0.0);
      EXPECT_GT(s.command.linear_mps, -0.05 - 1e-9);
      s = gm.Update(input(o.stuck_timeout_s + 0.1, false));
      EXPECT_GT(s.command.linear_mps, -0.05 - 1e-9);
    } else {
      EXPECT_EQ(asked, 0);
      EXPECT_DOUBLE_EQ(s.command.linear_mps, -o.back_up_speed_mps) << "blind: full speed";
    }
  }
}

// Backing up may leave the path the robot drove by at most the trail
// tolerance: the map behind it (which the lidar does not see) may be wrong.
TEST(GoalManagerTest, BackingUpStaysNearThePathDriven) {
  Room room;
  const Eigen::Vector2d stuck_at = room.b.At(20, 20);
  // Returns how far the robot backs up after getting stuck at 'stuck_at',
  // having driven there from 'from' (it faces +x, the frontier, either way).
  const auto backed_m = [&](const GoalManagerOptions& o, const Eigen::Vector2d& from,
                            int* blocked) {
    GoalManager gm = MakeManager(o);
    gm.Start();
    double t = 0.0;
    ExploreStatus s = gm.Update(room.Input(t, from, true));
    EXPECT_EQ(s.state, ExploreState::kDriving);
    for (double f = 0.0; f <= 1.0; f += 0.05) {
      s = gm.Update(room.Input(t += 0.1, from + f * (stuck_at - from), false));
    }
    for (int k = 0; k < 40 && gm.counters().recoveries == 0; ++k) {
      s = gm.Update(room.Input(t += 0.1, stuck_at, false));
    }
    EXPECT_EQ(gm.counters().recoveries, 1);
    Eigen::Vector2d robot = stuck_at;
    while (s.command.linear_mps < 0.0 && t < 100.0) {
      robot.x() -= 0.01;  // the command moves it 1 cm per update
      s = gm.Update(room.Input(t += 0.1, robot, false));
    }
    *blocked = gm.counters().back_ups_blocked;
    return (stuck_at - robot).norm();
  };
  GoalManagerOptions o;  // stuck recovery on
  o.back_up_trail_m = 3.0;
  int blocked = -1;
  // Came from behind: it backs up the whole back-up distance along its path.
  EXPECT_NEAR(backed_m(o, room.b.At(8, 20), &blocked), o.back_up_distance_m, 0.015);
  EXPECT_EQ(blocked, 0);
  // Turned round where it stands: it stops before its centre would leave the
  // path by the tolerance (the look-behind included).
  const double off_path_m = backed_m(o, room.b.At(32, 20), &blocked);
  EXPECT_LE(off_path_m, o.back_up_trail_tolerance_m - o.back_up_look_behind_m + 0.015);
  EXPECT_GT(off_path_m, 0.0);
  EXPECT_EQ(blocked, 1);
  // With the trail off, the free map alone lets it back the whole distance.
  o.back_up_trail_m = 0.0;
  EXPECT_NEAR(backed_m(o, room.b.At(32, 20), &blocked), o.back_up_distance_m, 0.015);
  EXPECT_EQ(blocked, 0);
}

// Stuck with no way to back up, or stuck again where the last back-up began:
// the robot drives back the way it came (turning round first; the lidar sees
// ahead), then selects afresh. With retrace_m 0 it only tries to back up.
TEST(GoalManagerTest, StuckRobotThatCannotBackUpRetracesTheWayItCame) {
  Room room;
  const Eigen::Vector2d from = room.b.At(10, 20), stuck_at = room.b.At(30, 20);
  // A wall across the robot's back, in the robot frame (behind: -x).
  std::vector<Eigen::Vector2d> wall_behind;
  for (double y = -0.4; y <= 0.4; y += 0.02) wall_behind.emplace_back(-0.22, y);
  for (const double retrace_m : {2.0, 0.0}) {
    GoalManagerOptions o;  // stuck recovery on
    o.retrace_m = retrace_m;
    GoalManager gm = MakeManager(o);
    gm.Start();
    double t = 0.0;
    const auto update = [&](const Eigen::Vector2d& at, double heading) {
      ExploreInput in = room.Input(t += 0.1, at, false);
      in.robot_pose = geometry::Rigid2d(at, heading);
      in.recent_returns = [&] { return wall_behind; };
      return gm.Update(in);
    };
    ExploreStatus s = gm.Update(room.Input(t, from, true));
    ASSERT_EQ(s.state, ExploreState::kDriving);
    for (double f = 0.0; f <= 1.0; f += 0.02) s = update(from + f * (stuck_at - from), 0.0);
    for (int k = 0; k < 40 && gm.counters().recoveries == 0; ++k) s = update(stuck_at, 0.0);
    ASSERT_EQ(gm.counters().recoveries, 1);
    EXPECT_GE(s.command.linear_mps, 0.0) << "never reverses into the wall";
    if (retrace_m == 0.0) {
      s = update(stuck_at, 0.0);
      EXPECT_EQ(gm.counters().back_ups_blocked, 1);
      EXPECT_EQ(gm.counters().retraces, 0);
      EXPECT_EQ(s.state, ExploreState::kPlanning);
      continue;
    }
    EXPECT_EQ(gm.counters().retraces, 1);
    EXPECT_EQ(gm.counters().back_ups_blocked, 0);
    // Facing the wall's other side: it turns on the spot first.
    s = update(stuck_at, 0.0);
    EXPECT_EQ(s.state, ExploreState::kDriving);
    EXPECT_EQ(s.command.linear_mps, 0.0);
    EXPECT_NE(s.command.angular_radps, 0.0);
    // Turned round, it drives forward along its own way back, 2 m of it.
    Eigen::Vector2d robot = stuck_at;
    for (int k = 0; k < 400 && s.state == ExploreState::kDriving; ++k) {
      s = update(robot, M_PI);
      if (s.state != ExploreState::kDriving) break;
      ASSERT_GT(s.command.linear_mps, 0.0) << k;
      EXPECT_LT(std::abs(s.command.angular_radps), 0.05) << k;
      robot.x() -= 0.02;
    }
    EXPECT_EQ(s.state, ExploreState::kPlanning);
    EXPECT_NEAR((stuck_at - robot).norm(), retrace_m, 0.3);
    EXPECT_EQ(gm.counters().stuck_reselections, 1);
    EXPECT_EQ(gm.counters().goals_failed, 0);
  }
}

TEST(GoalManagerTest, StuckAgainWhereTheBackUpBeganRetracesTheWayItCame) {
  Room room;
  const Eigen::Vector2d from = room.b.At(10, 20), stuck_at = room.b.At(30, 20);
  GoalManagerOptions o;  // stuck recovery on, nothing behind the robot
  o.retrace_m = 2.0;
  GoalManager gm = MakeManager(o);
  gm.Start();
  double t = 0.0;
  ExploreStatus s = gm.Update(room.Input(t, from, true));
  const auto drive_and_get_stuck = [&](const Eigen::Vector2d& start) {
    for (double f = 0.0; f <= 1.0; f += 0.02) {
      s = gm.Update(room.Input(t += 0.1, start + f * (stuck_at - start), false));
    }
    const int before = gm.counters().recoveries;
    for (int k = 0; k < 40 && gm.counters().recoveries == before; ++k) {
      s = gm.Update(room.Input(t += 0.1, stuck_at, false));
    }
  };
  drive_and_get_stuck(from);
  ASSERT_EQ(gm.counters().recoveries, 1);
  EXPECT_LT(s.command.linear_mps, 0.0) << "the first time it backs up";
  Eigen::Vector2d robot = stuck_at;
  while (s.command.linear_mps < 0.0) {
    robot.x() -= 0.02;
    s = gm.Update(room.Input(t += 0.1, robot, false));
  }
  EXPECT_EQ(gm.counters().retraces, 0);
  s = gm.Update(room.Input(t += 0.1, robot, false));
  ASSERT_EQ(s.state, ExploreState::kDriving);  // the same goal, selected afresh
  drive_and_get_stuck(robot);
  EXPECT_EQ(gm.counters().recoveries, 2);
  EXPECT_EQ(gm.counters().retraces, 1);
  EXPECT_GE(s.command.linear_mps, 0.0);
}

// The loop found the robot confined with no progress: the goal fails and the
// robot drives back the way it came (its trajectory, not a trail of its own),
// then selects afresh; at most max_last_resorts times, never when off, idle,
// or with no driven point far enough away.
TEST(GoalManagerTest, LastResortDrivesBackTheWayItCameThenSelectsAfresh) {
  Room room;  // 0.1 m cells: At(10, 20) is (1.05, 2.05)
  const Eigen::Vector2d from = room.b.At(10, 20), stuck_at = room.b.At(35, 20);
  std::vector<Eigen::Vector2d> driven;
  for (double f = 0.0; f <= 1.0 + 1e-9; f += 0.05) driven.push_back(from + f * (stuck_at - from));
  for (int k = 0; k < 200; ++k) driven.push_back(stuck_at);  // turning on the spot
  const auto input = [&](double t, const Eigen::Vector2d& at, double heading) {
    ExploreInput in = room.Input(t, at, false);
    in.robot_pose = geometry::Rigid2d(at, heading);
    in.driven = &driven;
    return in;
  };
  {
    GoalManagerOptions o = NoStuckRecovery();
    o.last_resort_retrace_m = 0.0;
    GoalManager off = MakeManager(o);
    off.Start();
    off.Update(room.Input(0.0, stuck_at, true));
    EXPECT_FALSE(off.LastResort(input(0.1, stuck_at, 0.0)));
  }
  GoalManager gm = MakeManager();  // on by default: 2 m, twice
  EXPECT_FALSE(gm.LastResort(input(0.0, stuck_at, 0.0))) << "idle";
  gm.Start();
  double t = 0.0;
  ExploreStatus s = gm.Update(room.Input(t, stuck_at, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_TRUE(s.goal.has_value());
  std::vector<Eigen::Vector2d> nothing_far{stuck_at, stuck_at + Eigen::Vector2d(0.5, 0.0)};
  ExploreInput short_way = input(t += 0.1, stuck_at, 0.0);
  short_way.driven = &nothing_far;
  EXPECT_FALSE(gm.LastResort(short_way)) << "no driven point 2 m away";

  ASSERT_TRUE(gm.LastResort(input(t += 0.1, stuck_at, 0.0)));
  EXPECT_EQ(gm.counters().last_resorts, 1);
  EXPECT_EQ(gm.counters().goals_failed, 1);
  // Facing away from the way back: it turns on the spot first ...
  s = gm.Update(input(t += 0.1, stuck_at, 0.0));
  EXPECT_EQ(s.state, ExploreState::kDriving);
  EXPECT_FALSE(s.goal.has_value());
  EXPECT_EQ(s.command.linear_mps, 0.0);
  EXPECT_NE(s.command.angular_radps, 0.0);
  // ... then drives forward along the way it came until 2 m away.
  Eigen::Vector2d robot = stuck_at;
  for (int k = 0; k < 400 && s.state == ExploreState::kDriving; ++k) {
    s = gm.Update(input(t += 0.1, robot, M_PI));
    if (s.state != ExploreState::kDriving) break;
    ASSERT_GT(s.command.linear_mps, 0.0) << k;
    robot.x() -= 0.02;
  }
  EXPECT_EQ(s.state, ExploreState::kPlanning);
  EXPECT_NEAR((stuck_at - robot).norm(), 2.0, 0.3);
  EXPECT_NEAR(robot.y(), stuck_at.y(), 1e-9);
  // Then it selects afresh.
  s = gm.Update(input(t += 0.1, robot, M_PI));
  EXPECT_EQ(s.state, ExploreState::kDriving);
  EXPECT_TRUE(s.goal.has_value());
  // Out of the pocket by itself when the timer ran out: it goes on with
  // its goal; that counts as a last resort too.
  {
    GoalManagerOptions three = NoStuckRecovery();
    three.max_last_resorts = 3;
    GoalManager out = MakeManager(three);
    out.Start();
    ExploreStatus o = out.Update(input(0.0, from, true));
    ASSERT_EQ(o.state, ExploreState::kDriving);
    const Eigen::Vector2d goal = *o.goal;
    EXPECT_TRUE(out.LastResort(input(0.1, from, 0.0), /*drive_back=*/false));
    EXPECT_EQ(out.counters().last_resorts, 1);
    EXPECT_EQ(out.counters().goals_failed, 0);
    o = out.Update(input(0.2, from, 0.0));
    EXPECT_EQ(o.state, ExploreState::kDriving);
    ASSERT_TRUE(o.goal.has_value());
    EXPECT_EQ(*o.goal, goal);
    // Confined later, it drives back; if the timer ran out again while it
    // drives back, it goes on driving back.
    ASSERT_TRUE(out.LastResort(input(0.3, stuck_at, 0.0)));
    EXPECT_EQ(out.counters().last_resorts, 2);
    EXPECT_EQ(out.counters().goals_failed, 1);
    ASSERT_TRUE(out.LastResort(input(0.4, stuck_at, 0.0)));
    EXPECT_EQ(out.counters().last_resorts, 3);
    EXPECT_EQ(out.counters().goals_failed, 1);
    o = out.Update(input(0.5, stuck_at, 0.0));
    EXPECT_EQ(o.state, ExploreState::kDriving);
    EXPECT_FALSE(o.goal.has_value());      // still on the way back, with no goal
    EXPECT_EQ(o.command.linear_mps, 0.0);  // turning round to it first
    EXPECT_NE(o.command.angular_radps, 0.0);
  }
  // Confined in the pocket again later: once more, then no more.
  EXPECT_TRUE(gm.LastResort(input(t += 0.1, stuck_at, M_PI)));
  EXPECT_EQ(gm.counters().last_resorts, 2);
  EXPECT_FALSE(gm.LastResort(input(t += 0.1, stuck_at, 0.0))) << "used up";
  EXPECT_EQ(gm.counters().last_resorts, 2);
}

// Stopped in the middle of a recovery, then started again: the robot drives
// to its next goal instead of going on with the back-up or the retrace.
TEST(GoalManagerTest, StopEndsARecoveryUnderWay) {
  Room room;
  const Eigen::Vector2d from = room.b.At(10, 20), stuck_at = room.b.At(30, 20);
  for (const bool retrace : {false, true}) {
    GoalManagerOptions o;  // stuck recovery on
    if (retrace) o.retrace_m = 2.0;
    GoalManager gm = MakeManager(o);
    gm.Start();
    double t = 0.0;
    ExploreStatus s = gm.Update(room.Input(t, from, true));
    for (double f = 0.0; f <= 1.0; f += 0.02) {
      s = gm.Update(room.Input(t += 0.1, from + f * (stuck_at - from), false));
    }
    for (int k = 0; k < 40 && gm.counters().recoveries == 0; ++k) {
      s = gm.Update(room.Input(t += 0.1, stuck_at, false));
    }
    ASSERT_EQ(gm.counters().recoveries, 1);
    if (retrace) {
      // Stuck again where it got stuck: it retraces, turning round first.
      s = gm.Update(room.Input(t += 0.1, stuck_at, false));
      while (s.command.linear_mps < 0.0) s = gm.Update(room.Input(t += 0.1, stuck_at, false));
      for (int k = 0; k < 80 && gm.counters().retraces == 0; ++k) {
        s = gm.Update(room.Input(t += 0.1, stuck_at, false));
      }
      ASSERT_EQ(gm.counters().retraces, 1);
      s = gm.Update(room.Input(t += 0.1, stuck_at, false));
      ASSERT_EQ(s.command.linear_mps, 0.0);
      ASSERT_NE(s.command.angular_radps, 0.0);  // turning to face the way back
    } else {
      ASSERT_LT(s.command.linear_mps, 0.0);  // backing up
    }
    gm.Stop();
    gm.Start();
    s = gm.Update(room.Input(t += 0.1, stuck_at, true));
    ASSERT_EQ(s.state, ExploreState::kDriving);
    s = gm.Update(room.Input(t += 0.1, stuck_at, false));
    EXPECT_GT(s.command.linear_mps, 0.0) << "on to the frontier ahead (+x)";
    EXPECT_LT(std::abs(s.command.angular_radps), 0.5);
  }
}

TEST(GoalManagerTest, FailedGoalMovesWithItsSubmapAndIsRetriedAfterTheMapChanges) {
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);
  ExploreInput in = room.Input(0, robot, true);
  in.submaps = {{0, geometry::Rigid2d(0, 0, 0)}, {1, geometry::Rigid2d(3.0, 2.0, 0.0)}};
  const ExploreStatus first = gm.Update(in);
  ASSERT_TRUE(first.goal.has_value());
  in.map_changed = false;
  in.time_s = 40;
  ASSERT_EQ(gm.Update(in).state, ExploreState::kFailed);
  const FailedGoal& failed = gm.failed_goals().goals().at(0);
  EXPECT_EQ(failed.where.submap_id, 1);  // submap 1's origin is the nearer one

  // A loop closure moves submap 1: the failed goal moves with it.
  const geometry::Rigid2d moved(3.4, 1.8, 0.1);
  in.submaps[1].global_pose = moved;
  in.time_s = 41;
  const ExploreStatus after = gm.Update(in);
  ASSERT_EQ(after.blacklisted.size(), 1u);
  const Eigen::Vector2d expected =
      moved * (geometry::Rigid2d(3.0, 2.0, 0.0).inverse() * *first.goal);
  EXPECT_NEAR((after.blacklisted[0] - expected).norm(), 0.0, 1e-9);

  // The map did not move with the closure here, so test retries in the
  // original poses. A change far away does not lift the blacklisting ...
  in.submaps[1].global_pose = geometry::Rigid2d(3.0, 2.0, 0.0);
  Room changed = room;
  changed.b.Free(1, 1, 3, 3);
  ExploreInput far = changed.Input(43, robot, true);
  far.submaps = in.submaps;
  EXPECT_EQ(gm.Update(far).blacklisted.size(), 1u);
  EXPECT_EQ(gm.counters().goals_retried, 0);
  // ... newly seen space around the goal does.
  changed.b.Free(41, 1, 50, 38);
  changed.frontier = changed.b.FrontierPoints();
  ExploreInput near = changed.Input(45, robot, true);
  near.submaps = in.submaps;
  EXPECT_TRUE(gm.Update(near).blacklisted.empty());
  EXPECT_EQ(gm.counters().goals_retried, 1);
}

TEST(GoalManagerTest, ReachedGoalIsCountedAndTheNextOneChosen) {
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  const ExploreStatus first = gm.Update(room.Input(0, room.b.At(10, 20), true));
  ASSERT_TRUE(first.goal.has_value());
  const ExploreStatus there = gm.Update(room.Input(5, *first.goal, false));
  EXPECT_EQ(there.state, ExploreState::kReached);
  EXPECT_EQ(gm.counters().goals_reached, 1);
  // The reached point stays a frontier here (the map did not change): it is
  // not chosen again, so the robot cannot loop on a frontier it cannot see.
  const ExploreStatus next = gm.Update(room.Input(6, *first.goal, false));
  EXPECT_EQ(next.state, ExploreState::kDriving);
  ASSERT_TRUE(next.goal.has_value());
  EXPECT_GT((*next.goal - *first.goal).norm(), 0.5);
}

TEST(GoalManagerTest, FrontierThatStaysWhereTheRobotWentCountsAsVisitedNotGivenUp) {
  // The map never changes: every goal the robot reaches leaves its frontier
  // in place. When no goal is left, that frontier is reported as visited
  // (the robot went and looked), not as reachable frontier given up on.
  Room room;
  GoalManagerOptions o = NoStuckRecovery();
  GoalManager gm = MakeManager(o);
  gm.Start();
  Eigen::Vector2d robot = room.b.At(10, 20);
  ExploreStatus s = gm.Update(room.Input(0, robot, true));
  double t = 0.0;
  while (s.state != ExploreState::kFinished && t < 500.0) {
    t += 0.5;
    if (s.state == ExploreState::kDriving && s.target) robot = *s.target;  // arrives
    s = gm.Update(room.Input(t, robot, false));
  }
  ASSERT_EQ(s.state, ExploreState::kFinished);
  EXPECT_GT(gm.counters().goals_reached, 1);
  EXPECT_EQ(s.frontier_left, static_cast<int>(room.frontier.size()));
  EXPECT_EQ(s.reachable_frontier_left, 0);
  // All but the points in the room's corners, too close to the walls for
  // any plan.
  EXPECT_GT(s.visited_frontier_left, s.frontier_left * 3 / 4);
  EXPECT_LE(s.visited_frontier_left, s.frontier_left);
}

TEST(GoalManagerTest, FrontierGivenUpOnIsCountedAndListed) {
  // The robot never moves: every goal fails and is blacklisted, until none is
  // left. The frontier it could plan to is reported as given up on, and
  // where each point lies, so a user can find it.
  Room room;
  GoalManagerOptions o = NoStuckRecovery();
  GoalManager gm = MakeManager(o);
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);
  ExploreStatus s = gm.Update(room.Input(0, robot, true));
  for (double t = 0.5; s.state != ExploreState::kFinished && t < 3000.0; t += 0.5) {
    s = gm.Update(room.Input(t, robot, false));
  }
  ASSERT_EQ(s.state, ExploreState::kFinished);
  EXPECT_GT(gm.counters().goals_failed, 0);
  EXPECT_EQ(gm.counters().goals_reached, 0);
  EXPECT_GT(s.reachable_frontier_left, 0);
  EXPECT_EQ(s.visited_frontier_left, 0);
  ASSERT_EQ(static_cast<int>(s.reachable_frontier_left_points.size()), s.reachable_frontier_left);
  for (const Eigen::Vector2d& p : s.reachable_frontier_left_points) {
    EXPECT_NE(std::find(room.frontier.begin(), room.frontier.end(), p), room.frontier.end())
        << p.transpose() << " is not a frontier point";
  }
}

TEST(GoalManagerTest, BeforeGivingUpAFailedGoalNextToReachableFrontierIsTriedAgain) {
  // One small unknown patch in a known room; the robot never moves, so its
  // goal there fails, and the map never changes, so the retry rule (known area
  // around the goal changed) never lifts it. Before finishing, the goal is
  // tried again while it has failed fewer than max_failures times.
  MapBuilder b{60, 40};
  b.Wall(0, 0, 59, 39).Free(1, 1, 58, 38).Fill(48, 19, 49, 20, grid::CellState::kUnknown);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  GoalManagerOptions o = NoStuckRecovery();
  ASSERT_EQ(o.failed_goals.max_failures, 3);
  GoalManager gm = MakeManager(o);
  gm.Start();
  const Eigen::Vector2d robot = b.At(10, 20);
  ExploreStatus s = gm.Update(InputAt(0, robot, b.map(), frontier, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  for (double t = 0.5; s.state != ExploreState::kFinished && t < 3000.0; t += 0.5) {
    s = gm.Update(InputAt(t, robot, b.map(), frontier, false));
  }
  ASSERT_EQ(s.state, ExploreState::kFinished);
  EXPECT_EQ(gm.counters().goals_issued, 3);
  EXPECT_EQ(gm.counters().goals_failed, 3);
  EXPECT_EQ(gm.counters().goals_retried, 2);
  // Given up on after the third failure, and reported so.
  EXPECT_EQ(s.reachable_frontier_left, static_cast<int>(frontier.size()));
}

TEST(GoalManagerTest, FinishesWhenNothingIsLeftAndReturnsHome) {
  Room room;
  room.frontier.clear();
  GoalManagerOptions o;
  o.return_to_start = true;
  GoalManager gm = MakeManager(o);
  gm.Start();
  const Eigen::Vector2d home = room.b.At(10, 20), away = room.b.At(30, 10);
  EXPECT_EQ(gm.Update(room.Input(0, home, true)).state, ExploreState::kPlanning);
  // No goal for less than finish_after_empty_s: still waiting for the map.
  EXPECT_EQ(gm.Update(room.Input(1.5, away, false)).state, ExploreState::kPlanning);
  const ExploreStatus back = gm.Update(room.Input(2.5, away, false));
  EXPECT_EQ(back.state, ExploreState::kReturning);
  ASSERT_FALSE(back.path.empty());
  EXPECT_NEAR((back.path.back() - home).norm(), 0.0, 1e-9);
  const ExploreStatus done = gm.Update(room.Input(3, home, false));
  EXPECT_EQ(done.state, ExploreState::kFinished);
  EXPECT_TRUE(done.returned_home);
  EXPECT_EQ(gm.counters().goals_issued, 0);
}

TEST(GoalManagerTest, BoundaryPolygonHidesFrontiersOutsideIt) {
  Room room;
  GoalManagerOptions o;
  o.boundary = {{0, 0}, {3.5, 0}, {3.5, 4}, {0, 4}};  // ends before the frontier at x = 4.05
  GoalManager gm = MakeManager(o);
  gm.Start();
  gm.Update(room.Input(0, room.b.At(10, 20), true));
  EXPECT_EQ(gm.Update(room.Input(3, room.b.At(10, 20), false)).state, ExploreState::kFinished);
  o.boundary = {{0, 0}, {4.5, 0}, {4.5, 4}, {0, 4}};
  GoalManager wide = MakeManager(o);
  wide.Start();
  EXPECT_EQ(wide.Update(room.Input(0, room.b.At(10, 20), true)).state, ExploreState::kDriving);
  o.boundary = {{0, 0}, {1, 1}};
  EXPECT_THROW(MakeManager(o), std::invalid_argument);
}

TEST(GoalManagerTest, UnreachableBaselineGoalIsBlacklistedNotDrivenTo) {
  // explore-lite's centroid of a U of frontier cells lies inside a pillar.
  MapBuilder b(40, 30, 0.1, grid::CellState::kFree);
  b.Wall(0, 0, 39, 29).Free(1, 1, 38, 28).Wall(11, 11, 13, 16);
  std::vector<Eigen::Vector2d> frontier;
  for (int y = 10; y <= 16; ++y) frontier.push_back(b.At(10, y)), frontier.push_back(b.At(14, y));
  for (int x = 11; x <= 13; ++x) frontier.push_back(b.At(x, 10));
  GoalManager gm = MakeManager({}, "explore-lite");
  gm.Start();
  ExploreInput in;
  in.robot_pose = geometry::Rigid2d(b.At(30, 20), 0);
  in.map = &b.map();
  in.frontier = &frontier;
  in.map_changed = true;
  const ExploreStatus st = gm.Update(in);
  EXPECT_EQ(st.state, ExploreState::kPlanning);
  EXPECT_EQ(gm.counters().goals_unreachable, 1);
  EXPECT_EQ(st.blacklisted.size(), 1u);
}

TEST(GoalManagerTest, RobotInsideTheInflatedBandNearAWallStillExploresTheRoom) {
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  // 0.2 m from the wall's cell centre: inside the 0.40 m band, and even
  // closer than a narrow passage allows. It must not "complete" here.
  const Eigen::Vector2d robot = room.b.At(10, 2);
  const ExploreStatus st = gm.Update(room.Input(0, robot, true));
  ASSERT_EQ(st.state, ExploreState::kDriving);
  ASSERT_TRUE(st.goal.has_value());
  EXPECT_NEAR(st.goal->x(), room.b.At(40, 0).x(), 1e-9);
  EXPECT_EQ(st.path.front(), robot);
  EXPECT_EQ(gm.counters().escapes, 1);
  // On the way out it never gets closer to the wall (row 0) than it was.
  for (const Eigen::Vector2d& p : st.path) EXPECT_GE(p.y(), robot.y() - 1e-9);
}

// A wall at x = 20 whose door is 0.7 m wide: narrower than twice the 0.40 m
// inflation (as SLAM's wall noise makes a 0.9 m door), wider than the robot.
struct PinchedDoor {
  MapBuilder b{60, 40};
  std::vector<Eigen::Vector2d> frontier;
  PinchedDoor() {
    b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
    b.Wall(20, 1, 20, 38).Free(20, 15, 20, 21);
    frontier = b.FrontierPoints();
  }
};

TEST(GoalManagerTest, ANarrowedDoorDoesNotSealTheRoomBehindIt) {
  PinchedDoor door;
  ExploreInput in;
  in.robot_pose = geometry::Rigid2d(door.b.At(8, 18), 0.0);
  in.map = &door.b.map();
  in.frontier = &door.frontier;
  in.map_changed = true;
  GoalManager gm = MakeManager();
  gm.Start();
  const ExploreStatus st = gm.Update(in);
  ASSERT_EQ(st.state, ExploreState::kDriving);
  ASSERT_TRUE(st.goal.has_value());
  EXPECT_GT(st.goal->x(), 4.0);  // beyond the door

  // Without narrow passages nothing is reachable: after turning on the spot
  // for finish_with_frontier_after_s it gives up, and says frontier is left
  // (the loop reports that as no_progress, never as complete).
  TraversabilityOptions strict;
  strict.narrow_margin_m = strict.safety_margin_m;
  GoalManagerOptions o;
  GoalManager sealed(o, strict, {}, {}, MakeGoalPolicy("scout", {}));
  sealed.Start();
  ExploreStatus waiting = sealed.Update(in);
  EXPECT_EQ(waiting.state, ExploreState::kPlanning);
  in.map_changed = false;
  in.time_s = o.finish_with_frontier_after_s - 1.0;
  waiting = sealed.Update(in);
  EXPECT_EQ(waiting.state, ExploreState::kPlanning);
  EXPECT_GT(waiting.command.angular_radps, 0.0);
  in.time_s = o.finish_with_frontier_after_s + 0.5;
  const ExploreStatus gave_up = sealed.Update(in);
  EXPECT_EQ(gave_up.state, ExploreState::kFinished);
  EXPECT_EQ(gave_up.frontier_left, static_cast<int>(door.frontier.size()));
  // Behind a door too narrow for any plan: left, but not reachable.
  EXPECT_EQ(gave_up.reachable_frontier_left, 0);
}

TEST(GoalManagerTest, ANarrowPassageTheRobotGotStuckInIsClosed) {
  PinchedDoor door;
  GoalManagerOptions o;  // stuck recovery and passage closing on
  GoalManager gm = MakeManager(o);
  gm.Start();
  const auto input = [&](double t, const Eigen::Vector2d& robot, bool changed) {
    ExploreInput in;
    in.time_s = t;
    in.robot_pose = geometry::Rigid2d(robot, 0.0);
    in.map = &door.b.map();
    in.frontier = &door.frontier;
    in.map_changed = changed;
    return in;
  };
  // In the door, on its way to the frontier beyond: pressed, not moving.
  Eigen::Vector2d robot = door.b.At(19, 18);
  ExploreStatus s = gm.Update(input(0, robot, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_GT(s.goal->x(), door.b.At(20, 0).x());
  for (double t = 0.5; t <= o.stuck_timeout_s; t += 0.5) s = gm.Update(input(t, robot, false));
  ASSERT_EQ(gm.counters().recoveries, 1);
  robot.x() -= 0.35;  // backed up
  s = gm.Update(input(o.stuck_timeout_s + 2.5, robot, false));
  EXPECT_EQ(s.state, ExploreState::kPlanning);  // selected afresh, not failed
  EXPECT_EQ(gm.counters().stuck_reselections, 1);
  // The door was the only way: no goal beyond it is issued again, and when
  // the robot gives up, the frontier there counts as out of reach.
  double t = o.stuck_timeout_s + 3.0;
  for (; t < o.stuck_timeout_s + 3.0 + o.finish_with_frontier_after_s + 1.0; t += 0.5) {
    s = gm.Update(input(t, robot, false));
    EXPECT_NE(s.state, ExploreState::kDriving) << t;
  }
  EXPECT_EQ(s.state, ExploreState::kFinished);
  EXPECT_EQ(s.reachable_frontier_left, 0);
  EXPECT_EQ(gm.counters().goals_issued, 1);

  // With closing off, or through a door the robot has driven through before
  // (it must never be sealed in where it has been), the next goal goes
  // through the same door again.
  GoalManagerOptions keep = o;
  keep.close_stuck_passage_radius_m = 0.0;
  const std::vector<Eigen::Vector2d> driven = {door.b.At(25, 18), door.b.At(20, 18),
                                               door.b.At(15, 18), door.b.At(10, 18)};
  for (const bool closing_off : {true, false}) {
    GoalManager again = MakeManager(closing_off ? keep : o);
    again.Start();
    robot = door.b.At(19, 18);
    const auto with_driven = [&](double t2, bool changed) {
      ExploreInput in = input(t2, robot, changed);
      if (!closing_off) in.driven = &driven;
      return in;
    };
    again.Update(with_driven(0, true));
    for (double t2 = 0.5; t2 <= o.stuck_timeout_s; t2 += 0.5) again.Update(with_driven(t2, false));
    robot.x() -= 0.35;
    again.Update(with_driven(o.stuck_timeout_s + 2.5, false));
    s = again.Update(with_driven(o.stuck_timeout_s + 3.0, false));
    EXPECT_EQ(s.state, ExploreState::kDriving) << closing_off;
    ASSERT_TRUE(s.goal.has_value());
    EXPECT_GT(s.goal->x(), door.b.At(20, 0).x());
    EXPECT_EQ(again.counters().recoveries, 1);
  }
}

TEST(GoalManagerTest, ClosingWhereTheRobotGotStuckNeverSealsItWhereItStands) {
  // A room (x < 20) with unknown space in its top-left corner, and a corridor
  // 0.7 m wide (x 20-40, rows 13-19) toward unknown space at x > 40; with a
  // 0.25 m safety margin its centre row is a narrow passage (0.4 m clear). The robot got stuck in
  // the corridor at x = 34 and backed up 0.25 m. SLAM's nodes (the driven
  // trajectory) end 0.95 m before where it stands.
  MapBuilder b{60, 40};
  b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
  b.Wall(20, 1, 40, 12).Wall(20, 20, 40, 38).Fill(1, 33, 6, 38, grid::CellState::kUnknown);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const std::vector<Eigen::Vector2d> driven = {b.At(5, 16), b.At(12, 16), b.At(17, 16),
                                               b.At(22, 16)};
  GoalManagerOptions o;  // stuck recovery and passage closing on
  TraversabilityOptions traversability;
  traversability.safety_margin_m = 0.25;
  GoalManager gm(o, traversability, {}, {}, MakeGoalPolicy("nearest", {}));
  gm.Start();
  Eigen::Vector2d robot = b.At(34, 16);
  const auto input = [&](double t, bool changed) {
    ExploreInput in = InputAt(t, robot, b.map(), frontier, changed);
    in.driven = &driven;
    return in;
  };
  ExploreStatus s = gm.Update(input(0, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_GE(s.goal->x(), b.At(40, 0).x() - 1e-9);  // the corridor's end, nearest
  for (double t = 0.5; t <= o.stuck_timeout_s; t += 0.5) s = gm.Update(input(t, false));
  ASSERT_EQ(gm.counters().recoveries, 1);
  robot.x() -= 0.25;
  s = gm.Update(input(o.stuck_timeout_s + 2.0, false));
  s = gm.Update(input(o.stuck_timeout_s + 4.5, false));  // back-up timed out
  ASSERT_EQ(gm.counters().stuck_reselections, 1);
  // The corridor's end stays closed, but the robot leaves the way it came, to
  // the unknown corner of the room, instead of giving up.
  s = gm.Update(input(o.stuck_timeout_s + 5.0, false));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_TRUE(s.goal.has_value());
  EXPECT_LT(s.goal->x(), b.At(10, 0).x());
}

TEST(GoalManagerTest, GoalIsKeptWhenASlightlyBetterOneAppearsAndSwitchedForAClearlyBetterOne) {
  Room room;
  GoalManagerOptions o;
  o.goal_switch_margin = 1.5;  // metres, for "nearest" (score = -distance)
  GoalManager gm = MakeManager(o, "nearest");
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);
  const ExploreStatus first = gm.Update(room.Input(0, robot, true));
  ASSERT_TRUE(first.goal.has_value());
  EXPECT_NEAR((*first.goal - room.b.At(40, 20)).norm(), 0.0, 1e-9);  // 3 m away

  // Unknown space appears 2.2 m away: better by 0.8 m only. The goal stays
  // (and so does the count of issued goals); only the path is re-planned.
  Room slightly = room;
  slightly.b.Fill(28, 5, 30, 7, grid::CellState::kUnknown);
  slightly.frontier = slightly.b.FrontierPoints();
  const ExploreStatus kept = gm.Update(slightly.Input(2, robot, true));
  ASSERT_EQ(kept.state, ExploreState::kDriving);
  EXPECT_EQ(*kept.goal, *first.goal);
  EXPECT_EQ(gm.counters().goals_issued, 1);
  EXPECT_EQ(gm.counters().goals_superseded, 0);

  // Unknown space 0.4 m from the robot: better by 2.6 m, so it wins.
  Room clearly = slightly;
  clearly.b.Fill(15, 20, 16, 21, grid::CellState::kUnknown);
  clearly.frontier = clearly.b.FrontierPoints();
  const ExploreStatus switched = gm.Update(clearly.Input(4, robot, true));
  ASSERT_EQ(switched.state, ExploreState::kDriving);
  EXPECT_LT((*switched.goal - robot).norm(), 0.5);
  EXPECT_EQ(gm.counters().goals_issued, 2);
  EXPECT_EQ(gm.counters().goals_superseded, 1);
}

TEST(GoalManagerTest, GoalWhoseFrontierIsSeenOnTheWayEndsAsSeen) {
  Room room;
  GoalManager gm = MakeManager();
  gm.Start();
  const Eigen::Vector2d robot = room.b.At(10, 20);
  ASSERT_TRUE(gm.Update(room.Input(0, robot, true)).goal.has_value());
  Room seen = room;
  seen.b.Free(41, 1, 58, 38);  // the whole room is known now
  seen.frontier = seen.b.FrontierPoints();
  ASSERT_TRUE(seen.frontier.empty());
  const ExploreStatus st = gm.Update(seen.Input(2, robot, true));
  EXPECT_NE(st.state, ExploreState::kDriving);
  EXPECT_EQ(gm.counters().goals_seen, 1);
  EXPECT_EQ(gm.counters().goals_reached, 0);
  EXPECT_EQ(gm.counters().goals_superseded, 0);
}

}  // namespace
}  // namespace scout::explore
