#include "scout/grid/submap_fusion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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

// Narrows the column offsets [*first, *last] of a row to those whose submap
// coordinate start + i * step can lie in [0, limit). Conservative by a slack
// far above rounding error: the per-cell test stays the only judge, this
// only skips the cells of the bounding box that lie outside the rotated grid.
void NarrowToInside(double start, double step, int limit, int* first, int* last) {
  if (step == 0.0) return;
  constexpr double kSlackCells = 1e-3;
  const double at_low = (-kSlackCells - start) / step;
  const double at_high = (limit + kSlackCells - start) / step;
  const double from = std::ceil(std::min(at_low, at_high)) - 2.0;
  const double to = std::floor(std::max(at_low, at_high)) + 2.0;
  if (from > *first) *first = from > *last ? *last + 1 : static_cast<int>(from);
  if (to < *last) *last = to < *first ? *first - 1 : static_cast<int>(to);
}

// The union of the submaps' boxes in the global frame.
geometry::Box2d SubmapBounds(const std::vector<PlacedGrid>& submaps) {
  geometry::Box2d bounds;
  for (const PlacedGrid& s : submaps) {
    const geometry::Box2d b = geometry::TransformBox(s.global_pose, s.grid->limits().Bounds());
    if (b.empty()) continue;
    bounds.Extend(b.min);
    bounds.Extend(b.max);
  }
  return bounds;
}

// The lattice cells covering 'bounds' at 'resolution_m', in doubles (the
// counts may be far beyond ints): the first column and row, the columns and
// rows.
struct LatticeExtent {
  double x0, y0, width, height;
};
LatticeExtent ExtentOf(const geometry::Box2d& bounds, double resolution_m) {
  const double kx = std::floor(bounds.min.x() / resolution_m);
  const double ky = std::floor(bounds.min.y() / resolution_m);
  return {kx, ky, std::ceil((bounds.max.x() - kx * resolution_m) / resolution_m),
          std::ceil((bounds.max.y() - ky * resolution_m) / resolution_m)};
}

}  // namespace

namespace fusion {

LatticeRect LatticeRect::United(const LatticeRect& o) const {
  if (o.empty()) return *this;
  if (empty()) return o;
  const int nx0 = std::min(x0, o.x0);
  const int ny0 = std::min(y0, o.y0);
  return {nx0, ny0, std::max(x1(), o.x1()) - nx0, std::max(y1(), o.y1()) - ny0};
}

LatticeRect LatticeRect::Intersected(const LatticeRect& o) const {
  const int nx0 = std::max(x0, o.x0);
  const int ny0 = std::max(y0, o.y0);
  const int nx1 = std::min(x1(), o.x1());
  const int ny1 = std::min(y1(), o.y1());
  if (nx1 <= nx0 || ny1 <= ny0) return {};
  return {nx0, ny0, nx1 - nx0, ny1 - ny0};
}

void LogOddsSums::Reset(const LatticeRect& r) {
  const int64_t cells = r.empty() ? 0 : static_cast<int64_t>(r.width) * r.height;
  if (cells > kMaxFusedCells) {
    throw std::length_error("fusing submaps: a map of " + std::to_string(r.width) + " x " +
                            std::to_string(r.height) + " cells is beyond the limit of " +
                            std::to_string(kMaxFusedCells) +
                            " (the submaps lie that far apart: has SLAM diverged?)");
  }
  rect = r;
  const size_t n = static_cast<size_t>(cells);
  log_odds.assign(n, 0.f);
  known.assign(n, 0);
}

LatticeRect SubmapCells(const PlacedGrid& submap, double resolution_m) {
  const geometry::Box2d b =
      geometry::TransformBox(submap.global_pose, submap.grid->limits().Bounds());
  if (b.empty()) return {};
  const int x0 = static_cast<int>(std::floor(b.min.x() / resolution_m));
  const int y0 = static_cast<int>(std::floor(b.min.y() / resolution_m));
  const int x1 = static_cast<int>(std::floor(b.max.x() / resolution_m));
  const int y1 = static_cast<int>(std::floor(b.max.y() / resolution_m));
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

MapLimits FusedLimits(const std::vector<PlacedGrid>& submaps, double resolution_m,
                      LatticeRect* lattice) {
  const geometry::Box2d bounds = SubmapBounds(submaps);
  *lattice = {};
  if (bounds.empty()) return MapLimits();
  const LatticeExtent e = ExtentOf(bounds, resolution_m);
  // Lattice indices are ints: beyond them (or with a non-finite pose) no map
  // can be made at this resolution.
  constexpr double kMaxIndex = 1 << 30;
  if (!(std::abs(e.x0) < kMaxIndex && std::abs(e.y0) < kMaxIndex && e.width < kMaxIndex &&
        e.height < kMaxIndex)) {
    throw std::length_error("fusing submaps: they span beyond " + std::to_string(1 << 30) +
                            " cells of " + std::to_string(resolution_m) +
                            " m or lie at a non-finite pose (has SLAM diverged?)");
  }
  *lattice = {static_cast<int>(e.x0), static_cast<int>(e.y0), static_cast<int>(e.width),
              static_cast<int>(e.height)};
  return MapLimits(resolution_m, {e.x0 * resolution_m, e.y0 * resolution_m}, lattice->width,
                   lattice->height);
}

void AddSubmap(const PlacedGrid& submap, double resolution_m, const LatticeRect& clip,
               LogOddsSums* sums) {
  const LatticeRect cells = SubmapCells(submap, resolution_m);
  const LatticeRect todo = cells.Intersected(clip);
  const MapLimits& limits = submap.grid->limits();
  if (todo.empty() || limits.num_cells() == 0) return;
  const int width = limits.width();
  const int height = limits.height();
  const double submap_resolution = limits.resolution();
  const std::vector<uint16_t>& values = submap.grid->values();
  const std::vector<float>& log_odds_of = LogOddsTable();
  const geometry::Rigid2d to_submap = submap.global_pose.inverse();
  // Submap coordinates in cells (from its min corner) are affine in the
  // lattice column: one multiply-add per cell instead of a full transform.
  const Eigen::Vector2d step = to_submap.Rotate({resolution_m, 0.0}) / submap_resolution;
  // A centre on a submap cell edge belongs to the cell above it, as cells are
  // half-open. Exact ties are common (a submap half a cell off the lattice,
  // e.g. in the world frame of a start at x.x25 m) and rounding alone would
  // decide them, differently for each way of computing the coordinate. The
  // nudge is far above that rounding error and far below any real offset.
  constexpr double kEdgeNudgeCells = 1e-10;
  for (int y = todo.y0; y < todo.y1(); ++y) {
    // Anchored at the submap's own first column, never the clip's, so a
    // cell's submap coordinates (hence its value) depend only on (x, y).
    const Eigen::Vector2d start =
        (to_submap * Eigen::Vector2d((cells.x0 + 0.5) * resolution_m, (y + 0.5) * resolution_m) -
         limits.origin()) /
            submap_resolution +
        Eigen::Vector2d::Constant(kEdgeNudgeCells);
    int first = todo.x0 - cells.x0;
    int last = todo.x1() - 1 - cells.x0;
    NarrowToInside(start.x(), step.x(), width, &first, &last);
    NarrowToInside(start.y(), step.y(), height, &first, &last);
    if (first > last) continue;
    const int64_t row = sums->Index(cells.x0, y);
    for (int i = first; i <= last; ++i) {
      const double u = start.x() + i * step.x();
      const double v = start.y() + i * step.y();
      // Truncation equals floor on [0, limit), the only range that is read.
      if (!(u >= 0.0 && u < width && v >= 0.0 && v < height)) continue;
      const uint16_t value =
          values[static_cast<size_t>(static_cast<int>(v)) * width + static_cast<int>(u)] &
          kMaxValue;
      if (value == kUnknownValue) continue;
      sums->log_odds[row + i] += log_odds_of[value];
      sums->known[row + i] = 1;
    }
  }
}

}  // namespace fusion

double ResolutionWithin(const std::vector<PlacedGrid>& submaps, double resolution_m,
                        int64_t max_cells) {
  if (!(resolution_m > 0.0) || max_cells < 1) {
    throw std::invalid_argument("ResolutionWithin: resolution and max_cells must be positive");
  }
  const geometry::Box2d bounds = SubmapBounds(submaps);
  if (bounds.empty()) return resolution_m;
  if (!bounds.min.allFinite() || !bounds.max.allFinite()) {
    throw std::length_error("fusing submaps: a submap lies at a non-finite pose");
  }
  const auto cells = [&](double r) {
    const LatticeExtent e = ExtentOf(bounds, r);
    return e.width * e.height;
  };
  double r = resolution_m;
  while (cells(r) > static_cast<double>(max_cells)) r *= 2.0;
  return r;
}

OccupancyMap FuseSubmaps(const std::vector<PlacedGrid>& submaps, double resolution_m) {
  OccupancyMap fused;
  fusion::LatticeRect lattice;
  fused.limits = fusion::FusedLimits(submaps, resolution_m, &lattice);
  if (lattice.empty()) return fused;
  fusion::LogOddsSums sums;
  sums.Reset(lattice);
  for (const PlacedGrid& s : submaps) fusion::AddSubmap(s, resolution_m, lattice, &sums);
  fused.cells.resize(sums.log_odds.size());
  for (size_t i = 0; i < sums.log_odds.size(); ++i) {
    fused.cells[i] = fusion::FusedState(sums.log_odds[i], sums.known[i] != 0);
  }
  return fused;
}

}  // namespace scout::grid
