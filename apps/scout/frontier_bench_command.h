#ifndef SCOUT_APPS_SCOUT_FRONTIER_BENCH_COMMAND_H_
#define SCOUT_APPS_SCOUT_FRONTIER_BENCH_COMMAND_H_

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace scout::apps {

struct FrontierBenchArgs {
  std::string world = "office";
  std::string world_size;  // "W" or "WxH" metres; empty: the generator's default
  uint64_t seed = 1;
  std::string out_dir = "out/frontier-bench";
  std::string config_file;
  std::optional<double> epsilon_m;
  std::string strategies = "full,dfd,bfs,direct,exact";
  std::string picture_strategy;  // empty: exact if it runs, else the first strategy
  bool quiet = false;
  // Skip full recomputation (the reference): no accuracy, precision or recall.
  bool no_reference = false;
};

// Registers `scout frontier-bench` on 'app'.
CLI::App* AddFrontierBenchCommand(CLI::App& app, FrontierBenchArgs* args);

// Runs the lockstep frontier evaluation on a synthetic SLAM event stream and
// writes summary.json, frontier.csv, frontiers.png, report.html and
// figures/*.svg into the output directory. Returns the process exit code; throws InputError on bad
// input.
int RunFrontierBench(const FrontierBenchArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_FRONTIER_BENCH_COMMAND_H_
