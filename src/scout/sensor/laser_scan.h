#ifndef SCOUT_SENSOR_LASER_SCAN_H_
#define SCOUT_SENSOR_LASER_SCAN_H_

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace scout::sensor {

// One sweep of a 2D lidar, as a driver reports it (sensor_msgs/LaserScan).
// Beam k points at angle_min_rad + k * angle_increment_rad in the sensor frame
// (x forward, y left) and measured ranges[k] metres. A beam without a return
// reports NaN or +infinity (or any value >= range_max_m).
struct LaserScan {
  double time_s = 0.0;
  float angle_min_rad = 0.f;
  float angle_increment_rad = 0.f;
  float range_min_m = 0.f;
  float range_max_m = 0.f;
  std::vector<float> ranges;
};

// A scan as points in the sensor frame: 'returns' are where a beam hit
// something; 'misses' are ends of beams without a return, which only tell that
// the space up to them is free.
struct RangeData {
  std::vector<Eigen::Vector2d> returns;
  std::vector<Eigen::Vector2d> misses;
};

// The longest ray Scout inserts, returns and misses alike: far beyond any 2D
// lidar, and short enough that a corrupt range cannot grow a submap to
// billions of cells (200 m is 4,000 cells at 5 cm).
inline constexpr double kMaxRayLength_m = 200.0;

struct RangeFilterOptions {
  // Returns closer than this are dropped (the scan's own range_min_m applies too).
  double min_range_m = 0.0;
  // Returns at or beyond this count as "no return"; the scan's range_max_m
  // and kMaxRayLength_m apply too, so the default (+infinity) means "use the
  // scan's range_max_m". At most kMaxRayLength_m when finite.
  double max_range_m = std::numeric_limits<double>::infinity();
  // Beams without a return (NaN, +infinity, >= max range) become free-space-only
  // misses of this length, as Cartographer's missing_data_ray_length (5 m).
  // 0 drops them. At most kMaxRayLength_m.
  double miss_ray_length_m = 5.0;
};

// Throws std::invalid_argument naming the first bad option
// ("range_filter.<key> must be ..., got <value>").
void Validate(const RangeFilterOptions& options);

// Returns the points of 'scan' in the sensor frame, filtered by 'options'.
// Throws std::invalid_argument if an option is negative or NaN.
RangeData ToRangeData(const LaserScan& scan, const RangeFilterOptions& options);

}  // namespace scout::sensor

#endif  // SCOUT_SENSOR_LASER_SCAN_H_
