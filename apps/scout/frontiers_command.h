#ifndef SCOUT_APPS_SCOUT_FRONTIERS_COMMAND_H_
#define SCOUT_APPS_SCOUT_FRONTIERS_COMMAND_H_

#include <CLI/CLI.hpp>
#include <string>

namespace scout::apps {

struct FrontiersArgs {
  std::string map;  // map_server YAML
  std::string robot;
  std::string out_dir = "out/frontiers";
  std::string config_file;
  bool quiet = false;
};

// Registers `scout frontiers MAP.yaml --robot X,Y` on 'app'.
CLI::App* AddFrontiersCommand(CLI::App& app, FrontiersArgs* args);

// Finds the frontier a robot at --robot can reach on a saved occupancy map
// (any SLAM system's map_server map) and its navigation points, as Scout's
// explorer would rank them, without driving anywhere. Writes
// navigation_points.csv, frontier_points.csv, map.png, summary.json and
// report.html. Returns the exit code; throws InputError on bad input.
int RunFrontiers(const FrontiersArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_FRONTIERS_COMMAND_H_
