#ifndef SCOUT_REPORT_COMPARE_H_
#define SCOUT_REPORT_COMPARE_H_

#include <filesystem>
#include <string>
#include <vector>

#include "scout/report/html_page.h"
#include "scout/report/run_data.h"
#include "scout/report/run_figures.h"

namespace scout::report {

// Returns the figures overlaying 'runs', each only when some run has its
// input: "compare_p" (P per strategy, one bar per run), "compare_accuracy",
// "compare_time" (update time per round), "compare_coverage_path" and
// "compare_coverage_time" (one line per run).
std::vector<Figure> ComparisonFigures(const std::vector<RunData>& runs);

// Returns compare.html: one table with a column per run (world or dataset,
// seed, strategy or goal policy, the summary's scalar values, per-strategy
// headline metrics, final coverage) and 'figures' inline. Self-contained.
std::string RenderComparison(const std::vector<RunData>& runs, const std::vector<Figure>& figures);

// Reads every directory of 'dirs' (runs are named after their directories,
// made unique with a suffix) and returns "compare.html" plus one
// "figures/<name>.svg" per figure. Throws InputError like ReadRun, and when
// 'dirs' is empty.
std::vector<ReportFile> BuildComparison(const std::vector<std::filesystem::path>& dirs);

}  // namespace scout::report

#endif  // SCOUT_REPORT_COMPARE_H_
