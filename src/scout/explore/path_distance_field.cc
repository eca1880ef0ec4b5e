#include "scout/explore/path_distance_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace scout::explore {

PathDistanceField::PathDistanceField(const PlanningMap& map, const Eigen::Vector2d& robot)
    : limits_(map.limits()), distance_m_(limits_.num_cells(), kUnreachable) {
  start_ = map.NearestTraversable(robot, map.options().inflation_radius_m());
  if (!start_) return;

  // Dijkstra in cell units; the heap holds (distance, flat) with lazy deletion.
  std::vector<float> d(limits_.num_cells(), kUnreachable);
  using Entry = std::pair<float, int64_t>;
  std::vector<Entry> heap;
  heap.reserve(1024);
  const auto later = [](const Entry& a, const Entry& b) { return a.first > b.first; };
  const int64_t s = limits_.FlatIndex(*start_);
  d[s] = 0.0f;
  heap.push_back({0.0f, s});
  const float kStep[8] = {
      1, 1, 1, 1, float(M_SQRT2), float(M_SQRT2), float(M_SQRT2), float(M_SQRT2)};
  const int w = limits_.width();
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [du, u] = heap.back();
    heap.pop_back();
    if (du > d[u]) continue;
    const grid::CellIndex cu = limits_.CellOfFlatIndex(u);
    for (int k = 0; k < 8; ++k) {
      if (!map.StepAllowed(cu, k)) continue;
      const int64_t v = u + kNeighbourOffsets[k][0] + int64_t{kNeighbourOffsets[k][1]} * w;
      const float dv = du + kStep[k];
      if (dv < d[v]) {
        d[v] = dv;
        heap.push_back({dv, v});
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
  // The robot may have started off its cell's centre (inside the band).
  const float offset = static_cast<float>((limits_.CellCenter(*start_) - robot).norm());
  const float res = static_cast<float>(limits_.resolution());
  for (size_t i = 0; i < d.size(); ++i) {
    if (std::isfinite(d[i])) distance_m_[i] = d[i] * res + offset;
  }
}

std::optional<PathDistanceField::Reached> PathDistanceField::NearestReached(
    const Eigen::Vector2d& p, double radius_m) const {
  std::optional<Reached> best;
  for (const grid::CellIndex& c : CellsWithin(limits_, p, radius_m)) {
    const float dist = distance_m_[limits_.FlatIndex(c)];
    if (std::isfinite(dist) && (!best || dist < best->distance_m)) best = Reached{dist, c};
  }
  return best;
}

}  // namespace scout::explore
