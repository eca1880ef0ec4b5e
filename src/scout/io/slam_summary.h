#ifndef SCOUT_IO_SLAM_SUMMARY_H_
#define SCOUT_IO_SLAM_SUMMARY_H_

#include <nlohmann/json.hpp>

#include "scout/slam/map_builder.h"

namespace scout::io {

// Returns the part of the "slam" object that every summary.json (explore and
// replay) shares: {nodes, submaps, optimizations, loop_closures,
// rejected_loop_closures, gated_loop_closures, loop_closure_searches,
// solve_time_s, synchronous}. The commands add their own keys to it.
nlohmann::json SlamSummary(const slam::SlamStats& stats, bool synchronous);

}  // namespace scout::io

#endif  // SCOUT_IO_SLAM_SUMMARY_H_
