// The whole closed loop (simulator, SLAM, frontier, goals) on a small
// building: it must finish by itself, cover the reachable space, never
// collide, never target the closet behind a too-narrow gap, and repeat
// itself exactly for the same seed.

#include "scout/exploration/exploration_loop.h"

#include <gtest/gtest.h>

#include "scout/common/error.h"
#include "scout/exploration/test_worlds.h"

namespace scout::exploration {
namespace {

ExplorationResult Explore(const ExplorationOptions& options, uint64_t seed) {
  ExplorationLoop loop(testing::SmallBuilding(), options, seed);
  return loop.Run();
}

// "Quickly" in simulated time, which is deterministic: the wall time (under a
// second in release) is measured by scout_explore_bench's
// BM_ExploreSmallBuilding, not asserted here, where a loaded machine or a
// sanitizer build would make it fail at random.
TEST(ExplorationLoopTest, ExploresASmallBuildingCompletelyAndQuickly) {
  ExplorationLoop loop(testing::SmallBuilding(), {}, 7);
  int progress_calls = 0;
  const ExplorationResult r = loop.Run([&](const ExplorationProgress&) { ++progress_calls; }, 5.0);
  std::cout << "terminated=" << ToString(r.terminated) << " coverage=" << r.coverage
            << " sim=" << r.sim_time_s << " s path=" << r.path_length_m
            << " m goals issued=" << r.counters.goals_issued
            << " reached=" << r.counters.goals_reached << " seen=" << r.counters.goals_seen
            << " failed=" << r.counters.goals_failed << " unreachable=" << r.unreachable_goals
            << "\n";
  EXPECT_EQ(r.terminated, Termination::kComplete);
  EXPECT_GE(r.coverage, 0.97);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_EQ(r.unreachable_goals, 0);
  EXPECT_GT(r.counters.goals_issued, 0);
  // Goals are kept until done: each ends reached at arrival or seen on the
  // way (the last may end with the run), none replaced on map changes.
  EXPECT_GE(r.counters.goals_reached + r.counters.goals_seen, r.counters.goals_issued - 1);
  EXPECT_EQ(r.counters.goals_superseded, 0);
  EXPECT_TRUE(r.frontier_counted);
  EXPECT_EQ(r.frontier_left, 0);
  // 25.8 s simulated and 6.2 m driven on 2026-12-06; the bounds leave room for
  // tuning but not for a robot that wanders or waits.
  EXPECT_LT(r.sim_time_s, 60.0);
  EXPECT_LT(r.path_length_m, 15.0);
  EXPECT_GT(progress_calls, 2);
  // The records agree with the totals.
  ASSERT_FALSE(r.coverage_samples.empty());
  EXPECT_DOUBLE_EQ(r.coverage_samples.back().coverage, r.coverage);
  EXPECT_DOUBLE_EQ(r.coverage_samples.back().sim_time_s, r.sim_time_s);
  for (size_t i = 1; i < r.coverage_samples.size(); ++i) {
    EXPECT_GT(r.coverage_samples[i].sim_time_s, r.coverage_samples[i - 1].sim_time_s);
    EXPECT_GE(r.coverage_samples[i].path_length_m, r.coverage_samples[i - 1].path_length_m);
  }
  ASSERT_TRUE(r.time_to_coverage_s[0].has_value());
  EXPECT_LE(*r.time_to_coverage_s[0], r.sim_time_s);
  EXPECT_EQ(static_cast<int>(r.goals.size()), r.counters.goals_issued);
  // Where the robot was sent lies on truly free space: each target is placed
  // in the world by the scans that mapped it, and its disc fit the map.
  const sim::World world = testing::SmallBuilding();
  for (const IssuedGoal& g : r.goals) {
    const grid::CellIndex cell = world.map.limits.CellContaining(g.target_world);
    ASSERT_TRUE(world.map.limits.Contains(cell));
    EXPECT_EQ(world.map.cells[world.map.limits.FlatIndex(cell)], grid::CellState::kFree)
        << "target issued at t=" << g.sim_time_s << " s lies at " << g.target_world.transpose();
  }
  // The SLAM estimate stays close to the truth: the last node against the
  // true pose at its scan, in the world frame.
  const std::vector<slam::TimedPose> nodes = loop.map_builder().GetTrajectory();
  ASSERT_FALSE(nodes.empty());
  for (const slam::TimedPose& t : r.truth) {
    if (t.time_s != nodes.back().time_s) continue;
    const Eigen::Vector2d estimate = (loop.world_from_map() * nodes.back().pose).translation();
    EXPECT_LT((estimate - t.pose.translation()).norm(), 0.15);
  }
}

// The guard with the base's motion predicted (off by default) explores the
// same building completely, without collision, on time.
TEST(ExplorationLoopTest, ExploresTheSmallBuildingWithTheGuardPredictingTheBase) {
  ExplorationOptions o;
  o.explore.goals.guard.predict_motion = true;
  const ExplorationResult r = Explore(o, 7);
  EXPECT_EQ(r.terminated, Termination::kComplete);
  EXPECT_GE(r.coverage, 0.97);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_EQ(r.unreachable_goals, 0);
  // The guard let the robot drive to its goals: each ended reached or mapped
  // on the way (in this small building the way maps most of them).
  EXPECT_GT(r.counters.goals_issued, 0);
  EXPECT_GE(r.counters.goals_reached + r.counters.goals_seen, r.counters.goals_issued - 1);
  EXPECT_GT(r.path_length_m, 3.0);
}

TEST(ExplorationLoopTest, SameSeedSameRun) {
  ExplorationOptions o;
  o.explore.max_sim_time_s = 40.0;
  const ExplorationResult a = Explore(o, 3);
  const ExplorationResult b = Explore(o, 3);
  EXPECT_EQ(a.terminated, b.terminated);
  EXPECT_EQ(a.coverage, b.coverage);
  EXPECT_EQ(a.path_length_m, b.path_length_m);
  EXPECT_EQ(a.sim_time_s, b.sim_time_s);
  EXPECT_EQ(a.counters.goals_issued, b.counters.goals_issued);
  ASSERT_EQ(a.truth.size(), b.truth.size());
  EXPECT_EQ(a.truth.back().pose.translation(), b.truth.back().pose.translation());
  // A different seed draws different sensor noise, so the run differs.
  const ExplorationResult c = Explore(o, 4);
  EXPECT_NE(a.truth.back().pose.translation(), c.truth.back().pose.translation());
}

TEST(ExplorationLoopTest, ARunThatCannotFinishEndsByItself) {
  ExplorationOptions o;
  o.explore.max_sim_time_s = 3.0;
  const ExplorationResult r = Explore(o, 1);
  EXPECT_EQ(r.terminated, Termination::kMaxSimTime);
  EXPECT_NEAR(r.sim_time_s, 3.0, 0.1);
  EXPECT_FALSE(r.frontier_counted);  // the goals had not run out

  // Without a goal policy able to move (zero speed is refused), a stalled
  // robot is caught by the coverage watchdog instead.
  ExplorationOptions stalled;
  stalled.explore.no_progress_timeout_s = 5.0;
  stalled.explore.goals.progress_timeout_s = 1000.0;
  stalled.explore.follower.max_linear_speed_mps = 1e-4;
  stalled.explore.follower.min_linear_speed_mps = 0.0;
  stalled.explore.follower.max_angular_speed_radps = 1e-4;
  const ExplorationResult s = Explore(stalled, 1);
  EXPECT_EQ(s.terminated, Termination::kNoProgress);
  EXPECT_LT(s.sim_time_s, 30.0);
}

// When the no-progress timer runs out on a confined robot, it first drives
// back the way it came and the timer starts again, at most max_last_resorts
// times; then the run ends no_progress. (No map growth ever counts here,
// "confined" spans the whole small building, and the robot drives slowly.)
TEST(ExplorationLoopTest, AConfinedRobotTriesItsLastResortsBeforeNoProgress) {
  ExplorationOptions o;
  o.explore.min_map_gain_m2 = 1e9;
  o.explore.no_progress_timeout_s = 20.0;
  o.explore.goals.last_resort_confined_radius_m = 100.0;
  o.explore.goals.last_resort_confined_s = 1.0;
  o.explore.goals.last_resort_retrace_m = 0.5;
  o.explore.goals.max_last_resorts = 2;
  o.explore.follower.max_linear_speed_mps = 0.1;  // slow enough not to finish within a minute
  const ExplorationResult r = Explore(o, 1);
  EXPECT_EQ(r.terminated, Termination::kNoProgress);
  EXPECT_EQ(r.counters.last_resorts, 2);
  EXPECT_GE(r.sim_time_s, 60.0);  // three timeouts
  EXPECT_LT(r.sim_time_s, 65.0);
  EXPECT_EQ(r.collisions, 0);

  o.explore.goals.max_last_resorts = 0;  // none: it ends at the first timeout
  const ExplorationResult none = Explore(o, 1);
  EXPECT_EQ(none.terminated, Termination::kNoProgress);
  EXPECT_EQ(none.counters.last_resorts, 0);
  EXPECT_NEAR(none.sim_time_s, 20.0, 0.5);
  o.explore.goals.max_last_resorts = 2;
  o.explore.goals.last_resort_confined_s = 30.0;  // longer than the window: never confined
  EXPECT_EQ(Explore(o, 1).counters.last_resorts, 0);
}

TEST(ExplorationLoopTest, AStopRequestEndsTheRunMeasuredLikeAnyOther) {
  // A user's Ctrl-C: asked once, from 20 s of simulated time on.
  ExplorationLoop loop(testing::SmallBuilding(), {}, 7);
  double last_progress_s = 0.0;
  const ExplorationResult r =
      loop.Run([&](const ExplorationProgress& p) { last_progress_s = p.sim_time_s; }, 1.0,
               [&] { return last_progress_s >= 20.0; });
  EXPECT_EQ(r.terminated, Termination::kInterrupted);
  EXPECT_EQ(ToString(r.terminated), "interrupted");
  EXPECT_NEAR(r.sim_time_s, 20.0, 0.5);
  EXPECT_FALSE(r.frontier_counted);
  // The map so far is measured (from the start the lidar sees much of this
  // small building), and the run is shorter than the one left to finish.
  EXPECT_GT(r.coverage, 0.1);
  const ExplorationResult whole = Explore({}, 7);
  EXPECT_EQ(whole.terminated, Termination::kComplete);
  EXPECT_LT(r.path_length_m, whole.path_length_m);
  EXPECT_EQ(r.coverage_samples.back().sim_time_s, r.sim_time_s);
  EXPECT_FALSE(r.truth.empty());
  EXPECT_GT(loop.map_builder().GetTrajectory().size(), 10u);
}

TEST(ExplorationLoopTest, ABoundaryKeepsTheRobotToItsAreaAndCoverageToIt) {
  // The left room only (the dividing wall starts at x = 4.5 m).
  ExplorationOptions o;
  o.explore.boundary = {{0.0, 0.0}, {4.4, 0.0}, {4.4, 6.3}, {0.0, 6.3}};
  ExplorationLoop loop(testing::SmallBuilding(), o, 7);
  const ExplorationResult r = loop.Run();
  const ExplorationResult whole = Explore({}, 7);
  EXPECT_EQ(r.terminated, Termination::kComplete);
  EXPECT_GE(r.coverage, 0.97);
  EXPECT_EQ(r.collisions, 0);
  // About 4 m x 6 m of the 9 m x 6 m building, less the pillar.
  EXPECT_GT(r.reachable_free_m2, 15.0);
  EXPECT_LT(r.reachable_free_m2, 0.55 * whole.reachable_free_m2);
  EXPECT_LT(r.path_length_m, whole.path_length_m);
  for (const IssuedGoal& g : r.goals) {
    EXPECT_LT(g.target_world.x(), 4.4 + 0.3) << "goal issued at t=" << g.sim_time_s << " s";
  }
}

TEST(ExplorationLoopTest, ReportsWhereGoalsFailedAsTheFinalMapHasThem) {
  // No goal can shrink its path by 100 m within 2 s: every goal fails.
  ExplorationOptions o;
  o.explore.goals.progress_timeout_s = 2.0;
  o.explore.goals.progress_min_m = 100.0;
  o.explore.max_sim_time_s = 40.0;
  ExplorationLoop loop(testing::SmallBuilding(), o, 7);
  std::vector<Eigen::Vector2d> blacklisted_seen;
  const ExplorationResult r = loop.Run(
      [&](const ExplorationProgress& p) {
        blacklisted_seen.insert(blacklisted_seen.end(), p.blacklisted_goals.begin(),
                                p.blacklisted_goals.end());
      },
      1.0);
  ASSERT_GT(r.counters.goals_failed, 0);
  EXPECT_FALSE(blacklisted_seen.empty());  // the progress reports list them
  int failures = 0;
  for (const ExplorationResult::FailedGoal& g : r.failed_goals) {
    EXPECT_GE(g.failures, 1);
    failures += g.failures;
    // Each lies where a goal was issued: here every failure is an issued goal
    // that made no progress (4 failures at 3 places, no candidate without a
    // plan), placed by the final submap poses instead of those at the time.
    double nearest_m = 1e9;
    for (const IssuedGoal& issued : r.goals) {
      nearest_m = std::min(nearest_m, (issued.goal_map - g.goal_map).norm());
    }
    EXPECT_LT(nearest_m, 0.6) << g.goal_map.transpose();
  }
  // One failure per failed goal and per candidate no plan led to.
  EXPECT_EQ(failures, r.counters.goals_failed + r.counters.goals_unreachable);
}

TEST(ExplorationLoopTest, BadOptionsAndStartsAreInputErrors) {
  ExplorationOptions o;
  o.explore.frontier_inflation_radius_m = 0.2;  // below the planner's 0.25 in narrow passages
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.explore.strategy = "magic";
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.explore.goal_policy = "random";
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.start = Eigen::Vector2d(2.2, 4.2);  // inside the pillar
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.explore.dt_s = 0.0;
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.explore.boundary = {{0.0, 0.0}, {4.4, 0.0}};  // two vertices
  EXPECT_THROW(Explore(o, 1), InputError);
  o = {};
  o.explore.boundary = {{5.0, 0.0}, {9.0, 0.0}, {9.0, 6.0}, {5.0, 6.0}};  // the start is at x = 1.5
  try {
    Explore(o, 1);
    ADD_FAILURE() << "a boundary without the start was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the boundary"), std::string::npos) << e.what();
  }
}

// The loop runs slam with what the explore section replaces: its local SLAM
// settings and its solve delay, whatever slam's own section says; the rest of
// slam's options (here the near matches of the loop-closure search) it keeps.
TEST(ExplorationLoopTest, TheLoopsSlamTakesTheExploreSectionsReplacements) {
  ExplorationOptions o;
  o.slam.pose_graph.constraint_builder.near_match_max_innovation_m = 0.2;
  o.slam.local.use_online_correlative_scan_matching = true;
  o.explore.local_slam.rotation_weight = 7.0;
  o.explore.solve_delay_nodes = 4;
  slam::SlamOptions s = EffectiveSlamOptions(o);
  EXPECT_EQ(s.pose_graph.constraint_builder.near_match_max_innovation_m, 0.2);
  EXPECT_FALSE(s.local.use_online_correlative_scan_matching);
  EXPECT_EQ(s.local.ceres_scan_matcher.rotation_weight, 7.0);
  EXPECT_TRUE(s.pose_graph.synchronous);
  EXPECT_EQ(s.pose_graph.synchronous_solve_delay_nodes, 4);
}

}  // namespace
}  // namespace scout::exploration
