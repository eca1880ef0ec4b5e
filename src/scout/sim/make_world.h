#ifndef SCOUT_SIM_MAKE_WORLD_H_
#define SCOUT_SIM_MAKE_WORLD_H_

#include <cstdint>
#include <optional>
#include <string>

#include "scout/sim/world.h"

namespace scout::sim {

// Outer extent of a generated building (width along x, height along y).
struct WorldSize {
  double width_m = 0.0;
  double height_m = 0.0;
};

// The largest side a generated world may have: 500 m is 10,000 cells of 5 cm
// per side, the largest world of the scaling measurement (docs/RESULTS.md,
// section d). At 1000 m a 5 s exploration needed 13.6 GB and the museum and
// frontier-bench ran out of memory (measured 2026-12-03).
inline constexpr double kMaxWorldSide_m = 500.0;

// Parses "W" (a square W x W) or "WxH", metres, e.g. "100" or "160x100".
// Throws InputError naming 'text' unless both are finite numbers > 0 and at
// most kMaxWorldSide_m.
WorldSize ParseWorldSize(const std::string& text);

// Returns the world named 'name_or_yaml': "office" or "museum" (generated from
// 'seed' with default options, except the outer extent when 'size' is given),
// or a ROS map_server map when it is a path ending in ".yaml". Throws
// InputError for anything else, a bad map file, a size the generator rejects
// (the message names width_m or height_m), or a size given for a map file
// (a recorded building cannot be scaled).
World MakeWorld(const std::string& name_or_yaml, uint64_t seed,
                const std::optional<WorldSize>& size = std::nullopt);

}  // namespace scout::sim

#endif  // SCOUT_SIM_MAKE_WORLD_H_
