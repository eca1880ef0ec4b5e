// End-to-end tests of `scout explore`: exit codes, error messages, and the
// outputs of a complete run on a small hand-made building map.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "apps/scout/cli_test_util.h"
#include "scout/common/atomic_file.h"
#include "scout/grid/map_io.h"

namespace {

namespace fs = std::filesystem;
using scout::grid::CellState;

using Result = scout::testing::CliResult;
using scout::testing::ReadFile;
using scout::testing::RunScout;

// Writes a map_server map 'name'.yaml: walls everywhere except the cells whose
// centres lie in one of the free boxes {x0, y0, x1, y1} (metres).
void WriteMap(const fs::path& dir, const std::string& name, int width, int height,
              const std::vector<std::array<double, 4>>& free_boxes) {
  scout::grid::OccupancyMap map;
  map.limits = scout::grid::MapLimits(0.05, {0, 0}, width, height);
  map.cells.assign(map.limits.num_cells(), CellState::kOccupied);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector2d c = map.limits.CellCenter({x, y});
      for (const auto& b : free_boxes) {
        if (c.x() >= b[0] && c.x() <= b[2] && c.y() >= b[1] && c.y() <= b[3]) {
          map.set({x, y}, CellState::kFree);
        }
      }
    }
  }
  scout::grid::WriteMapServerMap(map, dir / (name + ".yaml"));
}

class ExploreCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("scout_explore_cli_test_" + std::to_string(rd()));
    fs::create_directories(dir_);
    // 8 m x 5 m: two rooms joined by a 1.2 m door.
    WriteMap(dir_, "rooms", 166, 106,
             {{0.15, 0.15, 3.95, 5.15}, {4.1, 0.15, 8.15, 5.15}, {3.9, 2.0, 4.2, 3.2}});
    // A corridor only 0.6 m wide: the robot fits, its safety margin does not.
    WriteMap(dir_, "narrow", 100, 40, {{0.5, 0.7, 4.5, 1.3}});
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

TEST_F(ExploreCli, BadInputsNameWhatIsWrongAndLeaveNoOutputs) {
  const fs::path out = dir_ / "out";
  const std::string o = " --quiet --out " + out.string();
  const std::string rooms = " --world " + (dir_ / "rooms.yaml").string();
  Result r = RunScout("explore --world atlantis" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("unknown world 'atlantis'"), std::string::npos) << r.output;
  r = RunScout("explore --start 4.05,0.5" + rooms + o);  // inside the dividing wall
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--start X,Y"), std::string::npos) << r.output;
  r = RunScout("explore --start 1:2" + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("expected X,Y"), std::string::npos) << r.output;
  r = RunScout("explore --start 1e9,0" + rooms + o);  // a number, but no place on any map
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("'1e9,0': expected X,Y in metres, each within +-1e6"), std::string::npos)
      << r.output;
  r = RunScout("explore --start ''" + rooms + o);  // given, but empty: not the default start
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--start: expected a value"), std::string::npos) << r.output;
  r = RunScout("explore --start 500,500" + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("is outside the map, which spans"), std::string::npos) << r.output;
  r = RunScout("explore --world " + (dir_ / "narrow.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no free space is reachable"), std::string::npos) << r.output;
  r = RunScout("explore --strategy magic" + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  r = RunScout("explore --goals random" + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  for (const std::string bad : {"-5", "inf", "nan", "abc", "10s"}) {
    r = RunScout("explore --max-sim-time " + bad + rooms + o);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.output.find("--max-sim-time: expected a positive finite number of seconds, got '" +
                            bad + "'"),
              std::string::npos)
        << r.output;
  }
  scout::WriteTextFileAtomically(dir_ / "contradictory.yaml",
                                 "explore:\n  frontier_inflation_radius_m: 0.2\n");
  r = RunScout("explore --config " + (dir_ / "contradictory.yaml").string() + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("contradictory"), std::string::npos) << r.output;
  scout::WriteTextFileAtomically(dir_ / "bad.yaml", "explore:\n  follower:\n    lookahead: 1\n");
  r = RunScout("explore --config " + (dir_ / "bad.yaml").string() + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("explore.follower.lookahead"), std::string::npos) << r.output;
  // A boundary around the right room while the robot starts in the left one.
  scout::WriteTextFileAtomically(
      dir_ / "away.yaml", "explore:\n  boundary: [[4.2, 0], [8.2, 0], [8.2, 5.2], [4.2, 5.2]]\n");
  r = RunScout("explore --start 2,2.5 --config " + (dir_ / "away.yaml").string() + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("explore.boundary: the start"), std::string::npos) << r.output;
  r = RunScout("explore --status " + (dir_ / "nowhere" / "status.json").string() + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--status " + (dir_ / "nowhere" / "status.json").string() +
                          ": directory " + (dir_ / "nowhere").string() + " does not exist"),
            std::string::npos)
      << r.output;
  r = RunScout("explore --status " + dir_.string() + rooms + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("expected a file name, not a directory"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ExploreCli, KeepsALiveStatusFileWhileItRuns) {
  // A monitor reads the status while the run goes on; it always finds a whole
  // JSON object (rename into place). Copied once the simulated robot moves,
  // then the run is interrupted and the status says how it ended.
  const fs::path out = dir_ / "live";
  const fs::path status = dir_ / "status.json";
  const fs::path seen = dir_ / "status-seen.json";
  const Result r = scout::testing::RunShell(
      "sh -c '" + std::string(SCOUT_BINARY) + " explore --world office --quiet --out " +
      out.string() + " --status " + status.string() + " & pid=$!; n=0; until grep -q " +
      "-E sim_time_s.:.[1-9] " + status.string() + " 2>/dev/null || [ $n -ge 300 ]; do " +
      "sleep 0.1; n=$((n+1)); done; cp " + status.string() + " " + seen.string() +
      "; kill -INT $pid; wait $pid; echo exit=$?'");
  ASSERT_NE(r.output.find("exit=130"), std::string::npos) << r.output;
  std::ifstream seen_in(seen);
  const nlohmann::json live = nlohmann::json::parse(seen_in, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(live.is_object()) << r.output;
  EXPECT_EQ(live["command"], "explore");
  EXPECT_EQ(live["world"], "office");
  EXPECT_EQ(live["out"], out.string());
  EXPECT_EQ(live["running"], true);
  EXPECT_TRUE(live["terminated"].is_null());
  EXPECT_TRUE(live["summary"].is_null());
  EXPECT_GE(live["sim_time_s"].get<double>(), 1.0);
  EXPECT_TRUE(live["pose"]["x_m"].is_number());
  EXPECT_TRUE(live["goals"]["issued"].is_number());

  std::ifstream final_in(status);
  const nlohmann::json last = nlohmann::json::parse(final_in, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(last.is_object()) << r.output;
  EXPECT_EQ(last["running"], false);
  EXPECT_EQ(last["terminated"], "interrupted");
  EXPECT_EQ(last["state"], "ended");
  EXPECT_EQ(last["summary"], (out / "summary.json").string());
  EXPECT_GE(last["sim_time_s"].get<double>(), live["sim_time_s"].get<double>());
  std::ifstream summary_in(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_in);
  EXPECT_EQ(last["coverage"], summary["coverage"]);
  EXPECT_EQ(last["sim_time_s"], summary["sim_time_s"]);
}

TEST_F(ExploreCli, ProgressLinesComeEveryMinuteOfSimulatedTimeBesideAStatusFile) {
  // Not a terminal (a pipe): one line per 60 s of simulated time and the last
  // one, though the status file is refreshed every 5 s (without it the loop
  // reports every 60 s, through the same grid).
  const Result r =
      RunScout("explore --world office --max-sim-time 130 --out " + (dir_ / "lines").string() +
               " --status " + (dir_ / "status.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::string> times;
  for (size_t at = r.output.find("explore: t="); at != std::string::npos;
       at = r.output.find("explore: t=", at + 1)) {
    times.push_back(r.output.substr(at + 11, r.output.find(' ', at + 11) - at - 11));
  }
  EXPECT_EQ(times, (std::vector<std::string>{"0", "60", "120", "130"})) << r.output;
}

TEST_F(ExploreCli, AnInterruptedRunKeepsTheRunSoFar) {
  // The office takes about a minute: interrupted once its output directory
  // (made after the handler is installed) appears, the run stops, finishes
  // its SLAM and writes everything, saying why it ended.
  const fs::path out = dir_ / "interrupted";
  // Twice at once, as timeout(1) delivers it (to the process and its group):
  // one request, not the second Ctrl-C that quits at once.
  const Result r = scout::testing::RunScoutAndInterrupt(
      "explore --world office --quiet --out " + out.string(), out.string(), /*signals=*/2);
  EXPECT_EQ(r.exit_code, 130) << r.output;
  EXPECT_NE(r.output.find("scout: explore stopped by SIGINT at t="), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("explore: office seed 1: interrupted"), std::string::npos) << r.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(summary.is_object()) << r.output;
  EXPECT_EQ(summary["terminated"], "interrupted");
  EXPECT_LT(summary["coverage"].get<double>(), 0.9);
  EXPECT_TRUE(summary["goals"]["frontier_left"].is_null());  // the goals had not run out
  for (const char* name : {"map.yaml", "map.pgm", "map.png", "trajectory.tum", "truth.tum",
                           "coverage.csv", "report.html"}) {
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  }
  // Nothing but the run's own files: no staging directory left beside them.
  for (const fs::directory_entry& e : fs::directory_iterator(out)) {
    EXPECT_EQ(e.path().filename().string().find(".scout-staging"), std::string::npos) << e.path();
  }
}

TEST_F(ExploreCli, ExploresASmallMapAndWritesEveryOutput) {
  const fs::path out = dir_ / "out";
  const fs::path status_path = dir_ / "status.json";
  const Result r = RunScout("explore --quiet --seed 2 --world " + (dir_ / "rooms.yaml").string() +
                            " --out " + out.string() + " --status " + status_path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name :
       {"map.yaml", "map.pgm", "map.png", "coverage.png", "trajectory.tum", "truth.tum",
        "frontier.csv", "coverage.csv", "goals.csv", "loop_closures.csv", "summary.json",
        "report.html", "figures/coverage_path.svg", "figures/coverage_time.svg"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  // The report embeds both pictures and names the directory the run is in,
  // not the staging directory it was written in.
  std::ifstream page(out / "report.html");
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("<code>" + out.string() + "</code>"), std::string::npos);
  EXPECT_EQ(html.find("staging"), std::string::npos);
  EXPECT_NE(html.find("coverage.png"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  // Every loop closure found, checked against the simulator's truth: the
  // truth knows every node, so no row lacks its reference error.
  {
    std::ifstream csv(out / "loop_closures.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line.rfind("node,node_time_s,submap,outcome,", 0), 0u) << line;
    int accepted = 0;
    while (std::getline(csv, line)) {
      std::vector<std::string> f;
      std::istringstream fields(line);
      for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
      ASSERT_EQ(f.size(), 13u) << line;
      EXPECT_FALSE(f[11].empty()) << line;
      accepted += f[3] == "accepted";
    }
    EXPECT_EQ(accepted, s["slam"]["loop_closures"].get<int>());
  }
  // One row per goal issued, its outcome as the counters count it.
  {
    std::ifstream csv(out / "goals.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line,
              "issued_s,robot_x,robot_y,goal_x,goal_y,target_x,target_y,score,path_m,ended_s,"
              "outcome,reachable_in_truth");
    int rows = 0, reached = 0, seen = 0, open = 0, unreachable = 0;
    double last_issued_s = -1.0;
    while (std::getline(csv, line)) {
      std::vector<std::string> f;
      std::istringstream fields(line);
      for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
      ASSERT_EQ(f.size(), 12u) << line;
      ++rows;
      const double issued_s = std::stod(f[0]);
      EXPECT_GT(issued_s, last_issued_s) << line;
      last_issued_s = issued_s;
      EXPECT_GT(std::stod(f[8]), 0.0) << line;  // a path was planned
      reached += f[10] == "reached";
      seen += f[10] == "seen";
      open += f[10] == "open";
      if (f[10] != "open") {
        EXPECT_GE(std::stod(f[9]), issued_s) << line;
      }
      unreachable += f[11] == "0";
    }
    EXPECT_EQ(rows, s["goals"]["issued"].get<int>());
    EXPECT_EQ(reached, s["goals"]["reached"].get<int>());
    EXPECT_EQ(seen, s["goals"]["seen_before_arrival"].get<int>());
    EXPECT_LE(open, 1);  // at most the goal the run ended with
    EXPECT_EQ(unreachable, s["goals"]["unreachable"].get<int>());
  }
  EXPECT_EQ(s["world"], "rooms");
  EXPECT_EQ(s["seed"], 2);
  EXPECT_EQ(s["strategy"], "exact");
  EXPECT_EQ(s["goals_policy"], "scout");
  EXPECT_EQ(s["terminated"], "complete");
  EXPECT_GE(s["coverage"].get<double>(), 0.97);
  EXPECT_NEAR(s["coverage"].get<double>(),
              s["mapped_free_m2"].get<double>() / s["reachable_free_m2"].get<double>(), 1e-9);
  // The robot's own free area holds the truly mapped area, and little more:
  // free cells at the walls' edges that the truth counts as wall.
  EXPECT_GE(s["map_free_m2"].get<double>(), 0.97 * s["mapped_free_m2"].get<double>());
  EXPECT_LE(s["map_free_m2"].get<double>(), 1.3 * s["reachable_free_m2"].get<double>());
  EXPECT_EQ(s["collisions"], 0);
  EXPECT_TRUE(s["collision_places"].is_array());
  EXPECT_EQ(s["collision_places"].size(), 0u);  // one entry per collision
  EXPECT_EQ(s["goals"]["unreachable"], 0);
  EXPECT_EQ(s["unreachable_goals"].size(), 0u);  // one entry per unreachable goal
  // One place per reachable frontier point left.
  EXPECT_EQ(s["reachable_frontier_left_places"].size(),
            s["goals"]["reachable_frontier_left"].get<size_t>());
  // Every failure is counted at one failed-goal place.
  int failures = 0;
  int blacklisted = 0;
  for (const nlohmann::json& g : s["failed_goal_places"]) {
    EXPECT_EQ(g["goal_map"].size(), 2u);
    failures += g["failures"].get<int>();
    blacklisted += g["blacklisted"].get<bool>();
  }
  EXPECT_EQ(failures, s["goals"]["failed"].get<int>() + s["goals"]["no_plan"].get<int>());
  EXPECT_GT(s["goals"]["issued"].get<int>(), 0);
  EXPECT_LT(s["ate_rmse_m"].get<double>(), 0.1);
  EXPECT_GT(s["sim_time_s"].get<double>(), s["wall_time_s"].get<double>());
  EXPECT_TRUE(s["time_to_coverage_s"]["0.90"].is_number());
  EXPECT_TRUE(s["slam"].contains("nodes"));
  EXPECT_TRUE(s["frontier"]["strategies"].contains("exact"));
  std::ifstream csv(out / "coverage.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "sim_time_s,path_length_m,coverage,map_free_m2");
  // The last status is the summary's run, with the robot where it ended.
  std::ifstream status_in(status_path);
  const nlohmann::json status = nlohmann::json::parse(status_in);
  EXPECT_EQ(status["running"], false);
  EXPECT_EQ(status["terminated"], "complete");
  EXPECT_EQ(status["world"], "rooms");
  EXPECT_EQ(status["seed"], 2);
  EXPECT_EQ(status["summary"], (out / "summary.json").string());
  EXPECT_EQ(status["coverage"], s["coverage"]);
  EXPECT_EQ(status["path_length_m"], s["path_length_m"]);
  EXPECT_EQ(status["collisions"], 0);
  EXPECT_EQ(status["goals"]["issued"], s["goals"]["issued"]);
  EXPECT_EQ(status["goals"]["reached"], s["goals"]["reached"]);
  for (const char* counter : {"recoveries", "retraces", "last_resorts", "guard_stops"}) {
    EXPECT_EQ(status["goals"][counter], s["goals"][counter]) << counter;
  }
  EXPECT_EQ(status["frontier_points"], 0);  // explored completely
  EXPECT_EQ(status["blacklisted_goals"].size(), static_cast<size_t>(blacklisted));
  const Eigen::Vector2d estimated(status["pose"]["x_m"].get<double>(),
                                  status["pose"]["y_m"].get<double>());
  const Eigen::Vector2d truth(status["true_pose"]["x_m"].get<double>(),
                              status["true_pose"]["y_m"].get<double>());
  EXPECT_LT((estimated - truth).norm(), 0.2);
}

// The rows of a TUM trajectory file (stamp x y z qx qy qz qw), comments skipped.
std::vector<std::vector<double>> ReadTum(const fs::path& path) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(ReadFile(path));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

TEST_F(ExploreCli, RecordsItsSensorStreamForReplayAgainstTheTruePoses) {
  const fs::path out = dir_ / "out";
  const std::string rooms = " --world " + (dir_ / "rooms.yaml").string();
  Result r =
      RunScout("explore --quiet --record-log --max-sim-time 40" + rooms + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(fs::exists(out / "sensor.log"));
  // --explore-slam replays with the explore loop's SLAM settings, so the replay
  // sees what the loop saw.
  const std::string log = (out / "sensor.log").string();
  const std::string replay =
      "replay " + log + " --reference " + log + " --strategies exact --quiet";
  r = RunScout(replay + " --explore-slam --out " + (dir_ / "replay").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream explore_in(out / "summary.json");
  const nlohmann::json explored = nlohmann::json::parse(explore_in);
  std::ifstream replay_in(dir_ / "replay" / "summary.json");
  const nlohmann::json replayed = nlohmann::json::parse(replay_in);
  // Every scan the simulator made is in the log, every node found its true pose.
  EXPECT_EQ(replayed["scans"], explored["slam"]["scans"]);
  EXPECT_EQ(replayed["reference"]["matched_scans"], replayed["slam"]["nodes"]);
  EXPECT_LT(replayed["reference"]["ate_rmse_m"].get<double>(), 0.1);
  EXPECT_EQ(replayed["slam"]["settings"], "explore");
  EXPECT_EQ(replayed["slam"]["synchronous"], true);
  // The log holds every odometry sample and every number exactly, so the
  // replay repeats the loop's SLAM: the same nodes at the same poses, but
  // for the loop's placement of its map frame in the world (a translation
  // here, the start's heading being 0).
  EXPECT_EQ(replayed["odometry_source"], "odometry messages");
  const std::vector<std::vector<double>> looped = ReadTum(out / "trajectory.tum");
  const std::vector<std::vector<double>> replayed_poses =
      ReadTum(dir_ / "replay" / "trajectory.tum");
  ASSERT_EQ(looped.size(), replayed_poses.size());
  ASSERT_GT(looped.size(), 100u);
  const double world_x = looped[0][1] - replayed_poses[0][1];
  const double world_y = looped[0][2] - replayed_poses[0][2];
  for (size_t i = 0; i < looped.size(); ++i) {
    EXPECT_EQ(looped[i][0], replayed_poses[i][0]) << i;  // stamp
    EXPECT_NEAR(looped[i][1] - replayed_poses[i][1], world_x, 1e-9) << i;
    EXPECT_NEAR(looped[i][2] - replayed_poses[i][2], world_y, 1e-9) << i;
    EXPECT_EQ(looped[i][6], replayed_poses[i][6]) << i;  // qz
    EXPECT_EQ(looped[i][7], replayed_poses[i][7]) << i;  // qw
  }
  // The same as the explorer's settings (config/default.yaml's explore section)
  // written out for slam.local and the pose graph by hand: the same trajectory.
  scout::WriteTextFileAtomically(
      dir_ / "by_hand.yaml",
      "slam:\n  local:\n    use_online_correlative_scan_matching: false\n"
      "    ceres_scan_matcher:\n      translation_weight: 5\n      rotation_weight: 10\n"
      "      likelihood_field_sigma_m: 0\n"
      "  pose_graph:\n    synchronous: true\n    synchronous_solve_delay_nodes: 10\n");
  r = RunScout(replay + " --config " + (dir_ / "by_hand.yaml").string() + " --out " +
               (dir_ / "by_hand").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string explore_trajectory = ReadFile(dir_ / "replay" / "trajectory.tum");
  EXPECT_EQ(ReadFile(dir_ / "by_hand" / "trajectory.tum"), explore_trajectory);
  // And the explore section is what it reads: another translation prior there
  // gives another trajectory.
  scout::WriteTextFileAtomically(dir_ / "weak_prior.yaml",
                                 "explore:\n  local_slam:\n    translation_weight: 0.5\n");
  r = RunScout(replay + " --explore-slam --config " + (dir_ / "weak_prior.yaml").string() +
               " --out " + (dir_ / "weak_prior").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(ReadFile(dir_ / "weak_prior" / "trajectory.tum"), explore_trajectory);

  // A lidar whose beams a FLASER line cannot describe is refused before anything is written.
  scout::WriteTextFileAtomically(dir_ / "wide.yaml",
                                 "robot:\n  lidar:\n    fov_deg: 360\n    beams: 360\n");
  r = RunScout("explore --quiet --record-log --config " + (dir_ / "wide.yaml").string() + rooms +
               " --out " + (dir_ / "wide").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--record-log"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "wide"));
}

}  // namespace
