#ifndef SCOUT_IO_FRONTIER_REPORT_H_
#define SCOUT_IO_FRONTIER_REPORT_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "scout/frontier/frontier_engine.h"

namespace scout::io {

// Writes one row per optimisation round and strategy:
// round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points
// (local_points: local frontier points of all submaps at that round)
// (atomically: temporary file, then rename).
void WriteFrontierCsv(const frontier::FrontierEngine& engine, const std::filesystem::path& path);

// Returns {"strategies": {name: {queried_points, queried_submaps, time_ms,
// accuracy, precision, recall, P, tp, fp, tn, fn, grid_change_queried_points,
// grid_change_time_ms}}}, the "frontier" object of every summary.json.
nlohmann::json FrontierSummary(const frontier::FrontierEngine& engine);

// Draws the fused map of all submaps at their current poses (free white,
// occupied black, unknown grey), tints the submaps 'strategy' re-queried in the
// last optimisation round red, and marks the global frontier of 'strategy' in
// blue. Long sides are capped at 'max_side_px' by coarsening the resolution.
void WriteFrontierPicture(const frontier::FrontierEngine& engine, const std::string& strategy,
                          const std::filesystem::path& path, int max_side_px = 3000);

}  // namespace scout::io

#endif  // SCOUT_IO_FRONTIER_REPORT_H_
