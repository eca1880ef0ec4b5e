#include "scout/explore/goal_manager.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scout/explore/goal_manager_test_util.h"
#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::InputAt;
using testing::MakeManager;
using testing::MapBuilder;
using testing::NoStuckRecovery;
using testing::PinchedDoor;
using testing::Room;

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
  // The goal's record: issued at 0.1 s, dropped by Stop() after that update.
  ASSERT_EQ(gm.goal_log().size(), 1u);
  const GoalRecord& r = gm.goal_log()[0];
  EXPECT_EQ(r.issued_s, 0.1);
  EXPECT_EQ(r.goal, *driving.goal);
  EXPECT_EQ(r.ended_s, 0.1);
  EXPECT_EQ(r.outcome, GoalOutcome::kStopped);
  EXPECT_EQ(ToString(r.outcome), "stopped");
  // Scout's revenue: at most the area the gain counts, minus the path.
  EXPECT_GT(r.path_m, 2.5);
  EXPECT_LT(r.score, 0.0);
  EXPECT_GT(r.score, -r.path_m - 0.5);
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
  ASSERT_EQ(gm.goal_log().size(), 1u);
  EXPECT_EQ(gm.goal_log()[0].outcome, GoalOutcome::kReached);
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
  ASSERT_EQ(gm.goal_log().size(), 2u);
  EXPECT_EQ(gm.goal_log()[0].outcome, GoalOutcome::kSuperseded);
  EXPECT_EQ(gm.goal_log()[0].ended_s, 4.0);
  EXPECT_EQ(gm.goal_log()[1].outcome, GoalOutcome::kOpen);
  EXPECT_TRUE(std::isnan(gm.goal_log()[1].ended_s));
  EXPECT_GT(gm.goal_log()[1].score, gm.goal_log()[0].score);
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
  ASSERT_EQ(gm.goal_log().size(), 1u);
  EXPECT_EQ(gm.goal_log()[0].outcome, GoalOutcome::kSeen);
  EXPECT_EQ(gm.goal_log()[0].ended_s, 2.0);
}

TEST(GoalManagerTest, FindsTheBestGoalBeyondThePathDistanceSettledFirst) {
  // A corridor with a shallow pocket of unknown at its west end, 5.3 m from
  // the robot (0.65 m² of it), and open unknown space at its east end, 5.8 m
  // away (half a disc of it): by Scout's revenue (multiplier 1, hysteresis
  // off) the east end is the better goal. The goal manager first settles
  // path distances to what a candidate can score above its path cost (3.60
  // m², the disc that holds the cells the gain counts) plus 2 m: 5.60 m. The
  // west end, ranked then, is not sure to be the best, so it settles farther
  // before it plans.
  MapBuilder b{165, 100};
  b.Wall(0, 0, 164, 99).Fill(1, 1, 163, 98, grid::CellState::kUnknown);
  b.Wall(1, 1, 9, 98).Fill(5, 44, 9, 56, grid::CellState::kUnknown).Free(10, 1, 121, 98);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const Eigen::Vector2d robot = b.At(63, 50);
  GoalPolicyOptions policy;
  policy.navigation.hysteresis_gain = 1.0;
  const auto first_goal = [&](const GoalPolicyOptions& p) {
    GoalManager gm(NoStuckRecovery(), {}, {}, {}, MakeGoalPolicy("scout", p));
    gm.Start();
    const ExploreStatus s = gm.Update(InputAt(0, robot, b.map(), frontier, true));
    EXPECT_EQ(s.state, ExploreState::kDriving);
    return s.goal.value_or(Eigen::Vector2d(NAN, NAN));
  };
  EXPECT_GT(first_goal(policy).x(), robot.x() + 5.0);
  // Information weighs nothing: the nearer west end is the best.
  policy.navigation.info_multiplier = 0.01;
  EXPECT_LT(first_goal(policy).x(), robot.x() - 4.0);
}

TEST(GoalManagerTest, ComparesAGoalFarAroundAWallWithNewCandidates) {
  // The goal lies 4 m from the robot as the crow flies but 35 m by path,
  // round the end of a wall. Unknown space then appears 13 m away on the
  // robot's side: better by far more than the switch margin. Re-ranking
  // settles path distances to a detour's worth of the straight line to the
  // goal first; it must go on until it has the goal's own score to compare.
  MapBuilder b{200, 100};
  b.Wall(0, 0, 199, 99).Fill(1, 1, 198, 98, grid::CellState::kUnknown);
  b.Free(1, 1, 198, 48).Wall(1, 49, 170, 50).Free(171, 49, 198, 50).Free(1, 51, 198, 98);
  b.Fill(1, 70, 30, 98, grid::CellState::kUnknown);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const Eigen::Vector2d robot = b.At(20, 30);
  GoalManager gm = MakeManager();
  gm.Start();
  const ExploreStatus first = gm.Update(InputAt(0, robot, b.map(), frontier, true));
  ASSERT_EQ(first.state, ExploreState::kDriving);
  ASSERT_GT(first.goal->y(), b.At(0, 50).y());
  MapBuilder opened = b;
  opened.Fill(150, 1, 198, 20, grid::CellState::kUnknown);
  const std::vector<Eigen::Vector2d> more = opened.FrontierPoints();
  const ExploreStatus st = gm.Update(InputAt(2, robot, opened.map(), more, true));
  ASSERT_EQ(st.state, ExploreState::kDriving);
  EXPECT_LT(st.goal->y(), b.At(0, 49).y());
  EXPECT_GT(st.goal->x(), b.At(140, 0).x());
  EXPECT_EQ(gm.counters().goals_superseded, 1);
}

}  // namespace
}  // namespace scout::explore
