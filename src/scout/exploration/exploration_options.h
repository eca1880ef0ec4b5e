#ifndef SCOUT_EXPLORATION_EXPLORATION_OPTIONS_H_
#define SCOUT_EXPLORATION_EXPLORATION_OPTIONS_H_

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "scout/explore/goal_manager.h"
#include "scout/explore/goal_policies.h"
#include "scout/explore/path_follower.h"
#include "scout/explore/path_planner.h"
#include "scout/explore/planning_map.h"
#include "scout/frontier/frontier_options.h"
#include "scout/sim/simulated_robot.h"
#include "scout/slam/map_builder.h"

namespace scout::exploration {

// The "explore" section of the options file: the closed loop and the goal
// side of exploration (the robot, SLAM and frontier have their own sections).
struct ExploreOptions {
  // Simulation and control step. 0.05 s divides the 10 Hz scan and 50 Hz
  // odometry periods, so sensor stamps stay exact multiples of it.
  double dt_s = 0.05;
  // A run ends "max_sim_time" after this much simulated time ...
  double max_sim_time_s = 3600.0;
  // ... or "no_progress" when the robot's own map has not gained
  // min_map_gain_m2 of known free area for this long (a robot that cannot
  // finish must still stop by itself). Its own map, not the true coverage: a
  // robot whose map bent (museum seed 4: heading 20 degrees off in its far
  // halls) still explores, but what it maps there no longer lines up with the
  // true world, so true coverage stalled and ended such runs at 25 % coverage.
  double no_progress_timeout_s = 300.0;
  double min_map_gain_m2 = 1.0;
  // Finished counts as "complete" when at most this much frontier (metres:
  // points times the cell size) that a plan reaches is left; more means the
  // goal policy gave up on reachable frontier. 0.5 m is the smallest frontier
  // explore_lite pursues (min_frontier_size).
  double complete_max_reachable_frontier_m = 0.5;
  // The fused global map is rebuilt only when SLAM changed it, and at most
  // this often (fusing and re-inflating the whole map is the loop's dearest
  // step; the robot covers 0.5 m per second at most).
  double map_update_interval_s = 1.0;
  // Coverage is measured (and a coverage.csv row recorded) this often.
  double coverage_interval_s = 2.0;
  // Before exploring, the robot turns on the spot by this angle (radians): a
  // 180 degree lidar sees nothing behind the start, where the frontier may
  // then be empty, and SLAM gets a few scans of its surroundings. 0: none.
  double initial_turn_rad = 6.283185307179586;
  // The frontier update strategy that feeds the goals (exact, direct, bfs,
  // dfd, full) and the goal policy (scout, nearest, explore-lite,
  // meanshift-centres).
  std::string strategy = "exact";
  std::string goal_policy = "scout";
  // Also run "full" and score the strategy against it every round (costly).
  bool evaluate_frontier = false;
  // Run global SLAM in the loop's thread: the run is then a deterministic
  // function of world, options and seed. Overrides slam.pose_graph.synchronous.
  bool synchronous_slam = true;
  // With synchronous_slam: a pose-graph solve runs on a second thread while
  // the loop adds this many more nodes, and its result is applied before the
  // next (slam.pose_graph.synchronous_solve_delay_nodes; still deterministic).
  // 0 applies it at once.
  int solve_delay_nodes = 10;

  // Local SLAM settings that replace slam.local's for the simulated robot.
  // slam.local is tuned for recorded logs with poor odometry (fr079: online
  // correlative matching, weak priors). The simulated wheel odometry is
  // good, and correlative matching with weak priors then lets the pose slide
  // along featureless corridors (simulated office, perfect odometry: 3.7 m
  // behind after 8 s at 0.5 m/s). Without it, the priors pull toward the
  // odometry prediction. Cartographer's 10 / 40 let the heading follow the
  // odometry's drift (office seed 1, 300 s without loop closures: ATE 0.78 m,
  // 5 degrees off after 120 s); 5 / 1 gave 0.107, 0.065, 0.053, 0.076 m on
  // seeds 1-4 (2 / 2: 0.158, 0.046, 0.020, 0.067; 10 / 2: 0.25 on seed 1).
  // Rotation 10, not 1: in the museum's halls a scan of 20-60 returns that
  // sees a thin wall from its far side turned the pose 3-6 degrees per scan
  // (17 degrees in 0.3 s at one door). Local SLAM alone on the recorded truth
  // of museum seeds 4, 1, 5: most heading error 30, 21, 26 -> 8, 18, 12
  // degrees, steps over 1 degree between scans 47, 58, 44 -> 0, 1, 0; on
  // willow-garage seed 4 and mit-building-31 seed 5 5.9 and 7.8 -> 2.4 and
  // 5.7 degrees; office seed 1 2.3 -> 4.2 (loop closures keep its ATE).
  struct LocalSlam {
    bool use_online_correlative_scan_matching = false;
    double translation_weight = 5.0;
    double rotation_weight = 10.0;
    // slam.local's likelihood field (0 = the probabilities, as the
    // explorer's evaluation was made): with it, at 5 cm, office seed 3's
    // map broke (ATE 1.64 m, coverage 0.83) and seed 4 came out at 0.068 m
    // against 0.078 m; at 6 cm, 0.115 and 0.152 m against 0.074 and 0.078 m.
    double likelihood_field_sigma_m = 0.0;
  };
  LocalSlam local_slam;
  // Replaces frontier.inflation_radius_m (the paper's 0.40 m, which replay
  // and frontier-bench keep) for the frontier detector's reachability search.
  // Walls in the SLAM map stand up to a cell proud of the true ones, and the
  // fused map narrows doors further as scans of their posts add up, so a
  // 0.85 m door measures about 0.75 m and 0.40 m seals it: willow-garage
  // (seed 1) ended "complete" at coverage 0.70-0.74 with the rooms behind
  // such doors seen only through them (its true map has 1033 m² reachable
  // with 0.40 m of clearance, 687 m² with 0.45 m). Robot radius +
  // traversability.narrow_margin_m (0.25 m) is the clearance the planner's
  // narrow passages keep, and traversability.driven_width_m lets the robot
  // leave every room it entered. Measured on seed 1 (office / willow-garage):
  // 0.40 -> coverage 0.993 / 0.701, 0.35 -> 0.992 / 0.748, 0.30 -> 1.000 /
  // 0.950. (Without the driven cells, 0.30 stranded the robot in a willow
  // room: 0.50.) With the narrow margin at 0.05 m, 0.25 (2026-12-02, seeds
  // 1-5): willow-garage 0.973-0.981. It must be at least robot radius +
  // narrow margin.
  double frontier_inflation_radius_m = 0.25;
  // Optional exploration area: a polygon of at least three vertices in the
  // world frame (metres), which must contain the start. Frontier points
  // outside it are never goals (the loop hands it to the goal manager in the
  // map frame; goals.boundary is replaced), and coverage counts only the
  // reachable free space inside it; the robot may still drive outside it on
  // the way. Empty: no limit.
  std::vector<Eigen::Vector2d> boundary;
  explore::GoalManagerOptions goals;
  // robot_radius_m is taken from the robot section (robot.radius_m).
  explore::TraversabilityOptions traversability;
  explore::PathPlannerOptions planner;
  explore::PathFollowerOptions follower;
  explore::GoalPolicyOptions policy;
};

// Everything one exploration run needs.
struct ExplorationOptions {
  ExploreOptions explore;
  sim::SimulatedRobotOptions robot;
  slam::SlamOptions slam;
  frontier::FrontierOptions frontier;
  // Overrides the world's start position (world frame, metres).
  std::optional<Eigen::Vector2d> start;
};

// Throws InputError naming the key ("explore.dt_s") of a bad or contradictory
// option: out-of-range values, an unknown strategy or goal policy, a frontier
// inflation smaller than the clearance the planner keeps in narrow passages
// (frontier points no plan could reach), follower speeds above the robot's
// limits.
void CheckExplorationOptions(const ExplorationOptions& options);

// Throws InputError naming explore.boundary unless it is empty or has at
// least three finite vertices (part of CheckExplorationOptions).
void CheckExplorationBoundary(const std::vector<Eigen::Vector2d>& boundary);

// Throws InputError naming the key unless the simulator can keep the robot's
// sensor rates at this step: at most one scan and one odometry sample per
// step (part of CheckExplorationOptions).
void CheckSensorRatesAtStep(const ExploreOptions& explore, const sim::SimulatedRobotOptions& robot);

// Returns options.slam with explore.local_slam applied: what the loop runs.
slam::SlamOptions EffectiveSlamOptions(const ExplorationOptions& options);

// Returns options.frontier with explore.frontier_inflation_radius_m applied.
frontier::FrontierOptions EffectiveFrontierOptions(const ExplorationOptions& options);

// Returns the traversability the goal manager plans with: the explore
// section's, with the robot's radius.
explore::TraversabilityOptions PlanningTraversability(const ExplorationOptions& options);

}  // namespace scout::exploration

#endif  // SCOUT_EXPLORATION_EXPLORATION_OPTIONS_H_
