#ifndef SCOUT_REPORT_STRATEGY_STATS_H_
#define SCOUT_REPORT_STRATEGY_STATS_H_

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "scout/report/run_data.h"

namespace scout::report {

// The headline numbers of one update strategy over a run (ALGORITHMS §5).
struct StrategyStats {
  std::string strategy;
  int rounds = 0;                // optimisation rounds seen
  int64_t queried_points = 0;    // summed over rounds
  double time_ms = 0.0;          // summed over rounds
  double time_per_round_ms = 0;  // NaN without rounds
  // Against "full"; NaN when the run scored nothing (no reference).
  double accuracy = std::numeric_limits<double>::quiet_NaN();
  double precision = std::numeric_limits<double>::quiet_NaN();
  double recall = std::numeric_limits<double>::quiet_NaN();
  double performance_p = 0.0;  // 1 - queried / queried(dfd); NaN without dfd
};

// Returns one entry per strategy, in the order the run lists them. Values in
// summary.json ("frontier.strategies") take precedence, since the run computed
// them; frontier.csv fills in what the summary lacks (and the number of
// rounds). Empty when the run has neither.
std::vector<StrategyStats> StrategyStatsOf(const RunData& run);

}  // namespace scout::report

#endif  // SCOUT_REPORT_STRATEGY_STATS_H_
