#ifndef SCOUT_SLAM_MAP_BUILDER_H_
#define SCOUT_SLAM_MAP_BUILDER_H_

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sensor/odometry.h"
#include "scout/slam/local_trajectory_builder.h"
#include "scout/slam/pose_extrapolator.h"
#include "scout/slam/pose_graph.h"

namespace scout::slam {

// Every option of SLAM: local SLAM, global SLAM, and the event stream.
struct SlamOptions {
  LocalSlamOptions local;
  PoseGraphOptions pose_graph;
  // A SubmapChanged event is emitted for a submap's first insertion, every
  // this-many-th insertion, and when it finishes. 1 = every insertion; larger
  // values thin the stream for consumers whose per-event work is costly.
  int submap_event_every_n_insertions = 1;
};

// Throws std::invalid_argument naming the option when one is out of range.
void Validate(const SlamOptions& options);

struct SlamStats {
  int num_nodes = 0;
  int num_submaps = 0;
  int num_optimizations = 0;
  int num_loop_closures = 0;
  int num_rejected_loop_closures = 0;  // found, then dropped as outliers by a solve
  int num_gated_loop_closures = 0;     // matches too far from the estimate (PoseGraphStats)
  int num_loop_closure_searches = 0;
  // How the searches that found nothing ended, and the pairs not searched
  // for lack of overlap (PoseGraphStats).
  int num_searches_without_match = 0;
  int num_ambiguous_matches = 0;
  int num_wide_ambiguous_matches = 0;
  int num_matches_seeing_through = 0;
  int num_pairs_without_overlap = 0;
  int num_near_matches = 0;  // loop closures found as near matches (PoseGraphStats)
  double total_solve_time_s = 0.0;
  int num_scans = 0;  // scans given to AddScan
  int num_submap_events = 0;
  int num_optimized_events = 0;
};

// Cartographer-style 2D SLAM: local SLAM builds submaps, the pose graph closes
// loops, and every change reaches 'sink' as a plain event (the seam to the
// frontier module). Events are always delivered in the thread that calls
// AddScan / DrainEvents / Finish. In synchronous mode the event stream is a
// deterministic function of the inputs: per scan, the SubmapChanged events of
// its insertion (oldest submap first), then the Optimized event if the scan
// triggered a solve. In background mode an Optimized event is delivered at
// the first AddScan / DrainEvents / Finish after its solve completed, and
// always after the SubmapChanged of every submap it carries a pose for.
// Drive a MapBuilder from one thread.
class MapBuilder {
 public:
  using EventSink = std::function<void(events::SubmapEvent)>;

  // Throws std::invalid_argument if 'options' are invalid.
  MapBuilder(const SlamOptions& options, EventSink sink);
  ~MapBuilder();

  // Feeds one odometry reading to local SLAM (and to the pose graph's
  // odometry constraints, if enabled).
  void AddOdometry(const sensor::Odometry& odometry);
  // Feeds one scan; returns true if it was inserted (became a node).
  bool AddScan(const sensor::LaserScan& scan);
  // Delivers Optimized events of background solves finished since the last
  // delivery. Never needed in synchronous mode.
  void DrainEvents();
  // Waits for all pending global SLAM work, solves once more and delivers
  // the final Optimized event.
  void Finish();

  // Returns the global pose of every node with its scan time, in node order
  // (the trajectory, e.g. for a TUM file).
  std::vector<TimedPose> GetTrajectory() const;
  // The newest node of the trajectory, if any: its last element.
  std::optional<TimedPose> GetNewestNode() const;
  // Returns poses and latest grids of all submaps (e.g. for the fused map).
  std::vector<SubmapState> GetSubmaps() const;
  // Returns every constraint of the pose graph (intra-submap and loop
  // closures), e.g. to check loop closures against a simulator's truth.
  std::vector<Constraint> GetConstraints() const;
  // Every match the loop-closure search found, and what became of it.
  std::vector<LoopClosureRecord> GetLoopClosureLog() const;
  SlamStats GetStats() const;
  const LocalTrajectoryBuilder& local_trajectory_builder() const { return local_; }

 private:
  void Emit(events::SubmapEvent event);

  const SlamOptions options_;
  const EventSink sink_;
  LocalTrajectoryBuilder local_;
  // Tracks odometry only to look up the odometry pose of each node.
  PoseExtrapolator odometry_;
  std::map<events::SubmapId, int> insertions_per_submap_;
  int num_scans_ = 0;
  int num_submap_events_ = 0;
  int num_optimized_events_ = 0;

  // Optimized events from the pose graph callback, waiting for the caller's
  // thread. Declared before pose_graph_, which must die first (its worker may
  // still call back while it drains).
  mutable std::mutex pending_mutex_;
  std::deque<events::Optimized> pending_;
  std::unique_ptr<PoseGraph> pose_graph_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_MAP_BUILDER_H_
