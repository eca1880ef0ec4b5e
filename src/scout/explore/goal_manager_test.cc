#include "scout/explore/goal_manager.h"

#include <gtest/gtest.h>

#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// A walled room, known free for x <= 40, unknown beyond: one frontier column.
struct Room {
  MapBuilder b{60, 40};
  std::vector<Eigen::Vector2d> frontier;
  Room() {
    b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
    frontier = b.FrontierPoints();
  }
  ExploreInput Input(double t, const Eigen::Vector2d& robot, bool changed) const {
    ExploreInput in;
    in.time_s = t;
    in.robot_pose = geometry::Rigid2d(robot, 0.0);
    in.map = &b.map();
    in.frontier = &frontier;
    in.map_changed = changed;
    return in;
  }
};

GoalManager MakeManager(const GoalManagerOptions& o = {}, std::string_view policy = "scout") {
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

}  // namespace
}  // namespace scout::explore
