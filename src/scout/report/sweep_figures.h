#ifndef SCOUT_REPORT_SWEEP_FIGURES_H_
#define SCOUT_REPORT_SWEEP_FIGURES_H_

#include <vector>

#include "scout/report/run_data.h"
#include "scout/report/run_figures.h"

namespace scout::report {

// Figures across frontier-bench runs that differ in one parameter, one line
// per strategy, each only when the runs hold two or more distinct values:
// - "epsilon_points" and "epsilon_accuracy": points re-queried (sum over
//   rounds) and accuracy against 'full' over epsilon_m, for bfs and direct
//   (the strategies that take the threshold);
// - "size_points" and "size_time": points re-queried and update time per
//   optimisation round over the world's width (world_size_m), log scale,
//   every strategy.
std::vector<Figure> SweepFigures(const std::vector<RunData>& runs);

}  // namespace scout::report

#endif  // SCOUT_REPORT_SWEEP_FIGURES_H_
