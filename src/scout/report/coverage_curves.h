#ifndef SCOUT_REPORT_COVERAGE_CURVES_H_
#define SCOUT_REPORT_COVERAGE_CURVES_H_

#include <string>
#include <vector>

#include "scout/report/run_data.h"
#include "scout/report/svg_plot.h"

namespace scout::report {

// The coverage lines of a comparison figure, in percent of the reachable free
// area, over path length or over simulated time.
//
// Runs that share a world and a goal policy (several seeds) become one line,
// the mean of their coverage at each x: with 5 seeds x 4 policies, one line
// per run is 20 lines nobody can tell apart. A run that ended keeps its final
// coverage (it explored nothing more), so each mean runs to the longest run.
// Runs alone in their group keep their own line, named after the run.
struct CoverageLines {
  std::vector<Series> over_path;
  std::vector<Series> over_time;
  bool grouped = false;  // some line is the mean of several runs
};
CoverageLines CoverageLinesOf(const std::vector<RunData>& runs);

// Returns the mean coverage (percent) of 'runs' at 'samples' evenly spaced x
// from 0 to the largest x of any run; x is path length or simulated time.
Series MeanCoverage(const std::string& name, const std::vector<const RunData*>& runs,
                    bool over_path, int samples = 200);

}  // namespace scout::report

#endif  // SCOUT_REPORT_COVERAGE_CURVES_H_
