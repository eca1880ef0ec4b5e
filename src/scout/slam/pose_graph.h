#ifndef SCOUT_SLAM_POSE_GRAPH_H_
#define SCOUT_SLAM_POSE_GRAPH_H_

#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/slam/constraint_builder.h"
#include "scout/slam/optimization_problem.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/pose_graph_types.h"
#include "scout/slam/submap_chain.h"
#include "scout/slam/work_queue.h"

namespace scout::slam {

// Global SLAM settings (ALGORITHMS §7, Cartographer's 2D defaults).
struct PoseGraphOptions {
  // A solve runs after every this many added nodes (0: only on request).
  int optimize_every_n_nodes = 90;
  // ... or once the trajectory has grown this much since the last solve,
  // whichever comes first (0 = nodes only). 90 nodes are 10-20 m at 0.2 m
  // between scans but 90 m in logs with one scan per metre.
  double optimize_every_travel_m = 20.0;
  // Run constraint search and solves in the calling thread, in a fixed order
  // (tests, lockstep evaluation). Otherwise one background thread does them.
  bool synchronous = false;
  // Synchronous mode only: a solve runs on a second thread while this many
  // more nodes are added, and its result is applied just before the node
  // after them (or before the next solve or the final optimisation, when
  // sooner). Results stay deterministic, applied at fixed nodes, but the
  // solve overlaps the caller's work. Until then the graph and searches see
  // the poses of the solve before. 0: applied at once, as in background mode
  // with an idle worker.
  int synchronous_solve_delay_nodes = 0;
  // Weights of the node-to-insertion-submap constraints. Far below the loop
  // closure weights: they encode local SLAM's drift-prone placement.
  double intra_submap_translation_weight = 5e2;
  double intra_submap_rotation_weight = 1.6e3;
  // Scans are thinned further for loop-closure search than for local SLAM:
  // branch and bound costs grow with the number of points.
  AdaptiveVoxelFilterOptions loop_closure_voxel_filter{
      .max_length_m = 0.9, .min_num_points = 100, .max_range_m = 50.0};
  // Loop closures are not searched between a node and a finished submap whose
  // id is within this many of one of the node's insertion submaps (0: search
  // every pair). Local SLAM already ties such pairs rigidly through the
  // overlapping submaps, so a match there adds little but costs a full search.
  // fr079 bag: 2 (with sampling_ratio 0.05) cut searches 30,563 -> 4,475 at
  // ATE 0.086 -> 0.089 m.
  int skip_neighbour_submaps = 2;
  // The loop-closure search window grows with the trajectory between a node
  // and a submap (constraint_builder.search_window_per_travel): drift
  // accumulates along it. With this on, that length is taken along the
  // shortest chain of the submap sequence and the loop closures found so far
  // (ShortestChainTravel), since a closure ties the two places it joins. In a
  // building explored back and forth every place is then a short chain from
  // every other, and the window stays small. With the trajectory alone, a
  // robot 300 m on searched 7 m around its estimate: in the simulated office
  // (rooms 6.16 m apart; meanshift-centres policy, seed 2, its sensor data
  // replayed) six closures one room off were accepted together and bent the
  // map, ATE 1.81 m (0.133 m without any closure); with chains 0.050 m. The
  // Radish logs (odometry noise 1, seeds 1-3) stay within 0.01 m except aces
  // seed 1 (0.457 -> 0.441) and csail seed 2 (0.495 -> 0.784; both miss
  // 0.15 m either way); fr079 0.082 -> 0.083. Off by default: in the closed
  // loop the scout policy's office runs (seeds 1-5) came out worse, ATE
  // 0.045 / 0.051 / 0.039 / 0.030 / 0.083 -> 0.051 / 0.073 / 0.036 / 0.062 /
  // 0.101 m, and seed 5 collided once; the meanshift-centres run above went
  // from 1.226 m and 84 % coverage to 0.040 m and 99.9 %.
  bool search_windows_through_loop_closures = false;
  // Each loop closure on such a chain counts as this much trajectory on top:
  // a closure is only as good as its match (a cell, a fraction of a degree).
  // 10 m: aces seed 1 0.528 m; 30 m: 0.441 m, the rest alike.
  double loop_closure_chain_travel_m = 30.0;
  // Gate on the same chains, independent of the switch above: the search
  // window stays the trajectory's, but a match farther from the estimate
  // than the window of the chain's length (min_search_window_m +
  // search_window_per_travel * chain) is rejected. Once loop closures tie a
  // place to the submap, the graph knows the node's pose there within that
  // much, and a match metres away is a copy of the place. Office (intended
  // odometry noise, seed 4, its sensor log replayed to 11,150 scans): four
  // consistent closures 3.95 m off (by the simulator's truth) to the first
  // submaps bent the map to ATE 1.18 m (0.075 m at 11,100 scans).
  bool gate_loop_closures_by_chain = true;
  // Loop closures the solved graph disagrees with by more than this
  // (translation or rotation of the node in the submap frame) are dropped
  // for good and the graph is solved again, up to max_outlier_rounds times.
  // A wrong closure the Huber loss only dampens still bends the map: in the
  // simulated office, closures accepted late in a run rotated the whole map
  // by 3-4 degrees. 0 rounds keeps every closure.
  double outlier_translation_m = 0.3;
  double outlier_rotation_deg = 3.0;
  int max_outlier_rounds = 2;
  ConstraintBuilderOptions constraint_builder;
  OptimizationProblemOptions optimization_problem;
};

// Throws std::invalid_argument naming the option when one is out of range.
void Validate(const PoseGraphOptions& options);

// A submap as local SLAM reports it with a node inserted into it.
struct InsertedSubmap {
  int id = 0;
  geometry::Rigid2d local_pose;                       // submap frame -> local SLAM frame
  std::shared_ptr<const grid::ProbabilityGrid> grid;  // snapshot after the insertion
  bool finished = false;
};

struct PoseGraphStats {
  int num_nodes = 0;
  int num_submaps = 0;
  int num_optimizations = 0;
  int num_loop_closures = 0;           // accepted inter-submap constraints
  int num_searches = 0;                // (node, submap) pairs searched for a loop closure
  int num_rejected_loop_closures = 0;  // dropped as outliers after a solve
  // Matches rejected by gate_loop_closures_by_chain. The gate comes first,
  // so this counts some the wide ambiguity or see-through tests would reject.
  int num_gated_loop_closures = 0;
  // Why the other searches found nothing (ConstraintBuilder's counters): no
  // match above the minimum score, a rival as good elsewhere in the window,
  // a match that is not the one best in a wide window, rays through known
  // walls; and the pairs not searched because too little of the scan fell on
  // the submap.
  int num_searches_without_match = 0;
  int num_ambiguous_matches = 0;
  int num_wide_ambiguous_matches = 0;
  int num_matches_seeing_through = 0;
  int num_pairs_without_overlap = 0;
  // Loop closures (accepted, or later dropped) that scored below the minimum
  // score and were taken as near matches (near_match_max_innovation_m).
  int num_near_matches = 0;
  double total_solve_time_s = 0.0;
  double last_solve_time_s = 0.0;
};

struct TimedPose {
  double time_s = 0.0;
  geometry::Rigid2d pose;
};

struct SubmapState {
  geometry::Rigid2d local_pose;
  geometry::Rigid2d global_pose;
  std::shared_ptr<const grid::ProbabilityGrid> grid;
  bool finished = false;
};

// The pose graph of global SLAM: nodes (one per inserted scan) and submaps,
// intra-submap constraints from local SLAM, loop closures from the constraint
// builder, and sparse pose adjustment every N nodes. Public methods are
// thread-safe; call AddNode from one thread.
class PoseGraph {
 public:
  // Receives the global pose of every submap after each solve, indexed by
  // submap id. Called on the worker thread in background mode.
  using OptimizationCallback = std::function<void(const std::vector<geometry::Rigid2d>&)>;

  // Throws std::invalid_argument if 'options' are invalid.
  PoseGraph(const PoseGraphOptions& options, OptimizationCallback callback);
  // Finishes pending work (no final solve; see RunFinalOptimization).
  ~PoseGraph();

  // Adds a node at robot pose 'local_pose' (local SLAM frame) whose scan
  // 'points' (robot frame) went into 'insertion_submaps'. New submap ids must
  // continue the dense numbering; known ones get the new grid snapshot.
  // Returns the node id (dense from 0). Throws std::invalid_argument on a
  // gap in submap ids or a missing grid.
  int AddNode(double time_s, const geometry::Rigid2d& local_pose, const PointCloud& points,
              const std::vector<InsertedSubmap>& insertion_submaps,
              std::optional<geometry::Rigid2d> odometry_pose = std::nullopt);

  // Waits for all pending searches and solves, then solves once more.
  void RunFinalOptimization();
  // Returns once all work scheduled so far is done.
  void WaitForPendingWork();

  // Returns the global pose and scan time of every node, by node id.
  std::vector<TimedPose> GetNodePoses() const;
  // Returns the newest node's, if any (without copying the others).
  std::optional<TimedPose> GetNewestNodePose() const;
  // Returns the global pose of every submap, by submap id.
  std::vector<geometry::Rigid2d> GetSubmapGlobalPoses() const;
  // Returns poses and the latest grid of every submap, by submap id.
  std::vector<SubmapState> GetSubmaps() const;
  // Returns every constraint found so far.
  std::vector<Constraint> GetConstraints() const;
  // Returns every loop-closure search, how it ended (accepted, gated or
  // dropped since; or why no closure was made) and the match where there
  // was one, in the order they were made.
  std::vector<LoopClosureRecord> GetLoopClosureLog() const;
  // Returns the transform that maps local SLAM poses into the global frame,
  // as of the latest solve.
  geometry::Rigid2d GetLocalToGlobal() const;
  PoseGraphStats GetStats() const;

 private:
  struct Node {
    OptimizationNode data;
    std::shared_ptr<const PointCloud> points;  // thinned, robot frame
    double travel_m = 0.0;                     // local trajectory length up to this node
    std::vector<int> submap_ids;               // insertion submaps
  };
  struct Submap {
    SubmapState state;
    std::vector<int> node_ids;  // nodes inserted into it
  };

  // A solve's inputs, copied from the graph of the first 'num_nodes' nodes
  // and 'num_submaps' submaps, and its outcome.
  struct SolveInput {
    int num_nodes = 0;
    int num_submaps = 0;
    std::vector<OptimizationNode> nodes;
    std::vector<geometry::Rigid2d> submap_poses;
    std::vector<Constraint> constraints;
  };
  struct SolveOutput {
    OptimizationResult result;
    std::vector<Constraint> rejected;  // loop closures dropped as outliers
  };
  struct PendingSolve {
    int num_nodes = 0;
    int num_submaps = 0;
    int apply_before_node = 0;  // node id
    std::future<SolveOutput> output;
  };

  // Background steps, run in scheduling order by work_queue_.
  void ComputeConstraints(int node_id, const std::vector<int>& newly_finished);
  // Searches the (node id, submap id) 'pairs' the constraint builder
  // chooses (in order: its samplers count), the searches themselves on
  // several threads, and adds the closures found in the order of 'pairs', so
  // the graph is the same as searched one by one.
  void SearchPairs(const std::vector<std::pair<int, int>>& pairs);
  // The trajectory at which the first node of 'submap_id' was inserted.
  // mutex_ held.
  double SubmapStartTravel(int submap_id) const;
  // Records an accepted loop closure in loop_links_. mutex_ held.
  void AddLoopLink(const Constraint& closure);
  // Trajectory length of the shortest chain from 'sources' (submap id,
  // length already travelled) to every submap, over consecutive submaps and
  // loop_links_. mutex_ held.
  std::vector<double> ChainTravel(const std::vector<std::pair<int, double>>& sources) const;
  // True if 'submap_id' is a trajectory neighbour of a submap in 'node_submaps'.
  bool IsNeighbour(const std::vector<int>& node_submaps, int submap_id) const;
  void Optimize(int num_nodes, int num_submaps);
  SolveInput SnapshotForSolve(int num_nodes, int num_submaps) const;
  // Pure: reads only 'input' and the (stateless) optimisation problem.
  SolveOutput Solve(SolveInput input) const;
  void ApplySolve(int num_nodes, int num_submaps, const SolveOutput& output);
  // Synchronous mode with a solve delay: starts a solve on a second thread,
  // and applies a started one (waiting for it) when 'force' or its node came.
  void StartSolve(int num_nodes, int num_submaps, int node_id);
  void ApplyPendingSolve(bool force, int next_node_id);

  const PoseGraphOptions options_;
  const OptimizationCallback callback_;
  const OptimizationProblem optimization_problem_;
  ConstraintBuilder
      constraint_builder_;  // only touched by queued steps (GetStats reads an atomic counter)

  mutable std::mutex mutex_;
  std::vector<Node> nodes_;
  std::vector<Submap> submaps_;
  std::vector<Constraint> constraints_;
  std::vector<LoopClosureRecord> loop_closure_log_;
  // Accepted loop closures as links between submaps (by submap id): a
  // closure of node n in submap s links each insertion submap a of n with s,
  // n's travel from a's first node (plus loop_closure_chain_travel_m) apart.
  std::vector<std::vector<SubmapLink>> loop_links_;
  geometry::Rigid2d local_to_global_;
  int nodes_since_optimization_ = 0;
  double travel_at_optimization_m_ = 0.0;  // node travel when the last solve was scheduled
  PoseGraphStats stats_;
  // Only touched by the thread calling AddNode (synchronous mode).
  std::optional<PendingSolve> pending_solve_;

  // Declared last: destroyed first, so queued steps never see dead members.
  WorkQueue work_queue_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_POSE_GRAPH_H_
