#include "scout/synthetic/waypoint_cover.h"

#include <algorithm>
#include <limits>

namespace scout::synthetic {

std::vector<int64_t> SelectWaypoints(GridSearch& search, const std::vector<uint8_t>& reachable,
                                     const std::vector<float>& clearance, double min_clearance_m,
                                     double spacing_m) {
  std::vector<int64_t> candidates;
  for (int64_t i = 0; i < static_cast<int64_t>(reachable.size()); ++i) {
    if (reachable[i] && clearance[i] >= min_clearance_m) candidates.push_back(i);
  }
  std::sort(candidates.begin(), candidates.end(), [&](int64_t a, int64_t b) {
    return clearance[a] != clearance[b] ? clearance[a] > clearance[b] : a < b;
  });
  std::vector<uint8_t> covered(reachable.size(), 0);
  std::vector<int64_t> waypoints;
  for (int64_t candidate : candidates) {
    if (covered[candidate]) continue;
    waypoints.push_back(candidate);
    search.Run(candidate, spacing_m, [&](int64_t cell, double) {
      covered[cell] = 1;
      return false;
    });
  }
  return waypoints;
}

std::vector<std::vector<int64_t>> OrderByNearestNeighbour(GridSearch& search, int64_t start,
                                                          const std::vector<int64_t>& waypoints) {
  std::vector<uint8_t> pending(static_cast<size_t>(search.limits().num_cells()), 0);
  for (int64_t w : waypoints) pending[w] = 1;
  pending[start] = 0;
  std::vector<std::vector<int64_t>> legs;
  int64_t current = start;
  for (;;) {
    const int64_t next = search.Run(current, std::numeric_limits<double>::infinity(),
                                    [&](int64_t cell, double) { return pending[cell] != 0; });
    if (next < 0) break;
    pending[next] = 0;
    legs.push_back(search.PathTo(next));
    current = next;
  }
  return legs;
}

}  // namespace scout::synthetic
