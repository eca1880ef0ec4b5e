#ifndef SCOUT_IO_CONFIG_H_
#define SCOUT_IO_CONFIG_H_

#include <filesystem>

#include "scout/exploration/exploration_options.h"
#include "scout/frontier/frontier_options.h"
#include "scout/sim/simulated_robot.h"
#include "scout/slam/map_builder.h"
#include "scout/synthetic/synthetic_stream.h"

namespace scout::io {

// Every option of the scout commands, one struct per module, defaults from
// ALGORITHMS.md (config/default.yaml lists them all with comments).
struct ScoutConfig {
  frontier::FrontierOptions frontier;
  synthetic::SyntheticStreamOptions synthetic;
  slam::SlamOptions slam;
  exploration::ExploreOptions explore;
  sim::SimulatedRobotOptions robot;
};

// Reads a YAML options file; absent keys keep their defaults. Throws
// InputError naming the file and key for a missing or malformed file, an
// unknown key, or a value of the wrong type or range.
ScoutConfig LoadConfig(const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_CONFIG_H_
