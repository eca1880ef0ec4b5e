#include "scout/report/axis_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace scout::report {
namespace {

// Returns i * nice * 10^power computed so that ticks land exactly on decimal
// values (140 * 5 / 100 is 7.0; 140 * 0.05 is 7.000000000000001).
double TickValue(long i, double nice, int power) {
  return power < 0 ? (i * nice) / std::pow(10.0, -power) : i * nice * std::pow(10.0, power);
}

int DecimalsFor(double step) {
  return step > 0.0 && step < 1.0 ? static_cast<int>(std::ceil(-std::log10(step) - 1e-9)) : 0;
}

std::string TrimZeros(std::string s) {
  if (s.find('.') == std::string::npos) return s;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

AxisTicks NiceTicks(double lo, double hi, int target_count) {
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
    // A flat series still needs a readable axis around its value.
    const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  target_count = std::max(target_count, 2);
  const double rough = (hi - lo) / target_count;
  const double normalized = rough / std::pow(10.0, std::floor(std::log10(rough)));
  double nice = 10.0;
  if (normalized < 1.5) {
    nice = 1.0;
  } else if (normalized < 3.0) {
    nice = 2.0;
  } else if (normalized < 7.0) {
    nice = 5.0;
  }
  const int power = static_cast<int>(std::floor(std::log10(rough)));
  AxisTicks axis;
  axis.step = TickValue(1, nice, power);
  const long first = static_cast<long>(std::floor(lo / axis.step + 1e-9));
  const long last = static_cast<long>(std::ceil(hi / axis.step - 1e-9));
  axis.lo = TickValue(first, nice, power);
  axis.hi = TickValue(last, nice, power);
  for (long i = first; i <= last; ++i) axis.ticks.push_back(TickValue(i, nice, power));
  return axis;
}

AxisTicks LogTicks(double lo, double hi) {
  if (lo > hi) std::swap(lo, hi);
  const int first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (last == first) ++last;
  AxisTicks axis;
  axis.step = 0.0;
  axis.lo = std::pow(10.0, first);
  axis.hi = std::pow(10.0, last);
  const bool fine = last - first < 2;
  for (int d = first; d <= last; ++d) {
    const double decade = std::pow(10.0, d);
    axis.ticks.push_back(decade);
    if (fine && d < last) {
      axis.ticks.push_back(2 * decade);
      axis.ticks.push_back(5 * decade);
    }
  }
  return axis;
}

std::string FormatTick(double value, double step) {
  char buffer[64];
  const double magnitude = std::abs(value);
  if (magnitude >= 1e4) {
    // Five digits and more read faster abbreviated; the step says how many
    // decimals the abbreviation needs to stay exact.
    double scale = 1e3;
    const char* suffix = "k";
    if (magnitude >= 1e9) {
      scale = 1e9, suffix = "G";
    } else if (magnitude >= 1e6) {
      scale = 1e6, suffix = "M";
    }
    const int decimals = step > 0.0 ? DecimalsFor(step / scale) : 2;
    std::snprintf(buffer, sizeof(buffer), "%.*f", std::clamp(decimals, 0, 6), value / scale);
    return TrimZeros(buffer) + suffix;
  }
  if (step == 0.0) {
    std::snprintf(buffer, sizeof(buffer), "%.4g", value);  // log axis: 1, 20, 1000, 0.05
    return buffer;
  }
  std::snprintf(buffer, sizeof(buffer), "%.*f", std::clamp(DecimalsFor(step), 0, 12), value);
  // Returned fresh rather than assigned: g++ 12 with sanitizers reports a
  // false -Wrestrict on assigning a literal into the string here.
  if (std::string_view(buffer) == "-0") return "0";
  return buffer;
}

std::vector<std::string> TickLabels(const AxisTicks& axis) {
  std::vector<std::string> labels;
  double largest = 0.0;
  for (const double t : axis.ticks) largest = std::max(largest, std::abs(t));
  double scale = 1.0;
  const char* suffix = "";
  if (axis.step > 0.0 && largest >= 1e4) {
    scale = largest >= 1e9 ? 1e9 : largest >= 1e6 ? 1e6 : 1e3;
    suffix = largest >= 1e9 ? "G" : largest >= 1e6 ? "M" : "k";
  }
  for (const double t : axis.ticks) {
    if (axis.step == 0.0) {
      labels.push_back(FormatTick(t, 0.0));
    } else if (t == 0.0) {
      labels.push_back("0");
    } else {
      labels.push_back(FormatTick(t / scale, axis.step / scale) + suffix);
    }
  }
  return labels;
}

}  // namespace scout::report
