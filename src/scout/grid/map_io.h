#ifndef SCOUT_GRID_MAP_IO_H_
#define SCOUT_GRID_MAP_IO_H_

#include <filesystem>

#include "scout/grid/occupancy_map.h"

namespace scout::grid {

// Reads a ROS map_server map: a YAML file with 'image', 'resolution', 'origin'
// ([x, y, yaw]; yaw must be 0), 'negate', 'occupied_thresh', 'free_thresh'
// (and optional 'mode': trinary/scale/raw, treated as trinary thresholds), and
// the PGM (P2/P5, 8 or 16 bit) or PNG (gray, gray+alpha, RGB, RGBA; 8 or 16 bit)
// image it names, relative to the YAML's directory. The image's top row is the
// max-y row of the map. A pixel's occupancy is p = (255 - v) / 255 (v / 255 with
// negate), occupied if p > occupied_thresh, free if p < free_thresh, else unknown.
// Throws InputError naming the file and field on any problem.
OccupancyMap ReadMapServerMap(const std::filesystem::path& yaml_path);

// Writes 'map' as 'yaml_path' plus a PGM (P5) of the same stem beside it
// (map_server convention: 254 free, 0 occupied, 205 unknown; thresholds 0.65 /
// 0.196), each written to a temporary name and renamed. Throws InputError when
// the directory is not writable.
void WriteMapServerMap(const OccupancyMap& map, const std::filesystem::path& yaml_path);

}  // namespace scout::grid

#endif  // SCOUT_GRID_MAP_IO_H_
