#include "apps/scout/replay_command.h"

#include <unistd.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>

#include "apps/scout/command_util.h"
#include "apps/scout/interrupt.h"
#include "apps/scout/report_command.h"
#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/common/resource_usage.h"
#include "scout/exploration/exploration_options.h"
#include "scout/explore/map_navigation_points.h"
#include "scout/frontier/frontier_engine.h"
#include "scout/frontier/stopwatch.h"
#include "scout/io/config.h"
#include "scout/io/dataset.h"
#include "scout/io/frontier_report.h"
#include "scout/io/loop_closure_csv.h"
#include "scout/io/map_picture.h"
#include "scout/io/odometry_noise.h"
#include "scout/io/output_directory.h"
#include "scout/io/replay_reference.h"
#include "scout/io/revisit_consistency.h"
#include "scout/io/scan_consistency.h"
#include "scout/io/slam_summary.h"
#include "scout/io/trajectory_association.h"
#include "scout/io/trajectory_metrics.h"
#include "scout/io/tum_trajectory.h"
#include "scout/slam/map_builder.h"

namespace scout::apps {
namespace {

// All of them: the readers list at most ten of each kind and then say how
// many more there were, and a cap over all kinds hid the one that said the
// log ended early behind ten odometry lines.
void PrintWarnings(const io::Dataset& dataset) {
  for (const std::string& warning : dataset.warnings) {
    std::cerr << "scout: warning: " << warning << "\n";
  }
}

// Nominal scan period given to logs whose own times cannot order the scans.
constexpr double kRetimedScanPeriodS = 1.0;

// Some Radish logs (csail, orebro) stamp most scans with the same time (or 0).
// Odometry is matched to scans by time and nodes to reference poses by time,
// so with repeated times the odometry of all but the first such scan is
// dropped (local SLAM then predicts no motion for 0.5 m / 45 degree steps)
// and nodes pair with the wrong reference poses. When most times repeat, the
// scans and their laser-line odometry get synthetic times, one period apart.
// Returns whether the dataset was re-timed.
bool RetimeIfCoarse(io::Dataset* dataset) {
  std::vector<sensor::LaserScan>& scans = dataset->scans;
  size_t repeated = 0;
  for (size_t i = 1; i < scans.size(); ++i) repeated += !(scans[i].time_s > scans[i - 1].time_s);
  if (scans.size() < 2 || 2 * repeated < scans.size()) return false;
  const bool with_odometry = dataset->scan_odometry.size() == scans.size();
  for (size_t i = 0; i < scans.size(); ++i) {
    scans[i].time_s = kRetimedScanPeriodS * static_cast<double>(i);
    if (with_odometry) dataset->scan_odometry[i].time_s = scans[i].time_s;
  }
  // Other timed streams no longer line up with the scans.
  if (!with_odometry) dataset->odometry.clear();
  return true;
}

// Returns the dataset index of every node's scan (nodes are in scan order and
// carry their scan's own timestamp), -1 for none.
std::vector<int> NodeScans(const io::Dataset& dataset, const std::vector<slam::TimedPose>& nodes) {
  std::vector<int> node_scans;
  node_scans.reserve(nodes.size());
  size_t scan = 0;
  for (const slam::TimedPose& node : nodes) {
    while (scan < dataset.scans.size() && dataset.scans[scan].time_s < node.time_s) ++scan;
    const bool found = scan < dataset.scans.size() && dataset.scans[scan].time_s == node.time_s;
    node_scans.push_back(found ? static_cast<int>(scan) : -1);
  }
  return node_scans;
}

// The reference pose of every SLAM node's scan, by node id (none where the
// scan has no reference pose).
std::vector<std::optional<geometry::Rigid2d>> ReferenceByNode(const io::ScanReference& reference,
                                                              const std::vector<int>& node_scans) {
  std::vector<std::optional<geometry::Rigid2d>> by_node(node_scans.size());
  for (size_t i = 0; i < node_scans.size(); ++i) {
    if (node_scans[i] >= 0) by_node[i] = reference.poses[node_scans[i]];
  }
  return by_node;
}

// A reference that does not move (a log whose scan poses are all zero, not
// corrected poses) gives an ATE that measures only the estimate's own extent:
// say so rather than let the figure pass for an accuracy.
void WarnIfReferenceStandsStill(const std::vector<io::PosePair>& pairs,
                                const std::string& reference_file) {
  if (pairs.empty()) return;
  double reference_extent_m = 0.0, estimate_extent_m = 0.0;
  for (const io::PosePair& p : pairs) {
    reference_extent_m = std::max(
        reference_extent_m, (p.reference.translation() - pairs[0].reference.translation()).norm());
    estimate_extent_m = std::max(
        estimate_extent_m, (p.estimate.translation() - pairs[0].estimate.translation()).norm());
  }
  constexpr double kStillM = 0.01;
  constexpr double kMovedM = 1.0;
  if (reference_extent_m < kStillM && estimate_extent_m > kMovedM) {
    std::cerr << "scout: warning: " << reference_file << ": the reference poses matched to the "
              << pairs.size() << " nodes stay within " << kStillM * 100 << " cm of the first while "
              << "the estimate moves " << std::fixed << std::setprecision(1) << estimate_extent_m
              << " m; the ATE and RPE below measure no reference\n";
  }
}

// Reference-free local accuracy (io::MeasureScanConsistency) of the nodes,
// with each node's scan filtered as local SLAM filters it. With a reference,
// measured on the nodes it pairs with, for the estimate and the reference.
nlohmann::json ConsistencySummary(const io::Dataset& dataset,
                                  const std::vector<slam::TimedPose>& nodes,
                                  const std::vector<int>& node_scans,
                                  const io::ScanReference* reference,
                                  const sensor::RangeFilterOptions& range_filter) {
  const io::ScanConsistencyOptions options;
  std::vector<std::vector<Eigen::Vector2d>> points;
  std::vector<geometry::Rigid2d> estimate, reference_poses;
  std::vector<double> times_s;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const int scan = node_scans[i];
    if (scan < 0 || (reference != nullptr && !reference->poses[scan])) continue;
    points.push_back(sensor::ToRangeData(dataset.scans[scan], range_filter).returns);
    estimate.push_back(nodes[i].pose);
    times_s.push_back(nodes[i].time_s);
    if (reference != nullptr) reference_poses.push_back(*reference->poses[scan]);
  }
  const io::ScanConsistency of_estimate = io::MeasureScanConsistency(points, estimate, options);
  nlohmann::json json = {{"previous_scans", options.previous_scans},
                         {"max_distance_m", options.max_distance_m},
                         {"scans", of_estimate.scans},
                         {"estimate_mean_distance_m", of_estimate.mean_distance_m}};
  if (reference != nullptr) {
    json["reference_mean_distance_m"] =
        io::MeasureScanConsistency(points, reference_poses, options).mean_distance_m;
  }
  // Where the run comes back to a place: found by either trajectory, graded
  // for both on the same pairs.
  const io::RevisitOptions revisit;
  std::vector<std::vector<int>> revisits = io::FindRevisits(estimate, times_s, revisit);
  if (reference != nullptr) {
    revisits = io::MergeRevisits(revisits, io::FindRevisits(reference_poses, times_s, revisit));
  }
  nlohmann::json revisits_json = {{"min_separation_s", revisit.min_separation_s},
                                  {"max_pose_distance_m", revisit.max_distance_m},
                                  {"max_turn_deg", revisit.max_turn_deg},
                                  {"max_earlier_scans", revisit.max_earlier_scans}};
  // The same figures for either trajectory, under its prefix.
  const auto grade = [&](const std::vector<geometry::Rigid2d>& poses, const std::string& prefix) {
    const io::RevisitConsistency c =
        io::MeasureRevisitConsistency(points, poses, revisits, options.max_distance_m);
    revisits_json["scans"] = c.scans;
    revisits_json[prefix + "_mean_distance_m"] = c.mean_distance_m;
    revisits_json[prefix + "_paired_fraction"] = c.paired_fraction;
  };
  grade(estimate, "estimate");
  if (reference != nullptr) grade(reference_poses, "reference");
  json["revisits"] = revisits_json;
  return json;
}

nlohmann::json ReferenceSummary(const io::TrajectoryErrors& e, const io::ScanReference& r) {
  return {{"association", r.association},
          {"reference_scans", r.matched},
          {"matched_scans", e.matched},
          {"ate_rmse_m", e.ate_rmse_m},
          {"ate_max_m", e.ate_max_m},
          {"rpe_1s_trans_m", e.rpe_1s_trans_m},
          {"rpe_1s_rot_deg", e.rpe_1s_rot_deg},
          {"rpe_10s_trans_m", e.rpe_10s_trans_m},
          {"rpe_10s_rot_deg", e.rpe_10s_rot_deg},
          {"rpe_1s_trans_mean_m", e.rpe_1s_trans_mean_m},
          {"rpe_1s_rot_mean_deg", e.rpe_1s_rot_mean_deg},
          {"rpe_10s_trans_mean_m", e.rpe_10s_trans_mean_m},
          {"rpe_10s_rot_mean_deg", e.rpe_10s_rot_mean_deg}};
}

}  // namespace

CLI::App* AddReplayCommand(CLI::App& app, ReplayArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Run SLAM on a recorded dataset (CARMEN log or ROS 1 bag, plain or .gz) and every frontier "
      "update strategy in lockstep on its events");
  cmd->add_option("dataset", args->dataset, "the dataset file")->required();
  cmd->add_option("--out", args->out_dir, "output directory")->capture_default_str();
  cmd->add_option("--config", args->config_file, "YAML options file (see config/default.yaml)");
  cmd->add_option("--reference", args->reference,
                  "reference trajectory: a TUM file, or a CARMEN log whose scan poses are the "
                  "reference (paired by identical range readings)");
  cmd->add_option("--strategies", args->strategies, "comma-separated strategies to run")
      ->capture_default_str();
  cmd->add_option(
      "--picture-strategy", args->picture_strategy,
      "strategy whose frontier frontiers.png shows (default: exact if it runs, else the "
      "first of --strategies)");
  cmd->add_option("--scan-topic", args->scan_topic, "bags: LaserScan topic (default: detected)");
  cmd->add_option("--odom-topic", args->odometry_topic, "bags: Odometry topic (default: detected)");
  cmd->add_option("--odom-noise", args->odom_noise,
                  "scale of the wheel-odometry drift injected into the dataset's odometry (0 = "
                  "none, 1 = typical, at most 100)")
      ->capture_default_str()
      ->check(NonNegativeFiniteNumber(100.0));
  cmd->add_option("--seed", args->seed, "seed of the injected odometry noise")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->add_option("--max-scans", args->max_scans, "stop after this many scans (0 = all)")
      ->capture_default_str()
      ->check(NonNegativeInteger(std::numeric_limits<int>::max()));
  cmd->add_flag("--synchronous", args->synchronous,
                "run global SLAM in the calling thread (deterministic; overrides the config)");
  cmd->add_flag("--explore-slam", args->explore_slam,
                "run SLAM with the settings `scout explore` runs it with (explore.local_slam "
                "instead of slam.local's, and its synchronous solves) and the log's ODOM "
                "samples when it has them: for a sensor.log written by `scout explore "
                "--record-log`, whose SLAM it then repeats to the digit");
  cmd->add_flag("--quiet", args->quiet, "print only the final summary");
  return cmd;
}

// Where an explorer would go next from the last pose of the replay: the
// navigation points of the final map (explore.policy.navigation,
// explore.traversability with robot.radius_m, explore.boundary in the map
// frame), as the exploration loop ranks them.
explore::MapNavigationPoints FinalNavigationPoints(const io::ScoutConfig& config,
                                                   const io::GlobalSubmaps& submaps,
                                                   const std::vector<Eigen::Vector2d>& frontier,
                                                   const std::vector<slam::TimedPose>& nodes) {
  std::vector<Eigen::Vector2d> driven;
  driven.reserve(nodes.size());
  for (const slam::TimedPose& n : nodes) driven.push_back(n.pose.translation());
  return explore::NavigationPointsOnMap(
      io::FuseGlobalSubmaps(submaps), frontier, driven.back(), driven,
      exploration::PlanningTraversability(ExplorationOptionsFrom(config)),
      config.explore.policy.navigation, config.explore.boundary);
}

int RunReplay(const ReplayArgs& args) {
  const frontier::Stopwatch wall;
  io::ScoutConfig config = LoadConfigOrDefaults(args.config_file);
  // A recorded exploration replayed with the explorer's SLAM settings, so the
  // replay runs the SLAM the loop ran rather than the one tuned for real logs.
  if (args.explore_slam) {
    config.slam = exploration::EffectiveSlamOptions(ExplorationOptionsFrom(config));
  }
  if (args.synchronous) config.slam.pose_graph.synchronous = true;
  // Validates options and names before any long work or any output.
  const std::vector<std::string> strategies = SplitList(args.strategies, "--strategies");
  frontier::FrontierEngine engine(config.frontier, strategies, /*evaluate=*/true);
  const std::string picture_strategy = PictureStrategy(args.picture_strategy, strategies, engine);
  exploration::CheckExplorationBoundary(config.explore.boundary);

  io::Dataset dataset = io::LoadDataset(args.dataset, {args.scan_topic, args.odometry_topic});
  PrintWarnings(dataset);
  if (args.max_scans > 0 && dataset.scans.size() > static_cast<size_t>(args.max_scans)) {
    dataset.scans.resize(args.max_scans);
    if (!dataset.scan_poses.empty()) dataset.scan_poses.resize(args.max_scans);
    if (!dataset.scan_odometry.empty()) dataset.scan_odometry.resize(args.max_scans);
  }
  // CARMEN logs carry the odometry pose in every laser line, at the scan's own
  // time. That is the odometry local SLAM needs; the ODOM messages of the
  // Radish "-corrected" logs restart from the corrected pose after each scan,
  // so differences between them are not robot motion. A log of `scout explore
  // --record-log` (--explore-slam) holds every odometry sample the loop's SLAM
  // got as ODOM messages: those, so the replay repeats the loop's SLAM.
  if (RetimeIfCoarse(&dataset)) {
    std::cerr << "scout: warning: " << args.dataset << ": most scans repeat the time before; "
              << "replayed " << kRetimedScanPeriodS << " s apart\n";
  }
  std::string odometry_source = dataset.odometry.empty() ? "none" : "odometry messages";
  const bool recorded_samples = args.explore_slam && !dataset.odometry.empty();
  if (!dataset.scan_odometry.empty() && !recorded_samples) {
    dataset.odometry = dataset.scan_odometry;
    odometry_source = "laser lines";
  }
  if (dataset.odometry.empty()) {
    std::cerr << "scout: warning: " << args.dataset
              << ": no odometry; local SLAM predicts poses from scan matching alone\n";
  } else if (args.odom_noise > 0.0) {
    dataset.odometry = io::AddOdometryNoise(dataset.odometry, args.odom_noise, args.seed);
  }
  std::optional<io::ScanReference> reference;
  if (!args.reference.empty()) reference = io::LoadScanReference(dataset, args.reference);
  io::OutputDirectory out(args.out_dir, io::OutputDirectory::Mode::kReplaceRun, "replay",
                          {args.dataset, args.reference, args.config_file});

  const bool terminal = !args.quiet && ::isatty(STDERR_FILENO);
  slam::MapBuilder builder(config.slam,
                           [&engine](events::SubmapEvent event) { engine.Apply(event); });
  const double data_start_s = dataset.scans.front().time_s;
  size_t next_odometry = 0;
  const size_t dataset_scans = dataset.scans.size();
  size_t num_scans = dataset_scans;
  // Ctrl-C (SIGINT) or SIGTERM stops the replay after the scan in hand; the
  // scans so far are mapped and written, as with --max-scans.
  int stop_signal = 0;
  for (size_t i = 0; i < num_scans; ++i) {
    const sensor::LaserScan& scan = dataset.scans[i];
    while (next_odometry < dataset.odometry.size() &&
           dataset.odometry[next_odometry].time_s <= scan.time_s) {
      builder.AddOdometry(dataset.odometry[next_odometry++]);
    }
    if ((stop_signal = PendingSignal()) != 0) {
      // Nothing mapped yet: nothing to write.
      if (i == 0) ThrowIfInterrupted();
      num_scans = i;
      dataset.scans.resize(i);
      if (!dataset.scan_poses.empty()) dataset.scan_poses.resize(i);
      if (!dataset.scan_odometry.empty()) dataset.scan_odometry.resize(i);
      break;
    }
    builder.AddScan(scan);
    const bool report = (i + 1) % 500 == 0 || i + 1 == num_scans;
    if (report && !args.quiet) {
      const double factor = (scan.time_s - data_start_s) / std::max(1e-9, wall.ElapsedUs() * 1e-6);
      std::cerr << (terminal ? "\r" : "") << "replay: " << i + 1 << "/" << num_scans << " scans, "
                << std::fixed << std::setprecision(1) << factor << "x real time"
                << (terminal ? "" : "\n") << std::flush;
    }
  }
  if (terminal) std::cerr << "\n";
  const double data_duration_s = dataset.scans.back().time_s - data_start_s;
  builder.Finish();
  engine.Flush();
  const double wall_time_s = wall.ElapsedUs() * 1e-6;

  const std::vector<slam::TimedPose> nodes = builder.GetTrajectory();
  if (nodes.empty()) {
    if (stop_signal != 0) ThrowIfInterrupted();
    // Every scan was dropped by the range filter (no return and no miss), or
    // had no pose to insert it at: there is nothing to map.
    throw InputError(args.dataset + ": none of the " + std::to_string(num_scans) +
                     " scans could be inserted (expected ranges between the scan's range_min and "
                     "range_max, or readings beyond range_max with odometry to place them)");
  }
  std::vector<io::StampedPose> trajectory;
  trajectory.reserve(nodes.size());
  for (const slam::TimedPose& n : nodes) trajectory.push_back({n.time_s, n.pose});
  io::GlobalSubmaps submaps;
  for (const slam::SubmapState& s : builder.GetSubmaps())
    submaps.push_back({s.global_pose, s.grid});
  const slam::SlamStats stats = builder.GetStats();

  nlohmann::json summary;
  summary["dataset"] = dataset.name;
  summary["dataset_file"] = args.dataset;
  summary["format"] = dataset.format;
  summary["scans"] = num_scans;
  summary["dataset_scans"] = dataset_scans;
  summary["interrupted_by"] = stop_signal != 0 ? nlohmann::json(SignalName(stop_signal)) : nullptr;
  summary["odometry_readings"] = dataset.odometry.size();
  summary["odometry_source"] = odometry_source;
  summary["odom_noise"] = args.odom_noise;
  summary["seed"] = args.seed;
  summary["warnings"] = dataset.warnings.size();
  summary["data_duration_s"] = data_duration_s;
  summary["wall_time_s"] = wall_time_s;
  summary["realtime_factor"] = data_duration_s / std::max(1e-9, wall_time_s);
  summary["peak_rss_mb"] = PeakResidentSetMiB();
  summary["slam"] = io::SlamSummary(stats, config.slam.pose_graph.synchronous);
  summary["slam"]["submap_events"] = stats.num_submap_events;
  summary["slam"]["settings"] = args.explore_slam ? "explore" : "slam";
  {
    const slam::LocalTrajectoryBuilder::Statistics& local =
        builder.local_trajectory_builder().statistics();
    summary["slam"]["angular_edge_matches"] = local.num_angular_edge_matches;
    summary["slam"]["second_searches"] = local.num_second_searches;
    summary["slam"]["second_search_wins"] = local.num_second_search_wins;
    // More than the odd glitch on the window's edge: the odometry's turns are
    // off by more than the search looks (the eight Radish logs with injected
    // noise, seeds 1-12: at most one such scan per run; the fr079 bag: none).
    if (local.num_angular_edge_matches >= 3 &&
        local.num_angular_edge_matches > 0.01 * local.num_matched) {
      const slam::RealTimeCorrelativeScanMatcherOptions& m =
          config.slam.local.real_time_correlative_scan_matcher;
      std::cerr << "replay: warning: " << local.num_angular_edge_matches << " of "
                << local.num_matched << " matched scans found their best turn on the edge of "
                << "the real-time matcher's window ("
                << FormatNumber(m.angular_search_window_rad * 180.0 / std::numbers::pi)
                << " deg each way): the odometry's turns are off by more than it searches; "
                << (m.initial_estimate_at_angular_edge ? "their predictions were kept. " : "")
                << "A wider slam.local.real_time_correlative_scan_matcher."
                   "angular_search_window_deg may match them\n";
    }
  }
  const std::vector<int> node_scans = NodeScans(dataset, nodes);
  summary["consistency"] =
      ConsistencySummary(dataset, nodes, node_scans, reference ? &*reference : nullptr,
                         config.slam.local.range_filter);
  std::vector<io::PosePair> reference_pairs;
  std::vector<std::optional<geometry::Rigid2d>> reference_by_node(nodes.size());
  if (reference) {
    reference_by_node = ReferenceByNode(*reference, node_scans);
    reference_pairs = io::PairByIndex(trajectory, reference_by_node);
    WarnIfReferenceStandsStill(reference_pairs, args.reference);
    const io::TrajectoryErrors errors = io::ComputeTrajectoryErrors(reference_pairs);
    summary["reference"] = ReferenceSummary(errors, *reference);
    summary["reference"]["file"] = args.reference;
  }
  summary["grid_changes"] = engine.grid_changes();
  summary["grid_change_events"] = engine.grid_change_events();
  summary["submap_update_ms"] = engine.catalog_time_ms();
  summary["frontier"] = io::FrontierSummary(engine);
  const std::vector<Eigen::Vector2d> frontier = engine.GlobalFrontier(picture_strategy);
  // Submaps a diverged SLAM threw kilometres apart would need a map of
  // billions of cells: the map is then written coarser, and navigation points,
  // which need the robot's own resolution, are not looked for.
  const double map_resolution_m = io::GlobalMapResolution(submaps);
  const bool map_coarsened = map_resolution_m > config.slam.local.submaps.resolution_m * 1.5;
  summary["map_resolution_m"] = map_resolution_m;
  if (map_coarsened) {
    std::cerr << "replay: warning: the submaps lie too far apart for a map at "
              << config.slam.local.submaps.resolution_m << " m (has SLAM diverged?): map.yaml is "
              << "written at " << map_resolution_m
              << " m and no navigation points are looked for\n";
  }
  const frontier::Stopwatch navigation_watch;
  const explore::MapNavigationPoints navigation =
      map_coarsened ? explore::MapNavigationPoints{}
                    : FinalNavigationPoints(config, submaps, frontier, nodes);
  const double navigation_time_s = navigation_watch.ElapsedUs() * 1e-6;
  summary["navigation_points"] = {
      {"skipped_coarse_map", map_coarsened},
      {"strategy", picture_strategy},
      {"frontier_points", frontier.size()},
      {"frontier_points_in_boundary", navigation.frontier_points_in_boundary},
      {"count", navigation.points.size()},
      {"clusters", navigation.stats.clusters},
      {"components", navigation.stats.components},
      {"unreachable_components", navigation.stats.unreachable_components},
      {"robot_x_m", nodes.back().pose.translation().x()},
      {"robot_y_m", nodes.back().pose.translation().y()},
      {"robot_escaped", navigation.robot_escaped},
      {"robot_boxed_in", navigation.robot_boxed_in},
      {"time_s", navigation_time_s}};

  io::WriteMapServerMap(submaps, out.Stage("map.yaml"));
  // map_server's YAML names its image beside it.
  out.Stage("map.pgm");
  io::MapOverlay overlay;
  overlay.frontier = frontier;
  for (const explore::NavigationPoint& p : navigation.points) {
    overlay.candidates.push_back(p.position);
  }
  io::WriteMapPicture(submaps, trajectory, overlay, out.Stage("map.png"));
  WriteTextFileAtomically(out.Stage("navigation_points.csv"),
                          NavigationPointsCsv(navigation.points));
  io::WriteTumTrajectory(trajectory, out.Stage("trajectory.tum"));
  if (reference) {
    // The reference pose of every paired node, stamped like trajectory.tum,
    // so other tools (evo, a notebook) can compare the two without pairing.
    std::vector<io::StampedPose> paired_reference;
    paired_reference.reserve(reference_pairs.size());
    for (const io::PosePair& p : reference_pairs)
      paired_reference.push_back({p.time_s, p.reference});
    io::WriteTumTrajectory(paired_reference, out.Stage("reference.tum"));
  }
  // Each match of the loop-closure search and its fate, checked against the
  // final graph and, where the reference has the node and the submap's first
  // node, against the reference.
  io::WriteLoopClosureCsv(builder.GetLoopClosureLog(), trajectory, submaps, reference_by_node,
                          out.Stage("loop_closures.csv"));
  io::WriteFrontierCsv(engine, out.Stage("frontier.csv"));
  io::WriteFrontierPicture(engine, picture_strategy, out.Stage("frontiers.png"));
  const std::filesystem::path summary_path = out.Stage("summary.json");
  WriteTextFileAtomically(summary_path, summary.dump(2) + "\n");
  // The report reads the staged outputs and is committed together with them.
  StageRunReport(summary_path.parent_path(), out);
  out.Commit();

  std::cout << "replay: " << dataset.name << ": " << num_scans << " scans, " << stats.num_nodes
            << " nodes, " << stats.num_submaps << " submaps, " << stats.num_optimizations
            << " optimisations, " << stats.num_loop_closures << " loop closures; " << std::fixed
            << std::setprecision(1) << wall_time_s << " s wall, "
            << summary["realtime_factor"].get<double>() << "x real time, "
            << summary["peak_rss_mb"].get<double>() << " MiB peak\n";
  std::cout << "loop-closure searches: " << stats.num_loop_closure_searches << " ("
            << stats.num_searches_without_match << " below the minimum score, "
            << stats.num_ambiguous_matches << " ambiguous, " << stats.num_gated_loop_closures
            << " gated, " << stats.num_wide_ambiguous_matches << " ambiguous in a wide window, "
            << stats.num_matches_seeing_through << " seeing through walls, "
            << stats.num_loop_closures + stats.num_rejected_loop_closures << " found ("
            << stats.num_near_matches << " near matches), " << stats.num_rejected_loop_closures
            << " of them dropped as outliers); " << stats.num_pairs_without_overlap
            << " pairs not searched for lack of overlap\n";
  if (reference) {
    const nlohmann::json& r = summary["reference"];
    // Not measured (too few matched nodes for a pair that far apart) prints as a dash.
    const auto value = [&r](const char* key) { return FixedOrDash(r[key].get<double>(), 3); };
    std::cout << "reference: " << r["matched_scans"].get<int>() << " nodes matched, ATE RMSE "
              << value("ate_rmse_m") << " m, RPE 1 s " << value("rpe_1s_trans_m") << " m / "
              << value("rpe_1s_rot_deg") << " deg, 10 s " << value("rpe_10s_trans_m") << " m / "
              << value("rpe_10s_rot_deg") << " deg (RMSE; mean absolute 1 s "
              << value("rpe_1s_trans_mean_m") << " m / " << value("rpe_1s_rot_mean_deg")
              << " deg, 10 s " << value("rpe_10s_trans_mean_m") << " m / "
              << value("rpe_10s_rot_mean_deg") << " deg)\n";
  }
  {
    const nlohmann::json& c = summary["consistency"];
    // Millimetres; not measured (no scan had a pair: NaN here, null in the
    // file) prints as a dash.
    const auto mm = [](const nlohmann::json& v) {
      return FixedOrDash(
          v.is_number() ? v.get<double>() * 1000.0 : std::numeric_limits<double>::quiet_NaN(), 1);
    };
    std::cout << "scan consistency: " << mm(c["estimate_mean_distance_m"])
              << " mm from each scan's returns to the " << c["previous_scans"].get<int>()
              << " scans before it";
    if (c.contains("reference_mean_distance_m")) {
      std::cout << " (reference trajectory: " << mm(c["reference_mean_distance_m"]) << " mm)";
    }
    std::cout << "\n";
    const nlohmann::json& r = c["revisits"];
    const auto percent = [](const nlohmann::json& v) {
      return FixedOrDash(
          v.is_number() ? v.get<double>() * 100.0 : std::numeric_limits<double>::quiet_NaN(), 0);
    };
    std::cout << "revisit consistency: " << mm(r["estimate_mean_distance_m"]) << " mm, "
              << percent(r["estimate_paired_fraction"]) << " % of the returns paired, over "
              << r["scans"].get<int>() << " scans back at a place seen at least "
              << FormatNumber(r["min_separation_s"].get<double>()) << " s before";
    if (r.contains("reference_mean_distance_m")) {
      std::cout << " (reference trajectory: " << mm(r["reference_mean_distance_m"]) << " mm, "
                << percent(r["reference_paired_fraction"]) << " %)";
    }
    std::cout << "\n";
  }
  PrintStrategyTable(engine, std::cout);
  if (map_coarsened) {
    std::cout << "navigation points: not looked for (map coarsened to " << map_resolution_m
              << " m, see the warning above)";
  } else {
    std::cout << "navigation points: " << navigation.points.size() << " from the last pose ("
              << frontier.size() << " " << picture_strategy << " frontier points, "
              << navigation.stats.unreachable_components << " unreachable components)";
  }
  if (!navigation.points.empty()) {
    const explore::NavigationPoint& best = navigation.points.front();
    std::cout << "; best (" << std::setprecision(2) << best.position.x() << ", "
              << best.position.y() << ") m, " << best.cost_m << " m of path";
  }
  if (navigation.robot_boxed_in) std::cout << "; the robot's disc fits nowhere near its last pose";
  std::cout << "\n";
  std::cout << "outputs: " << (out.path() / "summary.json").string()
            << ", map.yaml, map.pgm, map.png, navigation_points.csv, trajectory.tum, "
            << (reference ? "reference.tum, " : "")
            << "loop_closures.csv, frontier.csv, frontiers.png, report.html\n";
  if (stop_signal != 0) {
    // The replay so far is complete in itself and written; the exit code
    // still tells a script that it did not reach the end of the dataset.
    std::cerr << "scout: replay stopped by " << SignalName(stop_signal) << " after " << num_scans
              << " of " << dataset_scans << " scans; the replay so far is written\n";
    return 128 + stop_signal;
  }
  return 0;
}

}  // namespace scout::apps
