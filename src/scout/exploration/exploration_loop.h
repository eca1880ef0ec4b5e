#ifndef SCOUT_EXPLORATION_EXPLORATION_LOOP_H_
#define SCOUT_EXPLORATION_EXPLORATION_LOOP_H_

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "scout/exploration/exploration_options.h"
#include "scout/exploration/ground_truth.h"
#include "scout/exploration/map_progress.h"
#include "scout/explore/goal_manager.h"
#include "scout/explore/scan_memory.h"
#include "scout/frontier/frontier_engine.h"
#include "scout/grid/incremental_fusion.h"
#include "scout/grid/occupancy_map.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sensor/odometry.h"
#include "scout/sim/simulated_robot.h"
#include "scout/sim/world.h"
#include "scout/slam/map_builder.h"

namespace scout::exploration {

// Why a run ended.
enum class Termination {
  kComplete,     // the goal manager found no frontier left (and came home, if asked)
  kMaxSimTime,   // explore.max_sim_time_s passed
  kNoProgress,   // the robot's map stopped growing for explore.no_progress_timeout_s, or
                 // frontier points remained that no goal could reach
  kInterrupted,  // the caller asked the run to stop (a user's Ctrl-C)
};
std::string_view ToString(Termination termination);

struct CoverageSample {
  double sim_time_s = 0.0;
  double path_length_m = 0.0;  // true distance driven so far
  double coverage = 0.0;
  // Free area of the robot's own fused map (what no_progress watches).
  double map_free_m2 = 0.0;
};

// A goal the goal manager issued, judged against the true world.
struct IssuedGoal {
  double sim_time_s = 0.0;
  // The navigation point, and where the robot was sent for it (the stand-off
  // point before it, or the point itself; GoalManagerOptions::max_stand_off_m),
  // placed in the world by the scans that mapped each: relative to the true
  // pose of the node nearest to it in a submap that knows it, as it lay
  // relative to that node in the submap (ExplorationLoop::MapPointsInWorld).
  Eigen::Vector2d goal_world = Eigen::Vector2d::Zero();
  Eigen::Vector2d target_world = Eigen::Vector2d::Zero();
  // The navigation point in the map frame as it was when issued (for
  // pictures of the estimated map).
  Eigen::Vector2d goal_map = Eigen::Vector2d::Zero();
  Eigen::Vector2d target_map = Eigen::Vector2d::Zero();
  Eigen::Vector2d robot_world = Eigen::Vector2d::Zero();  // true position then
  Eigen::Vector2d robot_map = Eigen::Vector2d::Zero();    // estimated position then
  // The goal manager's record of it: score, planned path, how it ended.
  explore::GoalRecord record;
  // False when the bare disc could not get within the goal tolerance of the
  // target from where it stood: the robot was sent somewhere it cannot be.
  bool reachable_in_truth = true;
  // The same for the navigation point itself (a frontier point on the edge
  // of unseen furniture is not; the stand-off exists for those).
  bool point_reachable_in_truth = true;
  // For the first kMaxUnreachableSnapshots goals not reachable in truth: the
  // fused map the goal was chosen on and the path planned to it (map frame),
  // so the picture of what the robot believed outlives later optimisations.
  std::shared_ptr<const grid::OccupancyMap> map_then;
  std::vector<Eigen::Vector2d> path_map;
  // ... and the returns of the latest scan then, placed in the map by the
  // estimated pose and in the world by the true one.
  std::vector<Eigen::Vector2d> scan_map;
  std::vector<Eigen::Vector2d> scan_world;
};

inline constexpr int kMaxUnreachableSnapshots = 3;

// What a running exploration reports (poses and points in the world frame,
// where the truth and the outputs are).
struct ExplorationProgress {
  double sim_time_s = 0.0;
  double coverage = 0.0;
  explore::ExploreState state = explore::ExploreState::kIdle;
  explore::ExploreCounters counters;
  double path_length_m = 0.0;
  int collisions = 0;
  geometry::Rigid2d estimated_pose;  // SLAM's
  geometry::Rigid2d true_pose;       // the simulator's
  std::optional<Eigen::Vector2d> goal;
  // Global frontier points of the latest fused map, and the navigation
  // points of the latest goal selection.
  int frontier_points = 0;
  int navigation_points = 0;
  // Goals the robot will not be sent to (near) while the map around them
  // stays as it is: failed, or no plan led to them.
  std::vector<Eigen::Vector2d> blacklisted_goals;
  // The last report of a run: SLAM finished and the final map measured.
  bool finished = false;
};

// Wall time spent in each part of the loop, seconds (SLAM excludes the
// frontier engine, which runs inside its event sink).
struct LoopTimings {
  double simulation_s = 0.0;
  double slam_s = 0.0;
  double frontier_s = 0.0;
  double map_fusion_s = 0.0;  // fused map, global frontier, coverage
  double goals_s = 0.0;       // the goal manager (planning maps, selection, A*)
};

struct ExplorationResult {
  Termination terminated = Termination::kMaxSimTime;
  // Mapped reachable free area / reachable free area (see GroundTruth), the
  // map placed by the rigid fit of the SLAM nodes to the truth.
  double coverage = 0.0;
  double mapped_free_m2 = 0.0;
  double reachable_free_m2 = 0.0;
  // Known free area of the robot's own fused map (what it believes it mapped).
  double map_free_m2 = 0.0;
  double path_length_m = 0.0;
  double sim_time_s = 0.0;
  // First sim time coverage reached each of kCoverageThresholds (if it did).
  std::vector<std::optional<double>> time_to_coverage_s;
  explore::ExploreCounters counters;
  // Issued goals the true world makes unreachable for the robot disc.
  int unreachable_goals = 0;
  // Issued navigation points the disc could not get within the goal
  // tolerance of (whatever the stand-off made of them).
  int unreachable_points = 0;
  int collisions = 0;
  bool returned_home = false;
  // Whether the goal manager finished (ran out of navigation points), so
  // that the frontier left was counted; not for runs that ran out of time,
  // stopped gaining map, or were interrupted while it still had goals.
  bool frontier_counted = false;
  // Frontier points left when the goal manager finished.
  int frontier_left = 0;
  // Of frontier_left, reachable by a plan and never visited, and reachable
  // but near a goal the robot reached (ExploreStatus).
  int reachable_frontier_left = 0;
  int visited_frontier_left = 0;
  // Where the reachable ones lie in the true world (placed like goals).
  std::vector<Eigen::Vector2d> reachable_frontier_left_world;
  std::vector<CoverageSample> coverage_samples;
  std::vector<IssuedGoal> goals;
  // The navigation points of the goal policy's latest selection, best first,
  // map frame (none when it finished because none was left).
  std::vector<Eigen::Vector2d> last_candidates_map;
  // Every place a goal failed at (not reached in time, or no plan led to
  // it), where the final submap poses put it (map frame), how often it
  // failed, and whether it was still blacklisted at the end (false: the map
  // around it changed and it was free to be chosen again).
  struct FailedGoal {
    Eigen::Vector2d goal_map = Eigen::Vector2d::Zero();
    int failures = 0;
    bool blacklisted = true;
  };
  std::vector<FailedGoal> failed_goals;
  // Where each collision began (true position, world frame) and when.
  struct Collision {
    double sim_time_s = 0.0;
    Eigen::Vector2d robot_world = Eigen::Vector2d::Zero();
  };
  std::vector<Collision> collision_places;
  // True poses at every scan time (world frame); estimated poses of the SLAM
  // nodes are MapBuilder::GetTrajectory() mapped by world_from_map.
  std::vector<slam::TimedPose> truth;
  LoopTimings timings;
};

// Coverage levels whose first-reach time is reported.
inline constexpr double kCoverageThresholds[] = {0.90, 0.95, 0.99};

// The closed loop in simulation: SimulatedRobot → MapBuilder (SLAM) →
// FrontierEngine (one strategy) → fused map → GoalManager (with the robot's
// SLAM estimate, never its true pose) → velocity commands → SimulatedRobot.
// With synchronous SLAM the run is a deterministic function of world,
// options and seed. Frames: SLAM's map frame is the robot's pose at t = 0;
// world_from_map() places it in the world (only evaluation and outputs use it).
class ExplorationLoop {
 public:
  using ProgressCallback = std::function<void(const ExplorationProgress&)>;
  // Sees every scan as SLAM gets it, with the robot's true pose (world frame)
  // and its odometry pose at the scan's time: `scout explore --record-log`.
  using ScanRecorder =
      std::function<void(const sensor::LaserScan& scan, const geometry::Rigid2d& true_pose,
                         const geometry::Rigid2d& odometry_pose)>;
  // Sees every odometry sample as SLAM gets it (before the scan of the same
  // step, as SLAM gets them).
  using OdometryRecorder = std::function<void(const sensor::Odometry& odometry)>;

  // Throws InputError on bad options, a start the robot does not fit at, or
  // no reachable free space.
  ExplorationLoop(const sim::World& world, const ExplorationOptions& options, uint64_t seed);

  // Runs until a termination condition, then finishes SLAM (final
  // optimisation) and measures the final map. Calls 'progress' about every
  // 'progress_interval_s' of sim time, and 'stop_requested' every control
  // step: when it returns true the run ends "interrupted" and is measured like
  // any other (a user's Ctrl-C keeps the map so far). Call once.
  ExplorationResult Run(const ProgressCallback& progress = {}, double progress_interval_s = 10.0,
                        const std::function<bool()>& stop_requested = {});

  // Call before Run().
  void set_scan_recorder(ScanRecorder recorder) { scan_recorder_ = std::move(recorder); }
  void set_odometry_recorder(OdometryRecorder recorder) {
    odometry_recorder_ = std::move(recorder);
  }

  const slam::MapBuilder& map_builder() const { return *builder_; }
  const frontier::FrontierEngine& frontier_engine() const { return engine_; }
  const GroundTruth& ground_truth() const { return truth_; }
  const sim::World& world() const { return world_; }
  // The latest fused map (map frame).
  const grid::OccupancyMap& fused_map() const { return fused_map_; }
  const geometry::Rigid2d& world_from_map() const { return world_from_map_; }
  const ExplorationOptions& options() const { return options_; }
  // Per cell of ground_truth().limits(): what the final coverage counted
  // (GroundTruth::CoverageMask of the latest fused map, placed as coverage
  // places it).
  std::vector<uint8_t> CoverageMask() const;

 private:
  ExplorationProgress MakeProgress(double sim_time_s, const explore::ExploreStatus& status) const;
  // Feeds due sensor readings to SLAM and keeps the pose estimate current.
  void FeedSensors();
  void FeedSensorsUntimed();
  // Returns the robot's SLAM estimate (map frame) at the latest odometry.
  geometry::Rigid2d EstimatedPose() const;
  // The robot's pose in local SLAM's frame (no jumps on optimisations): the
  // newest matched pose moved on by odometry since its scan.
  geometry::Rigid2d LocalPose() const;
  // Where points of the estimated map lie in the true world (see the .cc).
  std::vector<Eigen::Vector2d> MapPointsInWorld(
      const std::vector<Eigen::Vector2d>& points_map) const;
  // The robot's true pose at the scan stamped 'time_s' (a SLAM node's), if any.
  const slam::TimedPose* TruthAtScan(double time_s) const;
  // Where coverage places the fused map in the world, given SLAM's current
  // nodes (see the .cc).
  geometry::Rigid2d CoverageAlignment(const std::vector<slam::TimedPose>& nodes) const;
  // Rebuilds the fused map and frontier if SLAM changed them and the interval
  // has passed; returns true if it did.
  bool MaybeUpdateMap(bool force);
  // The robot's own mapped area (no_progress watches it) now, and coverage
  // on another thread; 'nodes' are SLAM's current ones. Coverage is only
  // measured, never acted on, so the loop does not wait for it: it waits at
  // the next measurement (CompleteCoverage), and the result is the same.
  void MeasureCoverage(const std::vector<slam::TimedPose>& nodes);
  // Waits for the coverage measurement in flight, if any, and records it: in
  // result_ and in the coverage samples taken since it started.
  void CompleteCoverage();
  void RecordIssuedGoal(const Eigen::Vector2d& goal_map, const Eigen::Vector2d& target_map,
                        const std::vector<Eigen::Vector2d>& path_map);
  std::optional<Termination> CheckTermination(const explore::ExploreStatus& status) const;
  // When the no-progress clock started: the map's last progress, or the
  // goal manager's last resort after it.
  double NoProgressSince() const;
  // Where the robot stood confined during the no-progress window ending at
  // 'sim_time_s': the latest SLAM node whose neighbours in time, over at least
  // last_resort_confined_s, all lie within last_resort_confined_radius_m of it
  // (GoalManagerOptions::last_resort_*); nothing if it never stood that long.
  std::optional<Eigen::Vector2d> ConfinedAt(double sim_time_s) const;

  const ExplorationOptions options_;
  sim::World world_;
  GroundTruth truth_;
  sim::SimulatedRobot robot_;
  frontier::FrontierEngine engine_;
  std::unique_ptr<slam::MapBuilder> builder_;
  explore::GoalManager goals_;
  geometry::Rigid2d world_from_map_;
  // The latest scan's returns (robot frame), for the collision guard.
  std::vector<Eigen::Vector2d> latest_returns_;
  // Where local SLAM (odometry-extrapolated) had the robot at the latest
  // scan, and that scan's returns moved to the current pose
  // (CollisionGuardOptions::predict_motion).
  geometry::Rigid2d latest_scan_local_pose_;
  std::vector<Eigen::Vector2d> guard_returns_;
  // The recent scans' returns near the robot (local SLAM frame), for backing up.
  explore::ScanMemory recent_returns_;
  // The recent scans' returns within the lidar's range, for the scan check
  // (GoalManagerOptions::scan_check_memory_s).
  explore::ScanMemory scan_check_returns_;
  // SLAM's node positions (global), refreshed with the fused map.
  std::vector<Eigen::Vector2d> driven_;

  // Pose estimate: global-from-local of the newest node, the newest matched
  // local pose and the odometry at its scan, and the newest odometry.
  geometry::Rigid2d global_from_local_;
  geometry::Rigid2d last_local_;
  geometry::Rigid2d newest_node_local_;
  geometry::Rigid2d odometry_at_last_local_;
  geometry::Rigid2d latest_odometry_;
  int accepted_scans_ = 0;

  bool slam_changed_ = false;
  double last_map_update_s_ = -1e300;
  // Adds again only the submaps that changed since the previous fusion.
  grid::IncrementalSubmapFusion fusion_;
  grid::OccupancyMap fused_map_;
  std::vector<Eigen::Vector2d> frontier_;
  std::vector<explore::SubmapPose> submap_poses_;

  ScanRecorder scan_recorder_;
  OdometryRecorder odometry_recorder_;
  ExplorationResult result_;
  // For each of result_.goals, its record in the goal manager's log.
  std::vector<size_t> goal_log_index_;
  MapProgress map_progress_;
  double last_resort_s_ = -1e300;

  // The coverage measurement in flight. Declared last: destroyed (joined)
  // first, while the ground truth it reads still exists.
  struct PendingCoverage {
    double sim_time_s = 0.0;
    size_t first_sample = 0;  // coverage samples from here on show it
    std::future<double> mapped_free_m2;
  };
  std::optional<PendingCoverage> pending_coverage_;
};

}  // namespace scout::exploration

#endif  // SCOUT_EXPLORATION_EXPLORATION_LOOP_H_
