#include "scout/explore/path_distance_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace scout::explore {

PathDistanceField::PathDistanceField(const PlanningMap& map, const Eigen::Vector2d& robot)
    : PathDistanceField(map, StartRegion(map, robot)) {}

PathDistanceField::PathDistanceField(const PlanningMap& map, const StartRegion& start)
    : limits_(map.limits()), distance_m_(limits_.num_cells(), kUnreachable) {
  if (start.empty()) return;
  const float res = static_cast<float>(limits_.resolution());

  // Dijkstra in cell units over a copy of the traversability mask padded by
  // one closed cell, so the inner loop needs no bounds checks.
  const int w = limits_.width(), h = limits_.height();
  const int pw = w + 2;
  std::vector<uint8_t> open(static_cast<size_t>(pw) * (h + 2), 0);
  std::vector<float> factor(open.size(), 1.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int64_t flat = int64_t{y} * w + x;
      open[(y + 1) * pw + x + 1] = map.traversable(flat);
      factor[(y + 1) * pw + x + 1] = map.StepFactor(flat);
    }
  }
  std::vector<float> d(open.size(), kUnreachable);
  const int64_t step[8] = {1, -1, pw, -pw, pw + 1, -pw + 1, pw - 1, -pw - 1};
  // For a diagonal step, the two orthogonal cells it passes between.
  const int64_t side_a[8] = {0, 0, 0, 0, 1, 1, -1, -1};
  const int64_t side_b[8] = {0, 0, 0, 0, pw, -pw, pw, -pw};
  const float cost[8] = {
      1, 1, 1, 1, float(M_SQRT2), float(M_SQRT2), float(M_SQRT2), float(M_SQRT2)};
  // Dial's bucket queue with buckets one cell wide: every step costs at least
  // one cell, so a cell popped from bucket k can only improve cells in later
  // buckets, and bucket k is final when its turn comes: exact, and O(cells).
  // The ring spans the dearest step (a narrow diagonal) and the seeds' own
  // distances (an escape path).
  float farthest_seed = 0.0f;
  for (const StartSeed& seed : start.seeds()) {
    farthest_seed = std::max(farthest_seed, seed.distance_m / res);
  }
  const int64_t ring =
      static_cast<int64_t>(std::ceil(farthest_seed + float(M_SQRT2) * map.MaxStepFactor())) + 2;
  std::vector<std::vector<uint32_t>> bucket(ring);
  std::vector<uint8_t> done(open.size(), 0);
  int64_t pending = 0;
  for (const StartSeed& seed : start.seeds()) {
    const uint32_t s = static_cast<uint32_t>((seed.cell.y + 1) * pw + seed.cell.x + 1);
    const float ds = seed.distance_m / res;
    if (ds < d[s]) {
      d[s] = ds;
      bucket[static_cast<int64_t>(ds) % ring].push_back(s);
      ++pending;
    }
  }
  for (int64_t k = 0; pending > 0; ++k) {
    std::vector<uint32_t>& current = bucket[k % ring];
    for (size_t i = 0; i < current.size(); ++i) {
      const uint32_t u = current[i];
      --pending;
      if (done[u]) continue;
      done[u] = 1;
      const float du = d[u];
      for (int n = 0; n < 8; ++n) {
        const int64_t v = u + step[n];
        if (!open[v] || done[v]) continue;
        if (n >= 4 && !(open[u + side_a[n]] && open[u + side_b[n]])) continue;
        const float dv = du + cost[n] * factor[v];
        if (dv < d[v]) {
          d[v] = dv;
          bucket[static_cast<int64_t>(dv) % ring].push_back(static_cast<uint32_t>(v));
          ++pending;
        }
      }
    }
    current.clear();
  }
  float nearest = kUnreachable;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float di = d[(y + 1) * pw + x + 1];
      if (std::isfinite(di)) distance_m_[int64_t{y} * w + x] = di * res;
    }
  }
  for (const StartSeed& seed : start.seeds()) {
    if (seed.distance_m < nearest) nearest = seed.distance_m, start_ = seed.cell;
  }
}

std::optional<PathDistanceField::Reached> PathDistanceField::NearestReached(
    const Eigen::Vector2d& p, double radius_m) const {
  // Inline rather than CellsWithin: this runs for every frontier point.
  std::optional<Reached> best;
  const grid::CellIndex centre = limits_.CellContaining(p);
  const int r = static_cast<int>(std::ceil(radius_m / limits_.resolution()));
  const double r2 = radius_m * radius_m;
  for (int y = centre.y - r; y <= centre.y + r; ++y) {
    for (int x = centre.x - r; x <= centre.x + r; ++x) {
      const grid::CellIndex c{x, y};
      if (!limits_.Contains(c)) continue;
      if (!(c == centre) && (limits_.CellCenter(c) - p).squaredNorm() > r2) continue;
      const float dist = distance_m_[limits_.FlatIndex(c)];
      if (std::isfinite(dist) && (!best || dist < best->distance_m)) best = Reached{dist, c};
    }
  }
  return best;
}

}  // namespace scout::explore
