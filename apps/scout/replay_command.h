#ifndef SCOUT_APPS_SCOUT_REPLAY_COMMAND_H_
#define SCOUT_APPS_SCOUT_REPLAY_COMMAND_H_

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace scout::apps {

struct ReplayArgs {
  std::string dataset;
  std::string out_dir = "out/replay";
  std::string config_file;
  std::string reference;
  std::string strategies = "full,dfd,bfs,direct,exact";
  std::string picture_strategy;  // empty: exact if it runs, else the first strategy
  std::string scan_topic;
  std::string odometry_topic;
  double odom_noise = 0.0;
  uint64_t seed = 1;
  int max_scans = 0;
  bool synchronous = false;
  bool explore_slam = false;  // SLAM as `scout explore` runs it (explore.local_slam, its solves)
  bool quiet = false;
};

// Registers `scout replay` on 'app'.
CLI::App* AddReplayCommand(CLI::App& app, ReplayArgs* args);

// Runs SLAM on a recorded dataset as fast as possible, feeds its events to
// every frontier strategy in lockstep, and writes the map (map.yaml/pgm,
// map.png), trajectory.tum, frontier.csv, frontiers.png and summary.json.
// Returns the process exit code; throws InputError on bad input.
int RunReplay(const ReplayArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_REPLAY_COMMAND_H_
