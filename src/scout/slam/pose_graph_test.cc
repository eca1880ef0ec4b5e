#include "scout/slam/pose_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "scout/grid/range_data_inserter.h"
#include "scout/slam/global_test_world.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

// What a local SLAM would hand to the pose graph while the robot drives 1.3
// laps of the corridor loop: drifting local poses, and submaps built with
// those poses (a new one every 10 scans, each receiving 20 scans).
struct NodeInput {
  double time_s;
  Rigid2d truth;
  Rigid2d local_pose;
  PointCloud points;
  std::vector<InsertedSubmap> submaps;
};

// A point on the corridor centre line at arc length 's' (counter-clockwise,
// starting at the bottom-left corner), heading along the corridor.
Rigid2d CentreLinePose(double s) {
  const double w = 17.0, h = 9.0;
  s = std::fmod(s, 2.0 * (w + h));
  if (s < w) return Rigid2d(-8.5 + s, -4.5, 0.0);
  if (s < w + h) return Rigid2d(8.5, -4.5 + (s - w), M_PI / 2);
  if (s < 2 * w + h) return Rigid2d(8.5 - (s - w - h), 4.5, M_PI);
  return Rigid2d(-8.5, 4.5 - (s - 2 * w - h), -M_PI / 2);
}

// 'heading_bias_rad' per 0.4 m step and 'scale_error' (relative) model
// local SLAM drift; 'slip' (robot frame) is added once, at node 'slip_node'.
std::vector<NodeInput> MakeDriftingRun(int num_nodes, double heading_bias_rad, double scale_error,
                                       int slip_node = -1, const Rigid2d& slip = Rigid2d()) {
  const auto walls = global_testing::CorridorLoop();
  const grid::RangeDataInserter inserter({});
  std::vector<NodeInput> run;
  std::vector<grid::ProbabilityGrid> grids;
  std::vector<Rigid2d> submap_local;
  Rigid2d local = CentreLinePose(0.0);
  Rigid2d previous_truth = local;
  for (int i = 0; i < num_nodes; ++i) {
    const Rigid2d truth = CentreLinePose(0.4 * i);
    if (i > 0) {
      const Rigid2d step = previous_truth.inverse() * truth;
      local = local *
              Rigid2d((1.0 + scale_error) * step.translation(), step.theta() + heading_bias_rad);
    }
    if (i == slip_node) local = local * slip;
    previous_truth = truth;
    NodeInput node{0.1 * i, truth, local, global_testing::ScanReturns(walls, truth), {}};
    if (i % 10 == 0) {
      grids.emplace_back(grid::MapLimits(0.05, {-1.0, -1.0}, 40, 40));
      submap_local.push_back(local);
    }
    const sensor::RangeData data =
        sensor::ToRangeData(global_testing::SimulateScan(walls, truth, 0.0, {}, nullptr), {});
    for (int k : {i / 10 - 1, i / 10}) {
      if (k < 0) continue;
      const Rigid2d in_submap = submap_local[k].inverse() * local;
      inserter.Insert(in_submap.translation(), TransformPointCloud(data.returns, in_submap),
                      TransformPointCloud(data.misses, in_submap), &grids[k]);
      node.submaps.push_back({k, submap_local[k],
                              std::make_shared<const grid::ProbabilityGrid>(grids[k]),
                              /*finished=*/i == 10 * k + 19});
    }
    run.push_back(std::move(node));
  }
  return run;
}

// 1.3 laps with 0.3 % scale error and 0.0012 rad heading bias per step:
// about 0.85 m rms open-loop error.
const std::vector<NodeInput>& DriveRun() {
  static const std::vector<NodeInput> run = MakeDriftingRun(170, 0.0012, 0.003);
  return run;
}

const std::vector<NodeInput>& ExactRun() {
  static const std::vector<NodeInput> run = MakeDriftingRun(170, 0.0, 0.0);
  return run;
}

struct Outcome {
  std::vector<TimedPose> nodes;
  std::vector<std::vector<Rigid2d>> optimized;  // callback payloads, in order
  PoseGraphStats stats;
  std::vector<Constraint> constraints;
  std::vector<LoopClosureRecord> log;
};

int CountOutcome(const Outcome& out, LoopClosureOutcome outcome) {
  return static_cast<int>(
      std::count_if(out.log.begin(), out.log.end(),
                    [&](const LoopClosureRecord& r) { return r.outcome == outcome; }));
}

Outcome Feed(const PoseGraphOptions& options, const std::vector<NodeInput>& run = DriveRun()) {
  Outcome out;
  std::mutex mutex;
  PoseGraph graph(options, [&](const std::vector<Rigid2d>& poses) {
    std::lock_guard<std::mutex> lock(mutex);
    out.optimized.push_back(poses);
  });
  for (const NodeInput& n : run) graph.AddNode(n.time_s, n.local_pose, n.points, n.submaps);
  graph.RunFinalOptimization();
  out.nodes = graph.GetNodePoses();
  out.stats = graph.GetStats();
  out.constraints = graph.GetConstraints();
  out.log = graph.GetLoopClosureLog();
  return out;
}

// Dense loop-closure search (Cartographer's 0.3, every pair): the drive here is
// one short lap, far fewer nodes per submap than the long logs the sparser
// defaults are measured on, and these tests check the graph, not the sampling.
PoseGraphOptions Synchronous() {
  PoseGraphOptions options;
  options.synchronous = true;
  options.skip_neighbour_submaps = 0;
  options.constraint_builder.sampling_ratio = 0.3;
  return options;
}

double RmsError(const std::vector<Rigid2d>& poses, const std::vector<NodeInput>& run) {
  double sum = 0.0;
  for (size_t i = 0; i < poses.size(); ++i) {
    sum += (poses[i].translation() - run[i].truth.translation()).squaredNorm();
  }
  return std::sqrt(sum / poses.size());
}

TEST(PoseGraphTest, LoopClosuresRemoveTheDriftOfLocalSlam) {
  PoseGraphOptions options = Synchronous();
  options.optimize_every_travel_m = 0.0;  // the node cadence alone (checked below)
  const auto start = std::chrono::steady_clock::now();
  const Outcome out = Feed(options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<Rigid2d> local, global;
  for (size_t i = 0; i < DriveRun().size(); ++i) {
    local.push_back(DriveRun()[i].local_pose);
    global.push_back(out.nodes[i].pose);
  }
  const double open_loop = RmsError(local, DriveRun());
  const double closed_loop = RmsError(global, DriveRun());
  RecordProperty("open_loop_rms_m", std::to_string(open_loop));
  RecordProperty("closed_loop_rms_m", std::to_string(closed_loop));
  std::cout << "170 nodes, " << out.stats.num_submaps << " submaps: " << out.stats.num_searches
            << " searches, " << out.stats.num_loop_closures << " loop closures, "
            << out.stats.num_optimizations << " solves (" << out.stats.total_solve_time_s
            << " s), total " << seconds << " s; rms error " << open_loop << " m -> " << closed_loop
            << " m\n";
  ASSERT_GT(open_loop, 0.5);
  EXPECT_GT(out.stats.num_loop_closures, 10);
  // The heading bias is spread over the loop, not removed: the far side keeps
  // ~0.25 m. The closed ends are tight.
  EXPECT_LT(closed_loop, 0.25 * open_loop);
  for (int i = 125; i < 145; ++i) {
    EXPECT_LT((global[i].translation() - DriveRun()[i].truth.translation()).norm(), 0.1) << i;
  }
  EXPECT_EQ(out.stats.num_nodes, 170);
  EXPECT_EQ(out.stats.num_submaps, 17);
  // Every 90 nodes, plus the final solve; each reports every submap.
  EXPECT_EQ(out.stats.num_optimizations, 2);
  ASSERT_EQ(out.optimized.size(), 2u);
  EXPECT_EQ(out.optimized[0].size(), 9u);  // submaps existing at node 90
  EXPECT_EQ(out.optimized[1].size(), 17u);
  EXPECT_EQ(out.nodes[7].time_s, DriveRun()[7].time_s);
}

TEST(PoseGraphTest, SearchWindowsAlongChainsOfLoopClosuresStillCloseTheLoop) {
  // Windows sized by the chain through closures shrink once the loop is
  // closed; the loop must close all the same, and as tightly.
  PoseGraphOptions options = Synchronous();
  options.optimize_every_travel_m = 0.0;
  options.search_windows_through_loop_closures = true;
  const Outcome chained = Feed(options);
  options.search_windows_through_loop_closures = false;
  const Outcome plain = Feed(options);
  std::vector<Rigid2d> local, chained_poses, plain_poses;
  for (size_t i = 0; i < DriveRun().size(); ++i) {
    local.push_back(DriveRun()[i].local_pose);
    chained_poses.push_back(chained.nodes[i].pose);
    plain_poses.push_back(plain.nodes[i].pose);
  }
  const double open_loop = RmsError(local, DriveRun());
  EXPECT_GT(chained.stats.num_loop_closures, 10);
  EXPECT_LT(RmsError(chained_poses, DriveRun()), 0.25 * open_loop);
  EXPECT_LT(RmsError(chained_poses, DriveRun()), RmsError(plain_poses, DriveRun()) + 0.05);
}

// Once loop closures tie the second lap to the first, the graph knows where
// the robot is within the window of that chain; a match farther from the
// estimate is taken for a copy of the place (in the simulated office four
// such closures, 3.95 m off, bent the map). Here local SLAM slips 1.6 m
// forward at node 150, after the second lap's first closures: its matches
// are then 1.6 m from the estimate, inside the trajectory's search window
// (about 2 m) but beyond the chain's (1 m plus 2 % of a few metres).
TEST(PoseGraphTest, MatchesFartherFromTheEstimateThanTheChainAllowsAreGated) {
  const std::vector<NodeInput> run =
      MakeDriftingRun(170, 0.0, 0.0, /*slip_node=*/150, Rigid2d(1.6, 0.0, 0.0));
  PoseGraphOptions options = Synchronous();
  options.loop_closure_chain_travel_m = 0.0;
  options.gate_loop_closures_by_chain = true;
  // Near matches tie the first lap down with more closures of their own
  // (checked at the end); without them the slip's matches show alone.
  const double near_match_max_innovation_m = options.constraint_builder.near_match_max_innovation_m;
  options.constraint_builder.near_match_max_innovation_m = 0.0;
  const Outcome gated = Feed(options, run);
  options.gate_loop_closures_by_chain = false;
  const Outcome outlier_rounds = Feed(options, run);
  options.max_outlier_rounds = 0;
  const Outcome neither = Feed(options, run);
  const auto error = [&](const Outcome& out, int i) {
    return (out.nodes[i].pose.translation() - run[i].truth.translation()).norm();
  };
  // The gate stops the slip's matches before any solve sees them ...
  EXPECT_GT(gated.stats.num_gated_loop_closures, 0);
  EXPECT_EQ(gated.stats.num_rejected_loop_closures, 0);
  EXPECT_LT(error(gated, 100), 0.03);
  // ... where without it only the outlier rounds drop them, after a solve ...
  EXPECT_EQ(outlier_rounds.stats.num_gated_loop_closures, 0);
  EXPECT_GT(outlier_rounds.stats.num_rejected_loop_closures, 0);
  // ... and without either they pull the first lap off, unless near matches
  // hold it.
  EXPECT_GT(error(neither, 100), 0.05);
  options.constraint_builder.near_match_max_innovation_m = near_match_max_innovation_m;
  const Outcome held = Feed(options, run);
  EXPECT_GT(held.stats.num_near_matches, 0);
  EXPECT_LT(error(held, 100), 0.03);

  // The log tells which was which. Every gated match lay beyond its window.
  // Placed by the truth of the submap's first node, the submap frame shows
  // the slip on one side of each: the match (an old node in a submap begun
  // before the slip and filled after it) or the estimate (a node after it).
  EXPECT_EQ(CountOutcome(gated, LoopClosureOutcome::kGated), gated.stats.num_gated_loop_closures);
  EXPECT_EQ(CountOutcome(gated, LoopClosureOutcome::kAccepted), gated.stats.num_loop_closures);
  for (const LoopClosureRecord& r : gated.log) {
    if (r.outcome != LoopClosureOutcome::kGated) continue;
    EXPECT_GT((r.match.translation() - r.estimate.translation()).norm(), r.gate_window_m);
    const Rigid2d submap_truth =
        run[r.submap_first_node_id].truth * r.first_node_in_submap.inverse();
    const Rigid2d truth = submap_truth.inverse() * run[r.node_id].truth;
    const double match_off_m = (truth.translation() - r.match.translation()).norm();
    const double estimate_off_m = (truth.translation() - r.estimate.translation()).norm();
    EXPECT_LT(std::min(match_off_m, estimate_off_m), 0.05) << r.node_id << " in " << r.submap_id;
    EXPECT_NEAR(std::max(match_off_m, estimate_off_m), 1.6, 0.1)
        << r.node_id << " in " << r.submap_id;
  }
  EXPECT_EQ(CountOutcome(outlier_rounds, LoopClosureOutcome::kDropped),
            outlier_rounds.stats.num_rejected_loop_closures);
  EXPECT_EQ(CountOutcome(outlier_rounds, LoopClosureOutcome::kAccepted),
            outlier_rounds.stats.num_loop_closures);
  EXPECT_EQ(CountOutcome(outlier_rounds, LoopClosureOutcome::kGated), 0);
  // Every search ends one way, gated or not, and the log holds each once.
  for (const Outcome* out : {&gated, &outlier_rounds, &neither, &held}) {
    const PoseGraphStats& st = out->stats;
    EXPECT_EQ(st.num_searches, st.num_searches_without_match + st.num_ambiguous_matches +
                                   st.num_gated_loop_closures + st.num_wide_ambiguous_matches +
                                   st.num_matches_seeing_through + st.num_loop_closures +
                                   st.num_rejected_loop_closures);
    EXPECT_EQ(static_cast<int>(out->log.size()), st.num_searches);
    EXPECT_EQ(CountOutcome(*out, LoopClosureOutcome::kNoMatch) +
                  CountOutcome(*out, LoopClosureOutcome::kFar),
              st.num_searches_without_match);
    EXPECT_EQ(CountOutcome(*out, LoopClosureOutcome::kAmbiguous), st.num_ambiguous_matches);
    EXPECT_EQ(CountOutcome(*out, LoopClosureOutcome::kSeeingThrough),
              st.num_matches_seeing_through);
    int near = 0;
    for (const LoopClosureRecord& r : out->log) {
      // A match and its score, or neither; the submap's minimum score and the
      // window always.
      EXPECT_EQ(r.has_match, std::isfinite(r.score));
      EXPECT_EQ(r.has_match, r.outcome != LoopClosureOutcome::kNoMatch);
      EXPECT_GT(r.min_score, 0.0);
      EXPECT_GT(r.search_window_m, 0.0);
      if (r.near_match) {
        ++near;
        EXPECT_LT(r.score, r.min_score);
        EXPECT_LE((r.match.translation() - r.estimate.translation()).norm(), 0.35);
      }
    }
    EXPECT_EQ(near, st.num_near_matches);
  }
}

TEST(PoseGraphTest, ExactLocalSlamStaysExact) {
  // Loop closures must not bias a trajectory that needs no correction (a
  // self-similar corridor once shifted this one by 11 cm).
  const Outcome out = Feed(Synchronous(), ExactRun());
  std::vector<Rigid2d> global;
  for (const TimedPose& p : out.nodes) global.push_back(p.pose);
  EXPECT_GT(out.stats.num_loop_closures, 10);
  EXPECT_LT(RmsError(global, ExactRun()), 0.02);
}

TEST(PoseGraphTest, SynchronousModeIsDeterministic) {
  const Outcome a = Feed(Synchronous());
  const Outcome b = Feed(Synchronous());
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].pose.x(), b.nodes[i].pose.x());
    EXPECT_EQ(a.nodes[i].pose.y(), b.nodes[i].pose.y());
    EXPECT_EQ(a.nodes[i].pose.theta(), b.nodes[i].pose.theta());
  }
  ASSERT_EQ(a.optimized.size(), b.optimized.size());
  for (size_t r = 0; r < a.optimized.size(); ++r) {
    ASSERT_EQ(a.optimized[r].size(), b.optimized[r].size());
    for (size_t s = 0; s < a.optimized[r].size(); ++s) {
      EXPECT_EQ(a.optimized[r][s].x(), b.optimized[r][s].x());
      EXPECT_EQ(a.optimized[r][s].theta(), b.optimized[r][s].theta());
    }
  }
  EXPECT_EQ(a.constraints.size(), b.constraints.size());
}

TEST(PoseGraphTest, BackgroundModeMatchesSynchronousMode) {
  const Outcome sync = Feed(Synchronous());
  PoseGraphOptions background_options = Synchronous();
  background_options.synchronous = false;
  const Outcome background = Feed(background_options);
  EXPECT_EQ(background.stats.num_loop_closures, sync.stats.num_loop_closures);
  EXPECT_EQ(background.stats.num_optimizations, sync.stats.num_optimizations);
  ASSERT_EQ(background.nodes.size(), sync.nodes.size());
  for (size_t i = 0; i < sync.nodes.size(); ++i) {
    EXPECT_LT((background.nodes[i].pose.translation() - sync.nodes[i].pose.translation()).norm(),
              1e-6);
  }
  ASSERT_EQ(background.optimized.size(), sync.optimized.size());
  EXPECT_EQ(background.optimized.back().size(), sync.optimized.back().size());
}

// A solve delayed by 10 nodes runs beside the caller, and its result is
// applied before node 90 + 10 + 1, never earlier or later: runs repeat bit
// for bit, and the loop closes as well as with the solve applied at once.
TEST(PoseGraphTest, DelayedSynchronousSolvesApplyAtAFixedNode) {
  PoseGraphOptions delayed = Synchronous();
  delayed.optimize_every_travel_m = 0.0;  // one solve at node 90, then the final one
  delayed.synchronous_solve_delay_nodes = 10;
  const auto& run = DriveRun();
  std::vector<int> solves_seen_at;  // nodes added when each callback came
  int added = 0;
  PoseGraph graph(delayed, [&](const std::vector<Rigid2d>&) { solves_seen_at.push_back(added); });
  std::vector<Rigid2d> before_apply;
  for (const NodeInput& n : run) {
    graph.AddNode(n.time_s, n.local_pose, n.points, n.submaps);
    ++added;
    if (added == 100) {
      for (const TimedPose& p : graph.GetNodePoses()) before_apply.push_back(p.pose);
    }
  }
  graph.RunFinalOptimization();
  // Node 89 (the 90th) starts the solve; it is applied as node 100 is added.
  ASSERT_EQ(solves_seen_at.size(), 2u);
  EXPECT_EQ(solves_seen_at[0], 100);
  EXPECT_EQ(graph.GetStats().num_optimizations, 2);
  // Until then nodes keep local SLAM's poses (no correction yet).
  for (int i = 0; i < 100; ++i) {
    EXPECT_NEAR(before_apply[i].x(), run[i].local_pose.x(), 1e-9) << i;
  }
  std::vector<Rigid2d> global;
  for (const TimedPose& p : graph.GetNodePoses()) global.push_back(p.pose);
  std::vector<Rigid2d> immediate;
  for (const TimedPose& p : Feed([] {
                              PoseGraphOptions o = Synchronous();
                              o.optimize_every_travel_m = 0.0;
                              return o;
                            }())
                                .nodes) {
    immediate.push_back(p.pose);
  }
  EXPECT_LT(RmsError(global, run), 1.2 * RmsError(immediate, run) + 0.01);
  // Deterministic.
  const Outcome again = Feed(delayed);
  ASSERT_EQ(again.nodes.size(), global.size());
  for (size_t i = 0; i < global.size(); ++i) {
    EXPECT_EQ(again.nodes[i].pose.x(), global[i].x());
    EXPECT_EQ(again.nodes[i].pose.theta(), global[i].theta());
  }
}

TEST(PoseGraphTest, NodesAddedAfterASolveFollowTheCorrection) {
  PoseGraphOptions options = Synchronous();
  options.optimize_every_n_nodes = 0;  // solve only on request
  PoseGraph graph(options, nullptr);
  const auto& run = DriveRun();
  for (int i = 0; i < 150; ++i) {
    graph.AddNode(run[i].time_s, run[i].local_pose, run[i].points, run[i].submaps);
  }
  graph.RunFinalOptimization();
  const Rigid2d local_to_global = graph.GetLocalToGlobal();
  // The loop was closed, so the correction is far from identity.
  EXPECT_GT(local_to_global.translation().norm() + std::abs(local_to_global.theta()), 0.1);
  for (int i = 150; i < 155; ++i) {
    graph.AddNode(run[i].time_s, run[i].local_pose, run[i].points, run[i].submaps);
  }
  const std::vector<TimedPose> poses = graph.GetNodePoses();
  for (int i = 150; i < 155; ++i) {
    const Rigid2d expected = local_to_global * run[i].local_pose;
    EXPECT_NEAR(poses[i].pose.x(), expected.x(), 1e-9);
    EXPECT_NEAR(poses[i].pose.y(), expected.y(), 1e-9);
    // And the correction helps: the new nodes are near the truth.
    EXPECT_LT((poses[i].pose.translation() - run[i].truth.translation()).norm(), 0.3);
  }
}

TEST(PoseGraphTest, SkipsNeighbourSubmapsWhenAsked) {
  const auto& run = DriveRun();
  PoseGraphOptions dense = Synchronous();
  PoseGraphOptions sparse = Synchronous();
  sparse.skip_neighbour_submaps = 2;
  PoseGraph all(dense, nullptr), skipping(sparse, nullptr);
  for (const NodeInput& node : run) {
    all.AddNode(node.time_s, node.local_pose, node.points, node.submaps);
    skipping.AddNode(node.time_s, node.local_pose, node.points, node.submaps);
  }
  EXPECT_LT(skipping.GetStats().num_searches, all.GetStats().num_searches);
  for (const Constraint& c : skipping.GetConstraints()) {
    if (c.kind != ConstraintKind::kInterSubmap) continue;
    for (const Constraint& intra : skipping.GetConstraints()) {
      if (intra.kind == ConstraintKind::kIntraSubmap && intra.node_id == c.node_id) {
        EXPECT_GT(std::abs(intra.submap_id - c.submap_id), 2);
      }
    }
  }
  PoseGraphOptions negative = Synchronous();
  negative.skip_neighbour_submaps = -1;
  EXPECT_THROW(PoseGraph(negative, nullptr), std::invalid_argument);
}

TEST(PoseGraphTest, OptimizesEveryNNodesOrEveryStretchOfTravel) {
  // The drive: 170 nodes 0.4 m apart (67.6 m).
  PoseGraphOptions by_nodes = Synchronous();
  by_nodes.optimize_every_n_nodes = 50;
  by_nodes.optimize_every_travel_m = 0.0;
  EXPECT_EQ(Feed(by_nodes).stats.num_optimizations, 3 + 1);  // nodes 50, 100, 150; final
  PoseGraphOptions by_travel = Synchronous();
  by_travel.optimize_every_n_nodes = 0;
  by_travel.optimize_every_travel_m = 10.0;
  // Every 25 nodes (10 m; node k is 0.4 k m along): 6 solves, then the final one.
  EXPECT_EQ(Feed(by_travel).stats.num_optimizations, 6 + 1);
  PoseGraphOptions both = by_nodes;
  both.optimize_every_travel_m = 10.0;
  EXPECT_EQ(Feed(both).stats.num_optimizations, 6 + 1);
  PoseGraphOptions bad = Synchronous();
  bad.optimize_every_travel_m = -1.0;
  EXPECT_THROW(PoseGraph(bad, nullptr), std::invalid_argument);
}

TEST(PoseGraphTest, RejectsGapsInSubmapIdsAndMissingGrids) {
  PoseGraph graph(Synchronous(), nullptr);
  const auto grid =
      std::make_shared<const grid::ProbabilityGrid>(grid::MapLimits(0.05, {0.0, 0.0}, 10, 10));
  EXPECT_THROW(graph.AddNode(0.0, Rigid2d(), {}, {{1, Rigid2d(), grid, false}}),
               std::invalid_argument);
  EXPECT_THROW(graph.AddNode(0.0, Rigid2d(), {}, {{0, Rigid2d(), nullptr, false}}),
               std::invalid_argument);
  EXPECT_EQ(graph.AddNode(0.0, Rigid2d(), {}, {{0, Rigid2d(), grid, false}}), 0);
  PoseGraphOptions bad;
  bad.optimize_every_n_nodes = -1;
  EXPECT_THROW(PoseGraph(bad, nullptr), std::invalid_argument);
  bad = {};
  bad.intra_submap_rotation_weight = 0.0;
  EXPECT_THROW(PoseGraph(bad, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
