#ifndef SCOUT_REPORT_AXIS_TICKS_H_
#define SCOUT_REPORT_AXIS_TICKS_H_

#include <string>
#include <vector>

namespace scout::report {

// An axis range rounded out to "nice" values (1, 2 or 5 times a power of ten)
// with the tick positions inside it, lowest first.
struct AxisTicks {
  double lo = 0.0;
  double hi = 1.0;
  double step = 0.2;  // 0 on a log axis (ticks are decades)
  std::vector<double> ticks;
};

// Returns about 'target_count' (>= 2) intervals covering [lo, hi], with lo/hi
// widened to multiples of the step. An empty range is widened around its value.
AxisTicks NiceTicks(double lo, double hi, int target_count = 5);

// Returns decade ticks covering [lo, hi] (both > 0), with 2 and 5 between
// decades when the range spans fewer than two decades.
AxisTicks LogTicks(double lo, double hi);

// Formats a tick value with just enough decimals for 'step' (0 on log axes),
// abbreviating large magnitudes (12000 -> "12k", 3500000 -> "3.5M").
std::string FormatTick(double value, double step);

// Returns the labels of 'axis'. On a linear axis reaching 10000 all labels
// share one abbreviation (0, 4k, 8k, 12k rather than 0, 4000, 8000, 12k).
std::vector<std::string> TickLabels(const AxisTicks& axis);

}  // namespace scout::report

#endif  // SCOUT_REPORT_AXIS_TICKS_H_
