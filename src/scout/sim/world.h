#ifndef SCOUT_SIM_WORLD_H_
#define SCOUT_SIM_WORLD_H_

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// The TRUE world of a simulation. Occupied cells are walls and obstacles; free
// cells are where the robot may be. Unknown cells (e.g. outside the walls of a
// loaded map, or beyond the map) are opaque to the lidar and not traversable.
struct World {
  std::string name;
  grid::OccupancyMap map;
  // Where the robot starts, world frame, metres.
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
};

// Returns the centre of the free cell with the largest clearance (see
// ComputeClearance) inside the largest 8-connected component of free cells;
// ties go to the lowest row-major index. Throws InputError naming 'what' if the
// map has no free cell.
Eigen::Vector2d ChooseStartPosition(const grid::OccupancyMap& map, const std::string& what);

// The name of the world in a map_server YAML file: the file's stem, or the name of
// its directory when the stem is map_saver's default "map".
std::string MapWorldName(const std::filesystem::path& yaml);

// Loads a ROS map_server map (YAML + image) as a world named MapWorldName(yaml),
// starting at ChooseStartPosition. Throws InputError on a bad file or a
// map without free cells.
World LoadMapWorld(const std::filesystem::path& yaml);

}  // namespace scout::sim

#endif  // SCOUT_SIM_WORLD_H_
