#include "apps/scout/explore_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "apps/scout/command_util.h"
#include "apps/scout/explore_status.h"
#include "apps/scout/interrupt.h"
#include "apps/scout/report_command.h"
#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/exploration/exploration_loop.h"
#include "scout/frontier/stopwatch.h"
#include "scout/io/carmen_log_writer.h"
#include "scout/io/config.h"
#include "scout/io/frontier_report.h"
#include "scout/io/loop_closure_csv.h"
#include "scout/io/map_picture.h"
#include "scout/io/output_directory.h"
#include "scout/io/plan_picture.h"
#include "scout/io/slam_summary.h"
#include "scout/io/trajectory_association.h"
#include "scout/io/trajectory_metrics.h"
#include "scout/io/tum_trajectory.h"
#include "scout/sim/lidar.h"
#include "scout/sim/make_world.h"

namespace scout::apps {
namespace {

exploration::ExplorationOptions MakeOptions(const ExploreArgs& args) {
  exploration::ExplorationOptions o =
      ExplorationOptionsFrom(LoadConfigOrDefaults(args.config_file));
  o.explore.strategy = args.strategy;
  o.explore.goal_policy = args.goals;
  if (args.max_sim_time_s) o.explore.max_sim_time_s = *args.max_sim_time_s;
  if (args.start) o.start = ParsePoint(*args.start, "--start");
  try {
    exploration::CheckExplorationOptions(o);
  } catch (const InputError& e) {
    // Options that contradict each other come from the options file (over the
    // defaults); a command-line option's message names its flag instead.
    const std::string message = e.what();
    if (args.config_file.empty() || message.rfind("--", 0) == 0) throw;
    throw InputError(args.config_file + ": " + message);
  }
  return o;
}

std::vector<io::StampedPose> ToWorld(const std::vector<slam::TimedPose>& poses,
                                     const geometry::Rigid2d& world_from_map) {
  std::vector<io::StampedPose> out;
  out.reserve(poses.size());
  for (const slam::TimedPose& p : poses) out.push_back({p.time_s, world_from_map * p.pose});
  return out;
}

// The true pose of every SLAM node, by node id, found by its scan's time
// (both carry the simulator's stamp of that scan).
std::vector<std::optional<geometry::Rigid2d>> TruthByNode(
    const std::vector<io::StampedPose>& estimate, const std::vector<slam::TimedPose>& truth) {
  std::map<double, geometry::Rigid2d> by_time;
  for (const slam::TimedPose& t : truth) by_time.emplace(t.time_s, t.pose);
  std::vector<std::optional<geometry::Rigid2d>> by_node;
  by_node.reserve(estimate.size());
  for (const io::StampedPose& e : estimate) {
    const auto it = by_time.find(e.time_s);
    by_node.push_back(it != by_time.end() ? std::optional(it->second) : std::nullopt);
  }
  return by_node;
}

// map.png's overlay in the world frame the picture is drawn in: the
// submaps where the run's strategy ran frontier detection in the last
// optimisation round, its global frontier, the navigation points issued,
// those of the last selection and the exploration boundary.
io::MapOverlay ExplorationOverlay(const exploration::ExplorationLoop& loop,
                                  const exploration::ExplorationResult& r) {
  const geometry::Rigid2d& world_from_map = loop.world_from_map();
  const frontier::FrontierEngine& engine = loop.frontier_engine();
  const std::string& strategy = loop.options().explore.strategy;
  io::MapOverlay overlay;
  for (const int id : engine.LastRoundSubmaps(strategy)) {
    const frontier::SubmapRecord& record = engine.catalog().submap(id);
    overlay.highlighted_submaps.push_back({world_from_map * record.global_pose, record.grid});
  }
  for (const Eigen::Vector2d& p : engine.GlobalFrontier(strategy)) {
    overlay.frontier.push_back(world_from_map * p);
  }
  for (const exploration::IssuedGoal& g : r.goals) {
    overlay.navigation_points.push_back(world_from_map * g.goal_map);
  }
  for (const Eigen::Vector2d& p : r.last_candidates_map) {
    overlay.candidates.push_back(world_from_map * p);
  }
  overlay.boundary = loop.options().explore.boundary;  // already in the world frame
  for (const exploration::ExplorationResult::FailedGoal& g : r.failed_goals) {
    if (g.blacklisted) overlay.blacklisted_goals.push_back(world_from_map * g.goal_map);
  }
  return overlay;
}

nlohmann::json OptionalSeconds(const std::optional<double>& t) {
  return t ? nlohmann::json(*t) : nlohmann::json(nullptr);
}

// A count of frontier left, or null when the run ended before the goal
// manager finished and so never counted it.
nlohmann::json Counted(const exploration::ExplorationResult& r, int count) {
  return r.frontier_counted ? nlohmann::json(count) : nlohmann::json(nullptr);
}

std::string FrontierLeftText(const exploration::ExplorationResult& r) {
  if (!r.frontier_counted) return "frontier left not counted (the goals had not run out)";
  return std::to_string(r.frontier_left) + " frontier points left unreached (" +
         std::to_string(r.reachable_frontier_left) + " reachable, never visited; " +
         std::to_string(r.visited_frontier_left) + " reachable near reached goals)";
}

nlohmann::json Summary(const ExploreArgs& args, const exploration::ExplorationLoop& loop,
                       const exploration::ExplorationResult& r, double wall_time_s,
                       double ate_rmse_m) {
  nlohmann::json s;
  s["world"] = loop.world().name;
  s["seed"] = args.seed;
  s["strategy"] = args.strategy;
  s["goals_policy"] = args.goals;
  s["terminated"] = std::string(exploration::ToString(r.terminated));
  s["coverage"] = r.coverage;
  s["mapped_free_m2"] = r.mapped_free_m2;
  s["reachable_free_m2"] = r.reachable_free_m2;
  // Present only with explore.boundary: coverage then counts inside it alone.
  const std::vector<Eigen::Vector2d>& boundary = loop.options().explore.boundary;
  if (!boundary.empty()) {
    nlohmann::json vertices = nlohmann::json::array();
    for (const Eigen::Vector2d& v : boundary) vertices.push_back({v.x(), v.y()});
    s["boundary"] = vertices;
  }
  s["map_free_m2"] = r.map_free_m2;
  s["path_length_m"] = r.path_length_m;
  s["sim_time_s"] = r.sim_time_s;
  s["wall_time_s"] = wall_time_s;
  s["time_to_coverage_s"] = {{"0.90", OptionalSeconds(r.time_to_coverage_s[0])},
                             {"0.95", OptionalSeconds(r.time_to_coverage_s[1])},
                             {"0.99", OptionalSeconds(r.time_to_coverage_s[2])}};
  s["goals"] = {{"issued", r.counters.goals_issued},
                {"reached", r.counters.goals_reached},
                {"failed", r.counters.goals_failed},
                {"unreachable", r.unreachable_goals},
                {"unreachable_points", r.unreachable_points},
                {"no_plan", r.counters.goals_unreachable},
                {"superseded", r.counters.goals_superseded},
                {"seen_before_arrival", r.counters.goals_seen},
                {"dropped", r.counters.goals_dropped},
                {"contradicted_by_scan", r.counters.goals_contradicted},
                {"retried", r.counters.goals_retried},
                {"escapes", r.counters.escapes},
                {"recoveries", r.counters.recoveries},
                {"stuck_reselections", r.counters.stuck_reselections},
                {"back_ups_blocked", r.counters.back_ups_blocked},
                {"retraces", r.counters.retraces},
                {"last_resorts", r.counters.last_resorts},
                {"guard_stops", r.counters.guard_stops},
                {"guard_steers", r.counters.guard_steers},
                // null: not counted, the goal manager had not finished.
                {"frontier_left", Counted(r, r.frontier_left)},
                {"reachable_frontier_left", Counted(r, r.reachable_frontier_left)},
                {"visited_frontier_left", Counted(r, r.visited_frontier_left)}};
  // Where each goal the true world made unreachable was, and the robot then
  // (world frame), so they can be found on the map; and the goal, target and
  // robot as the map had them (*_map, in the frame of map.yaml and
  // trajectory.tum): a point the map had in the open but the world has
  // inside a wall tells a SLAM error from a planning one.
  nlohmann::json unreachable = nlohmann::json::array();
  const geometry::Rigid2d& world_from_map = loop.world_from_map();
  for (const exploration::IssuedGoal& g : r.goals) {
    if (g.reachable_in_truth) continue;
    const Eigen::Vector2d goal_map = world_from_map * g.goal_map;
    const Eigen::Vector2d target_map = world_from_map * g.target_map;
    const Eigen::Vector2d robot_map = world_from_map * g.robot_map;
    unreachable.push_back({{"sim_time_s", g.sim_time_s},
                           {"goal", {g.goal_world.x(), g.goal_world.y()}},
                           {"target", {g.target_world.x(), g.target_world.y()}},
                           {"robot", {g.robot_world.x(), g.robot_world.y()}},
                           {"goal_map", {goal_map.x(), goal_map.y()}},
                           {"target_map", {target_map.x(), target_map.y()}},
                           {"robot_map", {robot_map.x(), robot_map.y()}}});
  }
  s["unreachable_goals"] = unreachable;
  // Where goals failed (not reached in time, or no plan led to them), as the
  // final map has them, how often, and whether they were still blacklisted
  // at the end (map.png crosses those out).
  nlohmann::json failed = nlohmann::json::array();
  for (const exploration::ExplorationResult::FailedGoal& g : r.failed_goals) {
    const Eigen::Vector2d goal_map = world_from_map * g.goal_map;
    failed.push_back({{"goal_map", {goal_map.x(), goal_map.y()}},
                      {"failures", g.failures},
                      {"blacklisted", g.blacklisted}});
  }
  s["failed_goal_places"] = failed;
  // Frontier the policy gave up on (ended no_progress with it left): where.
  nlohmann::json gave_up = nlohmann::json::array();
  for (const Eigen::Vector2d& p : r.reachable_frontier_left_world)
    gave_up.push_back({p.x(), p.y()});
  s["reachable_frontier_left_places"] = gave_up;
  s["returned_home"] = r.returned_home;
  s["collisions"] = r.collisions;
  nlohmann::json collisions = nlohmann::json::array();
  for (const exploration::ExplorationResult::Collision& c : r.collision_places) {
    collisions.push_back(
        {{"sim_time_s", c.sim_time_s}, {"robot", {c.robot_world.x(), c.robot_world.y()}}});
  }
  s["collision_places"] = collisions;
  s["ate_rmse_m"] = ate_rmse_m;
  const slam::SlamStats stats = loop.map_builder().GetStats();
  s["slam"] = io::SlamSummary(stats, loop.options().slam.pose_graph.synchronous);
  s["slam"]["scans"] = stats.num_scans;
  s["frontier"] = io::FrontierSummary(loop.frontier_engine());
  const exploration::LoopTimings& t = r.timings;
  s["wall_time_breakdown_s"] = {{"simulation", t.simulation_s},
                                {"slam", t.slam_s},
                                {"frontier", t.frontier_s},
                                {"map_fusion", t.map_fusion_s},
                                {"goals", t.goals_s}};
  const geometry::Rigid2d& start = loop.world_from_map();
  s["start"] = {start.translation().x(), start.translation().y(), start.theta()};
  return s;
}

void WriteCoverageCsv(const std::vector<exploration::CoverageSample>& samples,
                      const std::filesystem::path& path) {
  std::ostringstream csv;
  csv << "sim_time_s,path_length_m,coverage,map_free_m2\n" << std::setprecision(6);
  for (const exploration::CoverageSample& s : samples) {
    csv << s.sim_time_s << "," << s.path_length_m << "," << s.coverage << "," << s.map_free_m2
        << "\n";
  }
  WriteTextFileAtomically(path, csv.str());
}

// One row per goal issued: when, where the robot stood and where it was sent
// (world frame, as the truth places them), the policy's score, the planned
// path, how it ended, and whether the true world let the robot get there.
void WriteGoalsCsv(const std::vector<exploration::IssuedGoal>& goals,
                   const std::filesystem::path& path) {
  std::ostringstream csv;
  csv << "issued_s,robot_x,robot_y,goal_x,goal_y,target_x,target_y,score,path_m,ended_s,outcome,"
         "reachable_in_truth\n"
      << std::setprecision(6);
  // Empty where there is no value (a goal still open has no end).
  const auto number = [](double v) { return std::isfinite(v) ? FixedOrDash(v, 3) : ""; };
  for (const exploration::IssuedGoal& g : goals) {
    const explore::GoalRecord& r = g.record;
    csv << g.sim_time_s << "," << g.robot_world.x() << "," << g.robot_world.y() << ","
        << g.goal_world.x() << "," << g.goal_world.y() << "," << g.target_world.x() << ","
        << g.target_world.y() << "," << number(r.score) << "," << r.path_m << ","
        << number(r.ended_s) << "," << explore::ToString(r.outcome) << ","
        << (g.reachable_in_truth ? 1 : 0) << "\n";
  }
  WriteTextFileAtomically(path, csv.str());
}

void PrintProgress(const exploration::ExplorationProgress& p, bool terminal) {
  std::cerr << (terminal ? "\r" : "") << "explore: t=" << std::fixed << std::setprecision(0)
            << p.sim_time_s << " s coverage " << std::setprecision(1) << 100.0 * p.coverage
            << " % goals " << p.counters.goals_issued << " issued / " << p.counters.goals_reached
            << " reached / " << p.counters.goals_failed << " failed, " << explore::ToString(p.state)
            << (terminal ? "   " : "\n") << std::flush;
}

}  // namespace

CLI::App* AddExploreCommand(CLI::App& app, ExploreArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "explore",
      "Explore a simulated world in closed loop: simulator, SLAM, reachable frontiers, "
      "navigation points and path following");
  cmd->add_option("--world", args->world, "office, museum (generated) or a map_server .yaml")
      ->capture_default_str();
  cmd->add_option("--world-size", args->world_size,
                  "outer extent of a generated world, W or WxH metres, at most 500 (default: the "
                  "generator's)");
  cmd->add_option("--seed", args->seed, "seed of the generated world and the sensor noise")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->add_option("--out", args->out_dir, "output directory")->capture_default_str();
  cmd->add_option("--config", args->config_file, "YAML options file (see config/default.yaml)");
  cmd->add_option("--strategy", args->strategy, "frontier update strategy")
      ->check(CLI::IsMember({"exact", "direct", "bfs", "dfd", "full"}))
      ->capture_default_str();
  cmd->add_option("--goals", args->goals, "goal policy")
      ->check(CLI::IsMember({"scout", "nearest", "explore-lite", "meanshift-centres"}))
      ->capture_default_str();
  cmd->add_option("--max-sim-time", args->max_sim_time_s,
                  "stop after this much simulated time, seconds (default: explore.max_sim_time_s)")
      ->check(PositiveFiniteNumber("seconds"));
  cmd->add_option("--start", args->start, "start position X,Y in metres (default: the world's)");
  cmd->add_flag("--quiet", args->quiet, "print only the final summary");
  cmd->add_flag("--record-log", args->record_log,
                "also write sensor.log: every scan with its true and odometry pose and every "
                "odometry sample as a CARMEN log, numbers exact, to re-run the loop's SLAM on it "
                "to the digit with `scout replay sensor.log --reference sensor.log "
                "--explore-slam`");
  cmd->add_option("--status", args->status_file,
                  "keep a JSON status of the running exploration in this file (state, poses, "
                  "goal, coverage, counters), rewritten atomically every 5 s of simulated time");
  return cmd;
}

int RunExplore(const ExploreArgs& args) {
  const frontier::Stopwatch wall;
  // Everything that can be wrong with the input is found before any output.
  const exploration::ExplorationOptions options = MakeOptions(args);
  if (args.status_file) ExploreStatusFile::CheckPath(*args.status_file);
  const sim::World world = MakeCommandWorld(args.world, args.seed, args.world_size);
  std::unique_ptr<exploration::ExplorationLoop> loop_owner;
  try {
    loop_owner = std::make_unique<exploration::ExplorationLoop>(world, options, args.seed);
  } catch (const InputError& e) {
    // The boundary comes from the options file, which its message should name.
    const std::string message = e.what();
    if (args.config_file.empty() || message.rfind("explore.boundary", 0) != 0) throw;
    throw InputError(args.config_file + ": " + message);
  }
  exploration::ExplorationLoop& loop = *loop_owner;
  std::optional<io::CarmenLogWriter> log;
  if (args.record_log) {
    const sim::Lidar lidar(options.robot.lidar);
    io::CheckFlaserGeometry(lidar.angle_min_rad(), lidar.angle_increment_rad(),
                            options.robot.lidar.beams, "--record-log");
  }
  io::OutputDirectory out(args.out_dir, io::OutputDirectory::Mode::kReplaceRun, "explore",
                          {args.world, args.config_file});
  if (args.record_log) {
    log.emplace(out.Stage("sensor.log"));
    loop.set_scan_recorder([&log](const sensor::LaserScan& scan, const geometry::Rigid2d& true_pose,
                                  const geometry::Rigid2d& odometry_pose) {
      log->AddScan(scan, true_pose, odometry_pose);
    });
    loop.set_odometry_recorder(
        [&log](const sensor::Odometry& odometry) { log->AddOdometry(odometry); });
  }

  std::optional<ExploreStatusFile> status;
  if (args.status_file) {
    status.emplace(*args.status_file,
                   nlohmann::ordered_json{{"command", "explore"},
                                          {"world", world.name},
                                          {"seed", args.seed},
                                          {"strategy", options.explore.strategy},
                                          {"goals_policy", options.explore.goal_policy},
                                          {"out", out.path().string()}});
  }

  const bool terminal = !args.quiet && ::isatty(STDERR_FILENO);
  // A terminal's progress line and the status file are refreshed every 5 s
  // of simulated time; plain progress lines (a log) come every 60 s.
  constexpr double kLineEvery_s = 60.0;
  // Lines on the 60 s grid; the loop's clock sums steps, so a report due at
  // 120 s may come a hair before it.
  int64_t last_line = -1;
  exploration::ExplorationLoop::ProgressCallback progress;
  if (!args.quiet || status) {
    progress = [&](const exploration::ExplorationProgress& p) {
      if (status) status->Update(p, wall.ElapsedUs() * 1e-6);
      if (args.quiet) return;
      const auto line = static_cast<int64_t>(std::floor(p.sim_time_s / kLineEvery_s + 1e-6));
      if (!terminal && !p.finished && line <= last_line) return;
      last_line = line;
      PrintProgress(p, terminal);
    };
  }
  const exploration::ExplorationResult result = loop.Run(
      progress, terminal || status ? 5.0 : kLineEvery_s, [] { return PendingSignal() != 0; });
  if (terminal) std::cerr << "\n";
  const double wall_time_s = wall.ElapsedUs() * 1e-6;

  const geometry::Rigid2d& world_from_map = loop.world_from_map();
  const std::vector<io::StampedPose> estimate =
      ToWorld(loop.map_builder().GetTrajectory(), world_from_map);
  const std::vector<io::StampedPose> truth = ToWorld(result.truth, geometry::Rigid2d());
  const std::vector<std::optional<geometry::Rigid2d>> truth_by_node =
      TruthByNode(estimate, result.truth);
  const std::vector<io::PosePair> pairs = io::PairByIndex(estimate, truth_by_node);
  const double ate_rmse_m = io::ComputeTrajectoryErrors(pairs).ate_rmse_m;
  io::GlobalSubmaps submaps;
  for (const slam::SubmapState& s : loop.map_builder().GetSubmaps()) {
    submaps.push_back({world_from_map * s.global_pose, s.grid});
  }
  const nlohmann::json summary = Summary(args, loop, result, wall_time_s, ate_rmse_m);

  io::WriteMapServerMap(submaps, out.Stage("map.yaml"));
  out.Stage("map.pgm");  // map_server's YAML names its image beside it
  io::WriteMapPicture(submaps, estimate, ExplorationOverlay(loop, result), out.Stage("map.png"));
  io::WriteCoveragePicture(loop.world().map, loop.CoverageMask(), truth, out.Stage("coverage.png"));
  io::WriteTumTrajectory(estimate, out.Stage("trajectory.tum"));
  io::WriteTumTrajectory(truth, out.Stage("truth.tum"));
  io::WriteLoopClosureCsv(loop.map_builder().GetLoopClosureLog(), estimate, submaps, truth_by_node,
                          out.Stage("loop_closures.csv"));
  io::WriteFrontierCsv(loop.frontier_engine(), out.Stage("frontier.csv"));
  WriteCoverageCsv(result.coverage_samples, out.Stage("coverage.csv"));
  WriteGoalsCsv(result.goals, out.Stage("goals.csv"));
  int snapshots = 0;
  for (const exploration::IssuedGoal& g : result.goals) {
    if (g.map_then == nullptr) continue;
    const std::string name = "unreachable-goal-" + std::to_string(++snapshots);
    io::WritePlanPicture(*g.map_then,
                         {g.robot_map, g.goal_map, g.target_map, g.path_map, g.scan_map},
                         out.Stage(name + ".png"));
    // The same goal in the true world, where the scans that mapped it put
    // it: shows which wall the map had wrong.
    io::WritePlanPicture(loop.world().map,
                         {g.robot_world, g.goal_world, g.target_world, {}, g.scan_world},
                         out.Stage(name + "-truth.png"));
    std::cerr << "explore: unreachable goal " << snapshots << " at t=" << g.sim_time_s
              << " s: robot at (" << g.robot_world.x() << ", " << g.robot_world.y() << ") sent to ("
              << g.target_world.x() << ", " << g.target_world.y() << ") in the true world\n";
  }
  const std::filesystem::path summary_path = out.Stage("summary.json");
  WriteTextFileAtomically(summary_path, summary.dump(2) + "\n");
  // The report reads the staged outputs and is committed together with them.
  StageRunReport(summary_path.parent_path(), out);
  if (log) log->Close();
  out.Commit();
  if (status) status->Finish(result.terminated, out.path() / "summary.json");

  std::cout << std::fixed << std::setprecision(3) << "explore: " << world.name << " seed "
            << args.seed << ": " << summary["terminated"].get<std::string>() << ", coverage "
            << result.coverage << " (" << std::setprecision(1) << result.mapped_free_m2 << " of "
            << result.reachable_free_m2 << " m2), path " << result.path_length_m << " m, sim "
            << result.sim_time_s << " s, wall " << wall_time_s << " s ("
            << result.sim_time_s / std::max(1e-9, wall_time_s) << "x)\n"
            << "goals: " << result.counters.goals_issued << " issued, "
            << result.counters.goals_reached << " reached, " << result.counters.goals_failed
            << " failed, " << result.unreachable_goals << " unreachable in truth; collisions "
            << result.collisions << "; ATE RMSE " << FixedOrDash(ate_rmse_m, 3) << " m; "
            << FrontierLeftText(result) << "\n"
            << "outputs: " << (out.path() / "summary.json").string()
            << ", map.yaml, map.pgm, map.png, coverage.png, trajectory.tum, truth.tum, "
               "frontier.csv, coverage.csv, goals.csv, loop_closures.csv, report.html, figures/"
            << (log ? ", sensor.log" : "")
            << (snapshots > 0 ? ", unreachable-goal-*.png (the map each goal the true world made "
                                "unreachable was chosen on, and the true world around it)"
                              : "")
            << "\n";
  if (result.terminated == exploration::Termination::kInterrupted) {
    // The run so far is complete in itself and written; the exit code still
    // tells a script that it did not end by itself.
    const int signal_number = PendingSignal();
    std::cerr << "scout: explore stopped by " << SignalName(signal_number) << " at t=" << std::fixed
              << std::setprecision(1) << result.sim_time_s << " s; the run so far is written\n";
    return 128 + signal_number;
  }
  return 0;
}

}  // namespace scout::apps
