#ifndef SCOUT_SYNTHETIC_SYNTHETIC_STREAM_H_
#define SCOUT_SYNTHETIC_SYNTHETIC_STREAM_H_

#include <cstdint>
#include <functional>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/grid/range_data_inserter.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sim/lidar.h"
#include "scout/sim/world.h"
#include "scout/synthetic/correction_model.h"
#include "scout/synthetic/tour_planner.h"

// A synthetic submap-SLAM event stream: a stand-in for real SLAM that drives a
// lidar along an exploration-like tour of a true world and emits the events a
// Cartographer-style SLAM would (ARCHITECTURE.md, events/submap_events.h).
namespace scout::synthetic {

struct SyntheticStreamOptions {
  // Cell size of the submap grids.
  double resolution_m = 0.05;
  // Scans per submap (the paper: 70). A new submap starts every
  // scans_per_submap scans; each scan goes into the two active submaps; a
  // submap is finished on its 2 * scans_per_submap-th insertion.
  int scans_per_submap = 70;
  // Motion filter: a scan is taken every scan_spacing_m of travel or
  // scan_spacing_rad of turning (Cartographer: 0.2 m / 1 degree).
  double scan_spacing_m = 0.2;
  double scan_spacing_rad = 0.017453292519943295;  // 1 degree
  // Speeds of the synthetic robot (scan time stamps only).
  double linear_speed_mps = 0.5;
  double angular_speed_radps = 0.5;
  // A pose-graph solve (an Optimized event) after every this many scans.
  int optimize_every_n_scans = 90;
  // 1 degree beams: the stream's SLAM is synthetic (its submaps' poses come
  // from the correction model), so only the grids' look depends on them.
  sim::LidarOptions lidar{.beams = 181};
  sensor::RangeFilterOptions range_filter;
  // Hit 0.55 / miss 0.49 (ALGORITHMS §7).
  grid::RangeDataInserterOptions insertion;
  TourOptions tour;
  CorrectionModelOptions corrections;
  // Stop after this many scans; 0 = the whole tour.
  int max_scans = 0;
};

// Throws InputError naming the first bad option ("synthetic.<key>"), the
// tour's, corrections', lidar's and range filter's included. (The insertion
// probabilities are the inserter's to check; io's reader names them.)
void Validate(const SyntheticStreamOptions& options);

struct StreamStats {
  int scans = 0;
  int submaps = 0;
  int optimizations = 0;
  int loop_closures = 0;  // solves that closed a loop
  double trajectory_length_m = 0.0;
};

class SyntheticEventStream {
 public:
  // Keeps a reference to 'world', which must outlive the stream. Throws
  // InputError naming the option if 'options' is invalid.
  SyntheticEventStream(const sim::World& world, const SyntheticStreamOptions& options,
                       uint64_t seed);

  // Plans the tour, then calls 'sink' for every event in order: per scan, one
  // SubmapChanged per active submap (oldest first), then an Optimized event
  // after every optimize_every_n_scans scans. Returns statistics. The same
  // world, options and seed always give identical events.
  StreamStats Run(const std::function<void(const events::SubmapEvent&)>& sink);

  // True pose (submap frame -> world frame) of every submap of the last Run:
  // the true pose of its first scan.
  const std::vector<geometry::Rigid2d>& true_submap_poses() const { return true_submap_poses_; }
  // True robot pose of every scan of the last Run, in order.
  const std::vector<geometry::Rigid2d>& true_scan_poses() const { return true_scan_poses_; }

 private:
  const sim::World& world_;
  SyntheticStreamOptions options_;
  uint64_t seed_;
  std::vector<geometry::Rigid2d> true_submap_poses_;
  std::vector<geometry::Rigid2d> true_scan_poses_;
};

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_SYNTHETIC_STREAM_H_
