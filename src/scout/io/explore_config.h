#ifndef SCOUT_IO_EXPLORE_CONFIG_H_
#define SCOUT_IO_EXPLORE_CONFIG_H_

#include <string>

#include "scout/exploration/exploration_options.h"
#include "scout/io/yaml_fields.h"
#include "scout/sim/simulated_robot.h"

namespace scout::io {

// Reads the "explore" section of an options file (see config/default.yaml).
// The frontier strategy and goal policy are chosen on the command line.
void ReadExploreOptions(YamlSection section, exploration::ExploreOptions* options);

// Reads a "lidar" section (the simulated lidar of explore and frontier-bench).
void ReadLidarOptions(YamlSection section, sim::LidarOptions* options);

// Reads the "robot" section: the simulated base, its lidar and odometry.
// Angles are given in degrees in the file (keys ending in _deg).
void ReadRobotOptions(YamlSection section, sim::SimulatedRobotOptions* options);

// Throws InputError naming 'file' and the key of an out-of-range value in
// the explore and robot sections.
void ValidateExploreAndRobot(const exploration::ExploreOptions& explore,
                             const sim::SimulatedRobotOptions& robot, const std::string& file);

}  // namespace scout::io

#endif  // SCOUT_IO_EXPLORE_CONFIG_H_
