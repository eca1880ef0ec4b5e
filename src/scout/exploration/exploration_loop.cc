#include "scout/exploration/exploration_loop.h"

#include <algorithm>
#include <future>
#include <limits>
#include <optional>
#include <utility>

#include "scout/explore/scan_contradiction.h"
#include "scout/frontier/stopwatch.h"

namespace scout::exploration {
namespace {

// Applies the loop's overrides before anything is built from the options.
ExplorationOptions Prepared(const ExplorationOptions& options) {
  CheckExplorationOptions(options);
  ExplorationOptions o = options;
  o.slam = EffectiveSlamOptions(options);
  o.frontier = EffectiveFrontierOptions(options);
  return o;
}

sim::World WithStart(const sim::World& world, const std::optional<Eigen::Vector2d>& start) {
  sim::World w = world;
  if (start) w.start = *start;
  return w;
}

// The goal manager works in the map frame, which local SLAM starts at the
// start pose: explore.boundary (world frame) is moved into it.
explore::GoalManagerOptions GoalOptionsInMapFrame(const ExplorationOptions& options,
                                                  const sim::World& world) {
  explore::GoalManagerOptions goals = options.explore.goals;
  if (options.explore.boundary.empty()) return goals;
  const geometry::Rigid2d map_from_world =
      geometry::Rigid2d(world.start, options.robot.start_heading_rad).inverse();
  goals.boundary.clear();
  for (const Eigen::Vector2d& v : options.explore.boundary) {
    goals.boundary.push_back(map_from_world * v);
  }
  return goals;
}

// How far from the robot the scan memory keeps returns: at least 1 m, so a
// wall seen on the way in is kept from a little way off, and at least what
// backing up can reach within the guard's horizon plus the disc, its
// clearance and a spare (0.48 m by default: 0.15 m/s for 1 s, 0.2 + 0.03 m,
// 0.1 m), so a faster back-up speed widens it.
constexpr double kMinRecentReturnsRadiusM = 1.0;
// The scan check's remembered returns are thinned to one per cell of this
// side, well below the check radius (0.15 m), so a wall keeps its returns.
constexpr double kScanCheckThinningM = 0.02;
constexpr double kRecentReturnsSpareM = 0.1;
double RecentReturnsRadiusM(const ExplorationOptions& o) {
  const explore::GoalManagerOptions& g = o.explore.goals;
  return std::max(kMinRecentReturnsRadiusM, g.back_up_speed_mps * g.guard.horizon_s +
                                                o.robot.robot.radius_m + g.guard.clearance_m +
                                                kRecentReturnsSpareM);
}

std::vector<std::string> EngineStrategies(const ExploreOptions& e) { return {e.strategy}; }

}  // namespace

std::string_view ToString(Termination termination) {
  switch (termination) {
    case Termination::kComplete:
      return "complete";
    case Termination::kMaxSimTime:
      return "max_sim_time";
    case Termination::kNoProgress:
      return "no_progress";
    case Termination::kInterrupted:
      return "interrupted";
  }
  return "unknown";
}

ExplorationLoop::ExplorationLoop(const sim::World& world, const ExplorationOptions& options,
                                 uint64_t seed)
    : options_(Prepared(options)),
      world_(WithStart(world, options.start)),
      truth_(world_.map, world_.name, world_.start, PlanningTraversability(options_),
             options_.robot.robot.radius_m, options_.explore.boundary),
      robot_(world_, options_.robot, seed),
      engine_(options_.frontier, EngineStrategies(options_.explore),
              options_.explore.evaluate_frontier),
      goals_(GoalOptionsInMapFrame(options_, world_), PlanningTraversability(options_),
             options_.explore.planner, options_.explore.follower,
             explore::MakeGoalPolicy(options_.explore.goal_policy, options_.explore.policy)),
      world_from_map_(robot_.true_pose()),
      recent_returns_(options_.explore.goals.guard.memory_s, RecentReturnsRadiusM(options_)),
      scan_check_returns_(options_.explore.goals.scan_check_memory_s,
                          options_.robot.lidar.range_max_m),
      fusion_(options_.slam.local.submaps.resolution_m),
      map_progress_(options_.explore.min_map_gain_m2) {
  // Local SLAM's frame starts at the first scan's pose, which is the start.
  builder_ = std::make_unique<slam::MapBuilder>(options_.slam, [this](events::SubmapEvent event) {
    const frontier::Stopwatch watch;
    engine_.Apply(event);
    result_.timings.frontier_s += watch.ElapsedUs() * 1e-6;
    slam_changed_ = true;
  });
  latest_odometry_ = robot_.OdometryReading().pose;
  odometry_at_last_local_ = latest_odometry_;
  result_.time_to_coverage_s.assign(std::size(kCoverageThresholds), std::nullopt);
}

void ExplorationLoop::FeedSensors() {
  const frontier::Stopwatch watch;
  const double frontier_before_s = result_.timings.frontier_s;
  FeedSensorsUntimed();
  result_.timings.slam_s +=
      watch.ElapsedUs() * 1e-6 - (result_.timings.frontier_s - frontier_before_s);
}

void ExplorationLoop::FeedSensorsUntimed() {
  if (std::optional<sensor::Odometry> odometry = robot_.MaybeOdometry()) {
    if (odometry_recorder_) odometry_recorder_(*odometry);
    builder_->AddOdometry(*odometry);
    latest_odometry_ = odometry->pose;
  }
  std::optional<sensor::LaserScan> scan = robot_.MaybeScan();
  if (!scan) return;
  // The lidar sits at the robot's centre: its returns are the guard's view.
  latest_returns_ = sensor::ToRangeData(*scan, options_.slam.local.range_filter).returns;
  result_.truth.push_back({scan->time_s, robot_.true_pose()});
  if (scan_recorder_) scan_recorder_(*scan, robot_.true_pose(), latest_odometry_);
  const bool inserted = builder_->AddScan(*scan);
  builder_->DrainEvents();
  const slam::LocalTrajectoryBuilder& local = builder_->local_trajectory_builder();
  const slam::LocalTrajectoryBuilder::Statistics& stats = local.statistics();
  // A scan that local SLAM accepted (matched or the very first) moved last_pose.
  const int accepted = stats.num_scans - stats.num_empty_scans - stats.num_out_of_order_scans;
  if (accepted != accepted_scans_) {
    accepted_scans_ = accepted;
    last_local_ = local.last_pose();
    odometry_at_last_local_ = latest_odometry_;
  }
  latest_scan_local_pose_ = LocalPose();
  recent_returns_.Add(scan->time_s, latest_scan_local_pose_, latest_returns_);
  scan_check_returns_.Add(scan->time_s, latest_scan_local_pose_, latest_returns_);
  if (inserted || slam_changed_) {
    // The newest node ties the local frame to the global one; optimisations
    // move it, so it is re-read after every insertion or event (alone: a
    // copy of the whole trajectory per scan grew with the square of a run).
    const std::optional<slam::TimedPose> newest = builder_->GetNewestNode();
    if (newest && inserted) {
      global_from_local_ = newest->pose * last_local_.inverse();
      newest_node_local_ = last_local_;
    } else if (newest) {
      global_from_local_ = newest->pose * newest_node_local_.inverse();
    }
  }
}

geometry::Rigid2d ExplorationLoop::EstimatedPose() const {
  // Multiplied in this order as before LocalPose() existed: runs stay the same bit for bit.
  return global_from_local_ * last_local_ * (odometry_at_last_local_.inverse() * latest_odometry_);
}

geometry::Rigid2d ExplorationLoop::LocalPose() const {
  return last_local_ * (odometry_at_last_local_.inverse() * latest_odometry_);
}

bool ExplorationLoop::MaybeUpdateMap(bool force) {
  const double t = robot_.sim_time_s();
  if (!force &&
      (!slam_changed_ || t - last_map_update_s_ < options_.explore.map_update_interval_s)) {
    return false;
  }
  const frontier::Stopwatch watch;
  slam_changed_ = false;
  last_map_update_s_ = t;
  const std::vector<slam::SubmapState> submaps = builder_->GetSubmaps();
  std::vector<grid::FusionInput> inputs;
  submap_poses_.clear();
  for (size_t i = 0; i < submaps.size(); ++i) {
    const int id = static_cast<int>(i);
    inputs.push_back({id, submaps[i].grid, submaps[i].global_pose, submaps[i].finished});
    submap_poses_.push_back({id, submaps[i].global_pose});
  }
  fused_map_ = fusion_.Update(inputs);
  const std::vector<slam::TimedPose> nodes = builder_->GetTrajectory();
  driven_.clear();
  for (const slam::TimedPose& node : nodes) driven_.push_back(node.pose.translation());
  // Grid changes are deferred by the engine (FrontierOptions::
  // defer_grid_changes); apply them now that the frontier is needed.
  engine_.Flush();
  frontier_ = engine_.GlobalFrontier(options_.explore.strategy);
  MeasureCoverage(nodes);
  result_.timings.map_fusion_s += watch.ElapsedUs() * 1e-6;
  return true;
}

// Nodes are scans, and the truth holds the robot's pose at every scan, in time
// order.
const slam::TimedPose* ExplorationLoop::TruthAtScan(double time_s) const {
  const auto it =
      std::lower_bound(result_.truth.begin(), result_.truth.end(), time_s,
                       [](const slam::TimedPose& truth, double t) { return truth.time_s < t; });
  return it != result_.truth.end() && it->time_s == time_s ? &*it : nullptr;
}

// The map is placed in the world as the ATE places the trajectory: by the
// rigid fit of the SLAM nodes to the robot's true poses at their scans. The
// start pose alone (world_from_map_) charged the map's frame for how the
// optimiser turned the whole graph: on mit-building-31 seeds 1-5 the fitted
// map lay 0.4-2.7 degrees off the start alignment, and the final coverage
// was 0.941-0.998 against it but 0.997-1.000 fitted. Until the nodes spread
// over a metre (the turn on the spot) the rotation is undetermined: the start.
geometry::Rigid2d ExplorationLoop::CoverageAlignment(
    const std::vector<slam::TimedPose>& nodes) const {
  std::vector<Eigen::Vector2d> estimate;
  std::vector<Eigen::Vector2d> truth;
  for (const slam::TimedPose& node : nodes) {
    if (const slam::TimedPose* t = TruthAtScan(node.time_s)) {
      estimate.push_back(node.pose.translation());
      truth.push_back(t->pose.translation());
    }
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : estimate) mean += p;
  if (!estimate.empty()) mean /= static_cast<double>(estimate.size());
  double spread_m2 = 0.0;
  for (const Eigen::Vector2d& p : estimate) spread_m2 += (p - mean).squaredNorm();
  constexpr double kMinSpread_m = 1.0;
  if (estimate.empty() || spread_m2 < kMinSpread_m * kMinSpread_m * estimate.size()) {
    return world_from_map_;
  }
  return geometry::FitRigid2d(estimate, truth);
}

void ExplorationLoop::MeasureCoverage(const std::vector<slam::TimedPose>& nodes) {
  const double t = robot_.sim_time_s();
  CompleteCoverage();
  // Comparing the map with the truth cell by cell took a sixth of the museum's
  // wall time (every reachable cell, every map update); the copy of the map
  // it works on costs a few milliseconds.
  pending_coverage_.emplace();
  pending_coverage_->sim_time_s = t;
  pending_coverage_->first_sample = result_.coverage_samples.size();
  pending_coverage_->mapped_free_m2 = std::async(
      std::launch::async, [this, map = fused_map_, alignment = CoverageAlignment(nodes)] {
        return truth_.MappedFreeM2(map, alignment);
      });
  const int64_t free_cells =
      std::count(fused_map_.cells.begin(), fused_map_.cells.end(), grid::CellState::kFree);
  const double cell_m = fused_map_.limits.resolution();
  result_.map_free_m2 = static_cast<double>(free_cells) * cell_m * cell_m;
  map_progress_.Measure(t, result_.map_free_m2, builder_->GetStats().num_optimizations);
}

std::vector<uint8_t> ExplorationLoop::CoverageMask() const {
  return truth_.CoverageMask(fused_map_, CoverageAlignment(builder_->GetTrajectory()));
}

void ExplorationLoop::CompleteCoverage() {
  if (!pending_coverage_) return;
  PendingCoverage pending = std::move(*pending_coverage_);
  pending_coverage_.reset();
  result_.reachable_free_m2 = truth_.reachable_free_m2();
  result_.mapped_free_m2 = pending.mapped_free_m2.get();
  result_.coverage = result_.mapped_free_m2 / result_.reachable_free_m2;
  for (size_t i = 0; i < std::size(kCoverageThresholds); ++i) {
    if (!result_.time_to_coverage_s[i] && result_.coverage >= kCoverageThresholds[i]) {
      result_.time_to_coverage_s[i] = pending.sim_time_s;
    }
  }
  // Samples are taken after the map update that started the measurement, so
  // the ones since then show it, as if it had been measured at once.
  for (size_t i = pending.first_sample; i < result_.coverage_samples.size(); ++i) {
    result_.coverage_samples[i].coverage = result_.coverage;
  }
}

// A point of the map lies in the true world where the scans that mapped it
// put it: among the submaps whose grid knows the cell under it, the node
// inserted nearest to it, at that node's true pose, with the point where it
// lay relative to the node in the submap's frame. Submaps never change
// inside, so this holds whatever the optimiser did to the graph since.
// Two simpler rules each misplaced reachable goals (counted unreachable):
// relative to the robot's current pose, the heading error grows with the
// distance (office seed 1: a target 30 m away put against a desk's corner);
// relative to the SLAM node nearest in the global map, that node may belong
// to submaps a loop closure has not yet joined to the point's (mit-building-31
// seeds 2, 4 and 5: targets 2-4 m from the robot put a metre beyond the outer
// wall). Without such a node (no submap knows the point) the robot's pose is
// the reference. SLAM's state is fetched once for all the points.
std::vector<Eigen::Vector2d> ExplorationLoop::MapPointsInWorld(
    const std::vector<Eigen::Vector2d>& points_map) const {
  const std::vector<slam::SubmapState> submaps = builder_->GetSubmaps();
  const std::vector<slam::Constraint> constraints = builder_->GetConstraints();
  const std::vector<slam::TimedPose> nodes = builder_->GetTrajectory();
  const geometry::Rigid2d world_from_estimate = robot_.true_pose() * EstimatedPose().inverse();
  std::vector<Eigen::Vector2d> points_world;
  for (const Eigen::Vector2d& point_map : points_map) {
    std::vector<std::optional<Eigen::Vector2d>> point_in_submap(submaps.size());
    for (size_t i = 0; i < submaps.size(); ++i) {
      const Eigen::Vector2d q = submaps[i].global_pose.inverse() * point_map;
      const grid::ProbabilityGrid& grid = *submaps[i].grid;
      const grid::CellIndex cell = grid.limits().CellContaining(q);
      if (grid.limits().Contains(cell) && grid.IsKnown(cell)) point_in_submap[i] = q;
    }
    const slam::Constraint* nearest = nullptr;
    double best_m = std::numeric_limits<double>::infinity();
    for (const slam::Constraint& c : constraints) {
      if (c.kind != slam::ConstraintKind::kIntraSubmap) continue;
      const std::optional<Eigen::Vector2d>& q = point_in_submap.at(c.submap_id);
      if (!q) continue;
      const double d = (c.relative_pose.translation() - *q).norm();
      if (d < best_m) best_m = d, nearest = &c;
    }
    const slam::TimedPose* truth =
        nearest != nullptr ? TruthAtScan(nodes.at(nearest->node_id).time_s) : nullptr;
    points_world.push_back(truth != nullptr ? truth->pose * (nearest->relative_pose.inverse() *
                                                             *point_in_submap[nearest->submap_id])
                                            : world_from_estimate * point_map);
  }
  return points_world;
}

void ExplorationLoop::RecordIssuedGoal(const Eigen::Vector2d& goal_map,
                                       const Eigen::Vector2d& target_map,
                                       const std::vector<Eigen::Vector2d>& path_map) {
  IssuedGoal g;
  g.sim_time_s = robot_.sim_time_s();
  const std::vector<Eigen::Vector2d> world = MapPointsInWorld({goal_map, target_map});
  g.goal_world = world[0];
  g.target_world = world[1];
  g.goal_map = goal_map;
  g.target_map = target_map;
  g.robot_world = robot_.true_pose().translation();
  g.robot_map = EstimatedPose().translation();
  // Reached means within the follower's tolerance, so that is the slack.
  const double tolerance_m = options_.explore.follower.goal_tolerance_m;
  g.reachable_in_truth = truth_.DiscCanReach(g.robot_world, g.target_world, tolerance_m);
  g.point_reachable_in_truth = truth_.DiscCanReach(g.robot_world, g.goal_world, tolerance_m);
  if (!g.reachable_in_truth && result_.unreachable_goals < kMaxUnreachableSnapshots) {
    g.map_then = std::make_shared<const grid::OccupancyMap>(fused_map_);
    g.path_map = path_map;
    const geometry::Rigid2d map_from_scan =
        EstimatedPose() * LocalPose().inverse() * latest_scan_local_pose_;
    const geometry::Rigid2d world_from_scan = result_.truth.back().pose;
    for (const Eigen::Vector2d& p : latest_returns_) {
      g.scan_map.push_back(map_from_scan * p);
      g.scan_world.push_back(world_from_scan * p);
    }
  }
  result_.unreachable_goals += !g.reachable_in_truth;
  result_.unreachable_points += !g.point_reachable_in_truth;
  result_.goals.push_back(std::move(g));
}

std::optional<Termination> ExplorationLoop::CheckTermination(
    const explore::ExploreStatus& status) const {
  const double t = robot_.sim_time_s();
  if (status.state == explore::ExploreState::kFinished) {
    // The goal manager finishes when no navigation point is left to try
    // (ALGORITHMS section 6). Frontier points no plan on the fused map reaches
    // may remain (reported as frontier_left); more reachable frontier than
    // complete_max_reachable_frontier_m means the policy gave up on it (e.g.
    // its goals failed): not complete. Frontier near a goal the robot
    // reached does not count: it went there and the frontier stayed.
    const double reachable_m =
        status.reachable_frontier_left * options_.slam.local.submaps.resolution_m;
    return reachable_m > options_.explore.complete_max_reachable_frontier_m
               ? Termination::kNoProgress
               : Termination::kComplete;
  }
  if (t >= options_.explore.max_sim_time_s) return Termination::kMaxSimTime;
  if (t - NoProgressSince() >= options_.explore.no_progress_timeout_s) {
    return Termination::kNoProgress;
  }
  return std::nullopt;
}

double ExplorationLoop::NoProgressSince() const {
  return std::max(map_progress_.last_progress_s(), last_resort_s_);
}

std::optional<Eigen::Vector2d> ExplorationLoop::ConfinedAt(double sim_time_s) const {
  const explore::GoalManagerOptions& g = options_.explore.goals;
  if (g.last_resort_retrace_m <= 0.0) return std::nullopt;
  const std::vector<slam::TimedPose> nodes = builder_->GetTrajectory();
  const double window_start_s = sim_time_s - options_.explore.no_progress_timeout_s;
  const double r2 = g.last_resort_confined_radius_m * g.last_resort_confined_radius_m;
  // Newest first: each node of the window as the centre of a stretch of
  // nodes before it within the radius. Hundreds of nodes, once per timeout.
  for (size_t j = nodes.size(); j-- > 0 && nodes[j].time_s >= window_start_s;) {
    const Eigen::Vector2d centre = nodes[j].pose.translation();
    size_t i = j;
    while (i > 0 && nodes[i - 1].time_s >= window_start_s &&
           (nodes[i - 1].pose.translation() - centre).squaredNorm() <= r2) {
      --i;
    }
    if (nodes[j].time_s - nodes[i].time_s >= g.last_resort_confined_s) return centre;
  }
  return std::nullopt;
}

ExplorationProgress ExplorationLoop::MakeProgress(double sim_time_s,
                                                  const explore::ExploreStatus& status) const {
  ExplorationProgress p;
  p.sim_time_s = sim_time_s;
  p.coverage = result_.coverage;
  p.state = goals_.state();
  p.counters = goals_.counters();
  p.path_length_m = robot_.path_length_m();
  p.collisions = robot_.collisions();
  p.estimated_pose = world_from_map_ * EstimatedPose();
  p.true_pose = robot_.true_pose();
  if (status.goal) p.goal = world_from_map_ * *status.goal;
  p.frontier_points = static_cast<int>(frontier_.size());
  p.navigation_points = static_cast<int>(status.candidates.size());
  for (const Eigen::Vector2d& b : status.blacklisted) {
    p.blacklisted_goals.push_back(world_from_map_ * b);
  }
  return p;
}

ExplorationResult ExplorationLoop::Run(const ProgressCallback& progress, double progress_interval_s,
                                       const std::function<bool()>& stop_requested) {
  const ExploreOptions& e = options_.explore;
  FeedSensors();  // the readings of t = 0
  double next_sample_s = 0.0;
  double next_progress_s = 0.0;
  double turned_rad = 0.0;
  double last_heading_rad = EstimatedPose().theta();
  bool started = false;
  explore::ExploreStatus final_status;
  while (true) {
    const double t = robot_.sim_time_s();
    bool changed = MaybeUpdateMap(/*force=*/fused_map_.limits.num_cells() == 0);
    explore::ExploreStatus status;
    const double heading_rad = EstimatedPose().theta();
    turned_rad += std::abs(geometry::NormalizeAngle(heading_rad - last_heading_rad));
    last_heading_rad = heading_rad;
    if (!started && turned_rad < e.initial_turn_rad) {
      status.state = explore::ExploreState::kPlanning;
      status.command.angular_radps = e.follower.max_angular_speed_radps;
    } else if (!started) {
      // The goals see the map of the whole turn, so refresh it now.
      started = true;
      goals_.Start();
      changed = MaybeUpdateMap(/*force=*/true);
    }
    if (started && fused_map_.limits.num_cells() > 0) {
      const int issued_before = goals_.counters().goals_issued;
      explore::ExploreInput in;
      in.time_s = t;
      in.robot_pose = EstimatedPose();
      in.map = &fused_map_;
      in.frontier = &frontier_;
      in.submaps = submap_poses_;
      in.map_changed = changed;
      in.obstacles = &latest_returns_;
      if (e.goals.guard.predict_motion) {
        // The scan is up to one scan period old: move its returns to where
        // odometry says the robot is now, and tell the guard how it moves.
        const geometry::Rigid2d now_from_scan = LocalPose().inverse() * latest_scan_local_pose_;
        guard_returns_.clear();
        for (const Eigen::Vector2d& p : latest_returns_)
          guard_returns_.push_back(now_from_scan * p);
        in.obstacles = &guard_returns_;
        const sim::DiffDriveRobot& base = robot_.robot();
        in.base = explore::BaseMotion{base.linear_velocity_mps(), base.angular_velocity_radps(),
                                      base.options().max_linear_accel_mps2,
                                      base.options().max_angular_accel_radps2, e.dt_s};
      }
      in.recent_returns = [this] { return recent_returns_.Around(LocalPose()); };
      if (scan_check_returns_.num_scans() > 0) {
        in.scan_check_returns = [this] {
          return explore::ThinToCells(scan_check_returns_.Around(LocalPose()), kScanCheckThinningM);
        };
      }
      in.driven = &driven_;
      const frontier::Stopwatch watch;
      status = goals_.Update(in);
      // About to end no_progress: a robot that stood confined in that time
      // first tries its last resort: driving back the way it came if it still
      // stands there, going on with what it does if it got out by itself.
      if (t - NoProgressSince() >= e.no_progress_timeout_s) {
        if (const std::optional<Eigen::Vector2d> spot = ConfinedAt(t)) {
          const bool still_there =
              (in.robot_pose.translation() - *spot).norm() <= e.goals.last_resort_confined_radius_m;
          if (goals_.LastResort(in, /*drive_back=*/still_there)) last_resort_s_ = t;
        }
      }
      result_.timings.goals_s += watch.ElapsedUs() * 1e-6;
      if (goals_.counters().goals_issued > issued_before) {
        // A goal ended in the update that issued it (the robot already stood
        // at its stand-off point) is still recorded, at the goal itself.
        const explore::GoalRecord& issued = goals_.goal_log().back();
        const bool current = status.goal && status.target;
        RecordIssuedGoal(current ? *status.goal : issued.goal,
                         current ? *status.target : issued.goal,
                         current ? status.path : std::vector<Eigen::Vector2d>{});
        goal_log_index_.push_back(goals_.goal_log().size() - 1);
      }
    }
    if (t >= next_sample_s) {
      result_.coverage_samples.push_back(
          {t, robot_.path_length_m(), result_.coverage, result_.map_free_m2});
      next_sample_s += e.coverage_interval_s;
    }
    if (progress && t >= next_progress_s) {
      progress(MakeProgress(t, status));
      next_progress_s += progress_interval_s;
    }
    std::optional<Termination> end = CheckTermination(status);
    if (!end && stop_requested && stop_requested()) end = Termination::kInterrupted;
    if (end) {
      result_.terminated = *end;
      result_.returned_home = status.returned_home;
      result_.frontier_counted = status.state == explore::ExploreState::kFinished;
      result_.frontier_left = status.frontier_left;
      result_.reachable_frontier_left = status.reachable_frontier_left;
      result_.reachable_frontier_left_world =
          MapPointsInWorld(status.reachable_frontier_left_points);
      result_.visited_frontier_left = status.visited_frontier_left;
      result_.last_candidates_map = status.candidates;
      final_status = std::move(status);
      break;
    }
    const frontier::Stopwatch watch;
    const int collisions_before = robot_.collisions();
    robot_.Step(status.command.linear_mps, status.command.angular_radps, e.dt_s);
    result_.timings.simulation_s += watch.ElapsedUs() * 1e-6;
    if (robot_.collisions() > collisions_before) {
      result_.collision_places.push_back({robot_.sim_time_s(), robot_.true_pose().translation()});
    }
    FeedSensors();
  }
  // The final optimisation may still move submaps: measure the map users get.
  builder_->Finish();
  slam_changed_ = true;
  MaybeUpdateMap(/*force=*/true);
  CompleteCoverage();
  const double t = robot_.sim_time_s();
  if (result_.coverage_samples.empty() || result_.coverage_samples.back().sim_time_s < t) {
    result_.coverage_samples.push_back(
        {t, robot_.path_length_m(), result_.coverage, result_.map_free_m2});
  }
  result_.sim_time_s = t;
  result_.path_length_m = robot_.path_length_m();
  result_.collisions = robot_.collisions();
  result_.counters = goals_.counters();
  // The loop recorded each goal when issued; the goal manager's log of it
  // knows how it ended.
  for (size_t i = 0; i < result_.goals.size(); ++i) {
    result_.goals[i].record = goals_.goal_log()[goal_log_index_[i]];
  }
  for (const explore::FailedGoal& g : goals_.failed_goals().goals()) {
    result_.failed_goals.push_back(
        {explore::Resolve(g.where, submap_poses_), g.failures, g.blacklisted});
  }
  if (progress) {
    ExplorationProgress last = MakeProgress(t, final_status);
    last.finished = true;
    progress(last);
  }
  return std::move(result_);
}

}  // namespace scout::exploration
