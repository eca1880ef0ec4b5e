#include "scout/io/scan_consistency.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scout/io/scan_pairing.h"

namespace scout::io {

ScanConsistency MeasureScanConsistency(const std::vector<std::vector<Eigen::Vector2d>>& points,
                                       const std::vector<geometry::Rigid2d>& poses,
                                       const ScanConsistencyOptions& options) {
  if (points.size() != poses.size()) {
    throw std::invalid_argument("MeasureScanConsistency: " + std::to_string(points.size()) +
                                " scans but " + std::to_string(poses.size()) + " poses");
  }
  if (options.previous_scans < 1 || !(options.max_distance_m > 0.0)) {
    throw std::invalid_argument(
        "MeasureScanConsistency: previous_scans must be >= 1 and max_distance_m > 0");
  }
  const size_t window = static_cast<size_t>(options.previous_scans);
  // Each scan's returns in the world frame, placed once.
  const std::vector<std::vector<Eigen::Vector2d>> world = PlaceScans(points, poses);
  double sum_of_means = 0.0;
  ScanConsistency result;
  std::vector<size_t> before;
  for (size_t i = window; i < world.size(); ++i) {
    before.clear();
    for (size_t k = i - window; k < i; ++k) before.push_back(k);
    const ScanPairing pairing = PairWithNearest(world, before, i, options.max_distance_m);
    if (pairing.pairs == 0) continue;
    sum_of_means += pairing.sum_m / pairing.pairs;
    ++result.scans;
  }
  result.mean_distance_m =
      result.scans > 0 ? sum_of_means / result.scans : std::numeric_limits<double>::quiet_NaN();
  return result;
}

}  // namespace scout::io
