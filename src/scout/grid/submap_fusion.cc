#include "scout/grid/submap_fusion.h"

#include <cmath>

#include "scout/geometry/box.h"
#include "scout/grid/probability_values.h"

namespace scout::grid {
namespace {

// Log-odds of every stored value, computed once: a std::log per cell and
// submap was most of the fusion's time (the loop fuses at 1 Hz).
const std::vector<float>& LogOddsTable() {
  static const std::vector<float> table = [] {
    std::vector<float> t(kMaxValue + 1, 0.f);
    for (int v = 1; v <= kMaxValue; ++v) {
      const float p = ValueToProbability(static_cast<uint16_t>(v));
      t[v] = std::log(p / (1.f - p));
    }
    return t;
  }();
  return table;
}

}  // namespace

OccupancyMap FuseSubmaps(const std::vector<PlacedGrid>& submaps, double resolution_m) {
  geometry::Box2d bounds;
  for (const PlacedGrid& s : submaps) {
    const geometry::Box2d b = geometry::TransformBox(s.global_pose, s.grid->limits().Bounds());
    if (b.empty()) continue;
    bounds.Extend(b.min);
    bounds.Extend(b.max);
  }
  OccupancyMap fused;
  if (bounds.empty()) return fused;
  const Eigen::Vector2d origin(std::floor(bounds.min.x() / resolution_m) * resolution_m,
                               std::floor(bounds.min.y() / resolution_m) * resolution_m);
  const int width = static_cast<int>(std::ceil((bounds.max.x() - origin.x()) / resolution_m));
  const int height = static_cast<int>(std::ceil((bounds.max.y() - origin.y()) / resolution_m));
  fused.limits = MapLimits(resolution_m, origin, width, height);
  const std::vector<float>& log_odds_of = LogOddsTable();
  std::vector<float> log_odds(fused.limits.num_cells(), 0.f);
  std::vector<uint8_t> known(fused.limits.num_cells(), 0);
  for (const PlacedGrid& s : submaps) {
    const geometry::Box2d b = geometry::TransformBox(s.global_pose, s.grid->limits().Bounds());
    if (b.empty()) continue;
    const CellIndex lo = fused.limits.CellContaining(b.min);
    const CellIndex hi = fused.limits.CellContaining(b.max);
    const geometry::Rigid2d to_submap = s.global_pose.inverse();
    for (int y = std::max(lo.y, 0); y <= std::min(hi.y, height - 1); ++y) {
      for (int x = std::max(lo.x, 0); x <= std::min(hi.x, width - 1); ++x) {
        const CellIndex c{x, y};
        const CellIndex sc =
            s.grid->limits().CellContaining(to_submap * fused.limits.CellCenter(c));
        const uint16_t value = s.grid->value(sc);
        if (value == kUnknownValue) continue;
        const int64_t flat = fused.limits.FlatIndex(c);
        log_odds[flat] += log_odds_of[value];
        known[flat] = 1;
      }
    }
  }
  fused.cells.assign(fused.limits.num_cells(), CellState::kUnknown);
  for (int64_t flat = 0; flat < fused.limits.num_cells(); ++flat) {
    if (!known[flat]) continue;
    fused.cells[flat] = log_odds[flat] < 0.f   ? CellState::kFree
                        : log_odds[flat] > 0.f ? CellState::kOccupied
                                               : CellState::kUnknown;
  }
  return fused;
}

}  // namespace scout::grid
