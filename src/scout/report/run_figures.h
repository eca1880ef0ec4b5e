#ifndef SCOUT_REPORT_RUN_FIGURES_H_
#define SCOUT_REPORT_RUN_FIGURES_H_

#include <string>
#include <vector>

#include "scout/report/run_data.h"

namespace scout::report {

// A drawn figure: SVG text, the file stem it is saved under
// (figures/<name>.svg) and a one-line caption.
struct Figure {
  std::string name;
  std::string caption;
  std::string svg;
};

// Returns the figures of one run, in this order, each only when its input is
// present: the paper's frontier-update figures from frontier.csv
// ("local_points": total local frontier points per round, "queried_points":
// points re-queried per round per strategy, "update_time": update time per
// round per strategy, "accuracy": accuracy/precision/recall per strategy
// against full) and, from coverage.csv, "coverage_path" and "coverage_time".
std::vector<Figure> RunFigures(const RunData& run);

}  // namespace scout::report

#endif  // SCOUT_REPORT_RUN_FIGURES_H_
