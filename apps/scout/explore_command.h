#ifndef SCOUT_APPS_SCOUT_EXPLORE_COMMAND_H_
#define SCOUT_APPS_SCOUT_EXPLORE_COMMAND_H_

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace scout::apps {

struct ExploreArgs {
  std::string world = "office";
  std::string world_size;  // "W" or "WxH" metres; empty: the generator's default
  uint64_t seed = 1;
  std::string out_dir = "out/explore";
  std::string config_file;
  std::string strategy = "exact";
  std::string goals = "scout";
  std::optional<double> max_sim_time_s;
  std::optional<std::string> start;  // "X,Y"; absent: the world's own start
  bool quiet = false;
  bool record_log = false;                 // also write sensor.log (CARMEN) for `scout replay`
  std::optional<std::string> status_file;  // --status: live status JSON (ExploreStatusFile)
};

// Registers `scout explore` on 'app'.
CLI::App* AddExploreCommand(CLI::App& app, ExploreArgs* args);

// Explores a simulated world in closed loop (simulator, SLAM, frontier, goals)
// and writes map.yaml/pgm, map.png, trajectory.tum, truth.tum, frontier.csv,
// coverage.csv and summary.json (and sensor.log with --record-log). Returns the process exit code;
// throws InputError on bad input before writing anything.
int RunExplore(const ExploreArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_EXPLORE_COMMAND_H_
