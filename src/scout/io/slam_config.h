#ifndef SCOUT_IO_SLAM_CONFIG_H_
#define SCOUT_IO_SLAM_CONFIG_H_

#include "scout/io/yaml_fields.h"
#include "scout/slam/map_builder.h"

namespace scout::io {

// Reads the "slam" section of an options file (see config/default.yaml).
// Angles are given in degrees in the file (keys ending in _deg).
void ReadSlamOptions(YamlSection section, slam::SlamOptions* options);

// Reads hit_probability and miss_probability of a grid inserter.
void ReadHitMissProbabilities(YamlSection& section, grid::RangeDataInserterOptions* options);

}  // namespace scout::io

#endif  // SCOUT_IO_SLAM_CONFIG_H_
