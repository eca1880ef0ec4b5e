#ifndef SCOUT_SIM_MAKE_WORLD_H_
#define SCOUT_SIM_MAKE_WORLD_H_

#include <cstdint>
#include <string>

#include "scout/sim/world.h"

namespace scout::sim {

// Returns the world named 'name_or_yaml': "office" or "museum" (generated from
// 'seed' with default options), or a ROS map_server map when it is a path
// ending in ".yaml". Throws InputError for anything else or a bad map file.
World MakeWorld(const std::string& name_or_yaml, uint64_t seed);

}  // namespace scout::sim

#endif  // SCOUT_SIM_MAKE_WORLD_H_
