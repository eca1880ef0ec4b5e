#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scout/explore/goal_manager.h"
#include "scout/explore/goal_manager_test_util.h"
#include "scout/explore/test_maps.h"

// The goal manager when the robot makes no progress: progress timeouts, stuck
// detection, backing up, retracing, the last resort, and closing the passages
// it got stuck in.
namespace scout::explore {
namespace {

using testing::InputAt;
using testing::MakeManager;
using testing::MapBuilder;
using testing::NoStuckRecovery;
using testing::PinchedDoor;
using testing::Room;

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
  ASSERT_EQ(gm.goal_log().size(), 1u);
  EXPECT_EQ(gm.goal_log()[0].outcome, GoalOutcome::kFailed);
  EXPECT_EQ(gm.goal_log()[0].ended_s, 30.5);

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

// An obstacle beside and behind a disc the map has clear: backing up 0.1 m
// brings the disc onto it, though it nears the swept disc by only 0.034 m.
TEST(GoalManagerTest, BackingUpStopsAtAnObstacleBesideAndBehind) {
  Room room;
  room.b.Wall(9, 22, 9, 22);                // centre (0.95, 2.25)
  const Eigen::Vector2d robot(1.07, 2.06);  // 0.225 m away, at (-0.12, 0.19) facing +x
  GoalManagerOptions o;                     // stuck recovery on
  GoalManager gm = MakeManager(o);
  gm.Start();
  ExploreStatus s = gm.Update(room.Input(0, robot, true));
  ASSERT_EQ(s.state, ExploreState::kDriving);
  ASSERT_GT(s.command.linear_mps, 0.0);
  for (double t = 0.5; t <= o.stuck_timeout_s; t += 0.5) s = gm.Update(room.Input(t, robot, false));
  ASSERT_EQ(gm.counters().recoveries, 1);
  s = gm.Update(room.Input(o.stuck_timeout_s + 0.1, robot, false));
  EXPECT_GE(s.command.linear_mps, 0.0) << "reverses onto the obstacle";
  EXPECT_EQ(s.state, ExploreState::kPlanning);
  EXPECT_EQ(gm.counters().back_ups_blocked, 1);
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

}  // namespace
}  // namespace scout::explore
