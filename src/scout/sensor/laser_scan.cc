#include "scout/sensor/laser_scan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"

namespace scout::sensor {

static_assert(kMaxRayLength_m == 200.0, "the messages below say 200");
constexpr double kInfinity = std::numeric_limits<double>::infinity();

void Validate(const RangeFilterOptions& options) {
  const auto check = [](bool ok, const char* key, double value, const char* expected) {
    if (!ok) {
      throw std::invalid_argument(std::string("range_filter.") + key + " must be " + expected +
                                  ", got " + FormatNumber(value));
    }
  };
  check(options.min_range_m >= 0.0 && options.min_range_m <= kMaxRayLength_m, "min_range_m",
        options.min_range_m, "in [0, 200] (m)");
  check(options.max_range_m > options.min_range_m, "max_range_m", options.max_range_m,
        ("> range_filter.min_range_m (" + FormatNumber(options.min_range_m) + ")").c_str());
  check(options.max_range_m <= kMaxRayLength_m || options.max_range_m == kInfinity, "max_range_m",
        options.max_range_m, "at most 200 (m) when given");
  check(options.miss_ray_length_m >= 0.0 && options.miss_ray_length_m <= kMaxRayLength_m,
        "miss_ray_length_m", options.miss_ray_length_m, "in [0, 200] (m)");
}
namespace {

void CheckNonNegative(const char* name, double value) {
  if (!(value >= 0.0)) {
    throw std::invalid_argument(std::string("range filter: ") + name + " must be >= 0, got " +
                                FormatNumber(value));
  }
}

}  // namespace

RangeData ToRangeData(const LaserScan& scan, const RangeFilterOptions& options) {
  CheckNonNegative("min_range_m", options.min_range_m);
  CheckNonNegative("max_range_m", options.max_range_m);
  CheckNonNegative("miss_ray_length_m", options.miss_ray_length_m);
  const double min_range_m = std::max<double>(options.min_range_m, scan.range_min_m);
  // A corrupt log's range (or range_max) cannot make a ray longer than this.
  const double max_range_m =
      std::min({options.max_range_m, static_cast<double>(scan.range_max_m), kMaxRayLength_m});

  RangeData data;
  data.returns.reserve(scan.ranges.size());
  for (size_t k = 0; k < scan.ranges.size(); ++k) {
    const double angle_rad =
        static_cast<double>(scan.angle_min_rad) + static_cast<double>(k) * scan.angle_increment_rad;
    const Eigen::Vector2d direction(std::cos(angle_rad), std::sin(angle_rad));
    const double range_m = scan.ranges[k];
    const bool no_return = std::isnan(range_m) || range_m >= max_range_m;
    if (no_return) {
      if (options.miss_ray_length_m > 0.0) {
        data.misses.push_back(options.miss_ray_length_m * direction);
      }
    } else if (range_m >= min_range_m) {
      data.returns.push_back(range_m * direction);
    }
  }
  return data;
}

}  // namespace scout::sensor
