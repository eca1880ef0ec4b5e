#include "scout/frontier/answer_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scout/frontier/local_frontiers.h"
#include "scout/grid/distance_transform.h"

namespace scout::frontier {
namespace {

using grid::CellIndex;

// Cells within this many cells (Chebyshev) of a query's cell are checked one by
// one for an exact margin; beyond, the distance transform bounds the margin.
constexpr int kWindowRadius = 2;

// Distance from 'q' to the closed axis-aligned square [lo, hi], if it is below
// 'bound'; otherwise some value >= 'bound'. Both shortcuts return the exact
// one-sided distance. The root is not std::hypot, whose guard against
// overflow metres do not need (it held 1-1.6 % of a 200 m frontier-bench
// profile's samples); it is still never below the larger side, as
// sqrt(fl(a * a)) == |a| and the sum of squares rounds to no less than
// either square.
double DistanceToSquareBelow(const Eigen::Vector2d& q, const Eigen::Vector2d& lo,
                             const Eigen::Vector2d& hi, double bound) {
  const double dx = std::max({lo.x() - q.x(), 0.0, q.x() - hi.x()});
  const double dy = std::max({lo.y() - q.y(), 0.0, q.y() - hi.y()});
  if (dx == 0.0) return dy;
  if (dy == 0.0) return dx;
  if (std::max(dx, dy) >= bound) return bound;
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

AnswerMap::AnswerMap(const std::vector<grid::CellState>& states, const grid::MapLimits& limits,
                     const Eigen::Vector2d& lattice_corner)
    : limits_(limits),
      lattice_corner_(lattice_corner),
      lattice_offset_x_(static_cast<int>(
          std::llround((limits.origin().x() - lattice_corner.x()) / limits.resolution()))),
      lattice_offset_y_(static_cast<int>(
          std::llround((limits.origin().y() - lattice_corner.y()) / limits.resolution()))),
      cells_(states.size(), 0) {
  const std::vector<uint8_t> frontier = FrontierCellMask(states, limits);
  std::vector<uint8_t> objecting(states.size(), 0);
  objecting_to_border_m_ = std::numeric_limits<double>::infinity();
  for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
    const bool objects = states[flat] != grid::CellState::kUnknown && !frontier[flat];
    objecting[flat] = objects;
    if (objects) {
      ++num_objecting_;
      const CellIndex c = limits.CellOfFlatIndex(flat);
      const int to_border =
          std::min({c.x, c.y, limits.width() - 1 - c.x, limits.height() - 1 - c.y});
      objecting_to_border_m_ = std::min(objecting_to_border_m_, to_border * limits.resolution());
    }
  }
  // Each cell's distance to the nearest cell with the other answer, bounded
  // from below by one transform: the nearest cell of the other answer always
  // has a 4-neighbour that is not of its answer (the neighbour one step towards
  // the query would otherwise be nearer), so it is a border cell, and the
  // distance to the nearest border cell of either answer is a lower bound.
  const int width = limits.width(), height = limits.height();
  std::vector<uint8_t> border(objecting.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      const uint8_t o = objecting[i];
      border[i] = (x > 0 && objecting[i - 1] != o) || (x + 1 < width && objecting[i + 1] != o) ||
                  (y > 0 && objecting[i - width] != o) ||
                  (y + 1 < height && objecting[i + width] != o);
    }
  }
  const std::vector<float> to_border = grid::SquaredDistanceToNearestSite(border, width, height);
  for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
    const double d = std::sqrt(static_cast<double>(to_border[flat]));
    const double quarters = std::isfinite(d) ? std::floor(4.0 * d) : kDistanceMask;
    cells_[flat] = static_cast<uint8_t>(std::min<double>(quarters, kDistanceMask)) |
                   (objecting[flat] ? kObjectsBit : 0);
  }
}

double AnswerMap::Margin(const Eigen::Vector2d& q) const {
  const CellIndex c = CellContaining(q);
  const double res = limits_.resolution();
  if (!limits_.Contains(c)) {
    // Outside, nothing objects: the nearest objecting cell lies inside, so a
    // path to it crosses the border and then runs at least the objecting
    // cells' distance to the border.
    if (num_objecting_ == 0) return std::numeric_limits<double>::infinity();
    return limits_.Bounds().DistanceTo(q) + objecting_to_border_m_;
  }
  if (num_objecting_ == 0) return std::numeric_limits<double>::infinity();
  const uint8_t cell = cells_[limits_.FlatIndex(c)];
  const bool objects = cell & kObjectsBit;
  const double centre_distance = (cell & kDistanceMask) * 0.25 * res;
  double margin;
  // A cell with the other answer inside the window lies within 2*sqrt(2) cells
  // (centre to centre); when the transform says farther, the window holds none.
  if (centre_distance > (kWindowRadius * std::sqrt(2.0) + 0.01) * res) {
    // Any other-answer square is at least (centre distance - |q - centre| -
    // half a diagonal) away.
    margin = centre_distance - (q - limits_.CellCenter(c)).norm() - res * std::sqrt(0.5);
  } else {
    margin = WindowMargin(q, c, objects);
  }
  if (objects) {
    // Outside the grid nobody objects: the border is another answer.
    const geometry::Box2d bounds = limits_.Bounds();
    margin = std::min({margin, q.x() - bounds.min.x(), bounds.max.x() - q.x(),
                       q.y() - bounds.min.y(), bounds.max.y() - q.y()});
  }
  return std::max(0.0, margin);
}

double AnswerMap::WindowMargin(const Eigen::Vector2d& q, const CellIndex& c, bool objects) const {
  const double res = limits_.resolution();
  // Squares of the cells within Chebyshev distance 'ring' of c, and every
  // square beyond them, lie at least the distance from q to the edge of that
  // block of cells.
  const auto distance_to_block_edge = [&](int ring) {
    const Eigen::Vector2d lo = limits_.CellCenter({c.x - ring, c.y - ring}).array() - 0.5 * res;
    const Eigen::Vector2d hi = limits_.CellCenter({c.x + ring, c.y + ring}).array() + 0.5 * res;
    return std::min({q.x() - lo.x(), hi.x() - q.x(), q.y() - lo.y(), hi.y() - q.y()});
  };
  // Beyond the window, any cell is at least the distance from q to the window's edge.
  double margin = distance_to_block_edge(kWindowRadius);
  // Ring by ring from the inside: once the margin is no larger than the
  // distance to the next ring's inner edge, no cell of that ring or beyond can
  // lower it, so the result equals scanning the whole window (up to the
  // rounding of the block's edge against the cells' own squares, far below
  // the exact strategy's safety distance).
  for (int ring = 1; ring <= kWindowRadius; ++ring) {
    if (margin <= distance_to_block_edge(ring - 1)) break;
    for (int dy = -ring; dy <= ring; ++dy) {
      const bool edge_row = dy == -ring || dy == ring;
      for (int dx = -ring; dx <= ring; dx += edge_row ? 1 : 2 * ring) {
        const CellIndex n{c.x + dx, c.y + dy};
        if (ObjectsAtCell(n) == objects) continue;
        const Eigen::Vector2d centre = limits_.CellCenter(n);
        margin = std::min(margin, DistanceToSquareBelow(q, centre.array() - 0.5 * res,
                                                        centre.array() + 0.5 * res, margin));
      }
    }
  }
  return margin;
}

}  // namespace scout::frontier
