#include "scout/grid/range_data_inserter.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "scout/geometry/box.h"

namespace scout::grid {
namespace {

// Amanatides & Woo traversal of the segment start -> end: calls 'visit' for
// every cell the segment passes through, in order, starting with start's cell,
// ending with end's cell only if 'include_end'. The number of steps is fixed by
// the end cell, so rounding can never make the walk miss its end. Where the
// segment passes exactly through a cell corner it steps x first, also visiting
// one of the two cells it merely touches there (a cell-connected walk).
template <typename Visit>
void TraverseSegment(const MapLimits& limits, const Eigen::Vector2d& start,
                     const Eigen::Vector2d& end, bool include_end, Visit&& visit) {
  // Grid coordinates are computed exactly as in MapLimits::CellContaining, so
  // their floors agree with the start and end cells.
  const double res = limits.resolution();
  const double sx = (start.x() - limits.origin().x()) / res;
  const double sy = (start.y() - limits.origin().y()) / res;
  const double dx = (end.x() - limits.origin().x()) / res - sx;
  const double dy = (end.y() - limits.origin().y()) / res - sy;
  CellIndex cell = limits.CellContaining(start);
  const CellIndex last = limits.CellContaining(end);

  const int step_x = last.x > cell.x ? 1 : (last.x < cell.x ? -1 : 0);
  const int step_y = last.y > cell.y ? 1 : (last.y < cell.y ? -1 : 0);
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // t in [0, 1] along the segment at which the next x (y) cell border is crossed,
  // and the t between two consecutive x (y) borders.
  double t_max_x = kNever, t_delta_x = kNever, t_max_y = kNever, t_delta_y = kNever;
  if (step_x != 0) {
    t_max_x = (step_x > 0 ? cell.x + 1 - sx : sx - cell.x) / std::abs(dx);
    t_delta_x = 1.0 / std::abs(dx);
  }
  if (step_y != 0) {
    t_max_y = (step_y > 0 ? cell.y + 1 - sy : sy - cell.y) / std::abs(dy);
    t_delta_y = 1.0 / std::abs(dy);
  }

  for (int remaining = std::abs(last.x - cell.x) + std::abs(last.y - cell.y); remaining > 0;
       --remaining) {
    visit(cell);
    const bool x_done = cell.x == last.x;
    const bool y_done = cell.y == last.y;
    if (y_done || (!x_done && t_max_x <= t_max_y)) {
      cell.x += step_x;
      t_max_x += t_delta_x;
    } else {
      cell.y += step_y;
      t_max_y += t_delta_y;
    }
  }
  if (include_end) visit(cell);
}

}  // namespace

RangeDataInserter::RangeDataInserter(const RangeDataInserterOptions& options) {
  if (!(options.hit_probability > 0.5 && options.hit_probability < 1.0)) {
    throw std::invalid_argument("RangeDataInserter: hit_probability must be in (0.5, 1)");
  }
  if (!(options.miss_probability > 0.0 && options.miss_probability < 0.5)) {
    throw std::invalid_argument("RangeDataInserter: miss_probability must be in (0, 0.5)");
  }
  hit_table_ = ComputeLookupTableToApplyOdds(Odds(static_cast<float>(options.hit_probability)));
  miss_table_ = ComputeLookupTableToApplyOdds(Odds(static_cast<float>(options.miss_probability)));
}

void RangeDataInserter::Insert(const Eigen::Vector2d& origin,
                               const std::vector<Eigen::Vector2d>& returns,
                               const std::vector<Eigen::Vector2d>& misses,
                               ProbabilityGrid* grid) const {
  if (grid == nullptr) throw std::invalid_argument("RangeDataInserter::Insert: grid is null");
  // Grow once to the bounding box of the scan rather than per point: each growth
  // copies the grid.
  geometry::Box2d box;
  // Checked per point: min/max would silently drop a NaN.
  const auto extend = [&box](const Eigen::Vector2d& p) {
    if (!p.allFinite()) {
      throw std::invalid_argument("RangeDataInserter::Insert: points must be finite");
    }
    box.Extend(p);
  };
  extend(origin);
  for (const Eigen::Vector2d& p : returns) extend(p);
  for (const Eigen::Vector2d& p : misses) extend(p);
  grid->GrowToInclude(box.min);
  grid->GrowToInclude(box.max);

  const MapLimits& limits = grid->limits();
  // Hits first: once marked, a return cell ignores the misses of other rays.
  for (const Eigen::Vector2d& hit : returns) {
    grid->ApplyLookupTable(limits.CellContaining(hit), hit_table_);
  }
  const auto apply_miss = [&](const CellIndex& cell) { grid->ApplyLookupTable(cell, miss_table_); };
  for (const Eigen::Vector2d& hit : returns) {
    TraverseSegment(limits, origin, hit, /*include_end=*/false, apply_miss);
  }
  for (const Eigen::Vector2d& miss : misses) {
    TraverseSegment(limits, origin, miss, /*include_end=*/true, apply_miss);
  }
  grid->FinishUpdate();
}

}  // namespace scout::grid
