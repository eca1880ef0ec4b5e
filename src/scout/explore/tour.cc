#include "scout/explore/tour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace scout::explore {

std::vector<std::vector<double>> CoarsePathDistances(const PlanningMap& map,
                                                     const std::vector<grid::CellIndex>& cells,
                                                     double coarse_cell_m) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(cells.size());
  std::vector<std::vector<double>> d(n, std::vector<double>(n, kInf));
  for (int i = 0; i < n; ++i) d[i][i] = 0.0;
  if (n < 2) return d;
  const grid::MapLimits& limits = map.limits();
  const int factor =
      std::max(1, static_cast<int>(std::lround(coarse_cell_m / limits.resolution())));
  const int cw = (limits.width() + factor - 1) / factor;
  const int ch = (limits.height() + factor - 1) / factor;
  std::vector<uint8_t> open(static_cast<size_t>(cw) * ch, 0);
  for (int y = 0; y < limits.height(); ++y) {
    for (int x = 0; x < limits.width(); ++x) {
      if (map.traversable(limits.FlatIndex({x, y}))) open[(y / factor) * cw + x / factor] = 1;
    }
  }
  const auto coarse = [&](const grid::CellIndex& c) {
    return static_cast<int64_t>(c.y / factor) * cw + c.x / factor;
  };
  // A candidate's own coarse cell is open when its fine cell is traversable;
  // a cell outside the map is never reached.
  std::vector<int64_t> target(n, -1);
  for (int i = 0; i < n; ++i) {
    if (limits.Contains(cells[i])) target[i] = coarse(cells[i]);
  }
  const double step_m = factor * limits.resolution();
  std::vector<double> dist(open.size());
  using Item = std::pair<double, int64_t>;
  for (int i = 0; i + 1 < n; ++i) {
    if (target[i] < 0 || !open[target[i]]) continue;
    // Dijkstra from i until every later candidate is settled (the earlier
    // ones found their distance to i already).
    std::fill(dist.begin(), dist.end(), kInf);
    std::vector<std::pair<int64_t, int>> wanted;
    for (int j = i + 1; j < n; ++j) {
      if (target[j] >= 0 && open[target[j]]) wanted.push_back({target[j], j});
    }
    std::sort(wanted.begin(), wanted.end());
    size_t remaining = wanted.size();
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    dist[target[i]] = 0.0;
    queue.push({0.0, target[i]});
    while (!queue.empty() && remaining > 0) {
      const auto [du, u] = queue.top();
      queue.pop();
      if (du > dist[u]) continue;
      for (auto it = std::lower_bound(wanted.begin(), wanted.end(), std::make_pair(u, -1));
           it != wanted.end() && it->first == u; ++it) {
        d[i][it->second] = d[it->second][i] = du * step_m;
        --remaining;
      }
      const int ux = static_cast<int>(u % cw), uy = static_cast<int>(u / cw);
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) continue;
          const int vx = ux + dx, vy = uy + dy;
          if (vx < 0 || vy < 0 || vx >= cw || vy >= ch) continue;
          const int64_t v = static_cast<int64_t>(vy) * cw + vx;
          if (!open[v]) continue;
          const double dv = du + (dx != 0 && dy != 0 ? M_SQRT2 : 1.0);
          if (dv < dist[v]) {
            dist[v] = dv;
            queue.push({dv, v});
          }
        }
      }
    }
  }
  return d;
}

std::vector<double> OpenTourLengths(const std::vector<double>& first_leg_m,
                                    const std::vector<std::vector<double>>& distance_m) {
  const int n = static_cast<int>(first_leg_m.size());
  if (n > kMaxTourPoints) {
    throw std::invalid_argument("OpenTourLengths: more than kMaxTourPoints candidates");
  }
  if (n == 0) return {};
  const auto pair = [&](int a, int b) {
    const double d = distance_m[a][b];
    return std::isfinite(d) ? d : first_leg_m[a] + first_leg_m[b];
  };
  // rest[S][i]: the shortest path that starts at i (in S) and visits all of S.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const uint32_t all = (1u << n) - 1;
  std::vector<double> rest(static_cast<size_t>(all + 1) * n, kInf);
  for (uint32_t s = 1; s <= all; ++s) {
    for (int i = 0; i < n; ++i) {
      if (!(s & (1u << i))) continue;
      const uint32_t others = s & ~(1u << i);
      double best = others == 0 ? 0.0 : kInf;
      for (int j = 0; j < n; ++j) {
        if (others & (1u << j)) best = std::min(best, pair(i, j) + rest[others * n + j]);
      }
      rest[s * n + i] = best;
    }
  }
  std::vector<double> lengths(n);
  for (int i = 0; i < n; ++i) lengths[i] = first_leg_m[i] + rest[all * n + i];
  return lengths;
}

}  // namespace scout::explore
