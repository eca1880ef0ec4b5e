#include "scout/sim/office_furniture.h"

#include <optional>

#include "scout/sim/box_util.h"
#include "scout/sim/random.h"

namespace scout::sim {
namespace {

// Pushes [lo, hi] flush against 'bounds' ends it is closer to than 'gap_m'.
// Returns false if it would end up flush against both ends (spanning the room)
// or too close to an end it cannot touch.
bool SnapToWalls(const Interval& bounds, double gap_m, double* lo, double* hi) {
  const double size = *hi - *lo;
  if (*lo - bounds.lo < gap_m) {
    *lo = bounds.lo;
    *hi = bounds.lo + size;
  } else if (bounds.hi - *hi < gap_m) {
    *hi = bounds.hi;
    *lo = bounds.hi - size;
  }
  const double low_gap = *lo - bounds.lo;
  const double high_gap = bounds.hi - *hi;
  const bool low_ok = low_gap == 0.0 || low_gap >= gap_m;
  const bool high_ok = high_gap == 0.0 || high_gap >= gap_m;
  return low_ok && high_ok && !(low_gap == 0.0 && high_gap == 0.0);
}

std::optional<geometry::Box2d> DrawPiece(const OfficeRoom& room, const OfficeWorldOptions& o,
                                         std::mt19937_64& rng) {
  const geometry::Box2d& in = room.interior;
  const double width = UniformReal(rng, o.min_furniture_size_m, o.max_furniture_size_m);
  const double height = UniformReal(rng, o.min_furniture_size_m, o.max_furniture_size_m);
  const double x = UniformReal(rng, in.min.x(), in.max.x() - width);
  const double y = UniformReal(rng, in.min.y(), in.max.y() - height);
  if (x + width > in.max.x() || y + height > in.max.y()) return std::nullopt;
  double x_lo = x, x_hi = x + width, y_lo = y, y_hi = y + height;
  if (!SnapToWalls({in.min.x(), in.max.x()}, o.narrow_gap_m, &x_lo, &x_hi)) return std::nullopt;
  if (!SnapToWalls({in.min.y(), in.max.y()}, o.narrow_gap_m, &y_lo, &y_hi)) return std::nullopt;
  return geometry::Box2d(Eigen::Vector2d(x_lo, y_lo), Eigen::Vector2d(x_hi, y_hi));
}

}  // namespace

std::vector<geometry::Box2d> FurnishRoom(const OfficeRoom& room, const OfficeWorldOptions& o,
                                         std::mt19937_64& rng) {
  const geometry::Box2d keep_clear = room.doorway.Inflated(o.door_clearance_m);
  const int count = UniformInt(rng, o.min_furniture_per_room, o.max_furniture_per_room);
  std::vector<geometry::Box2d> pieces;
  for (int i = 0; i < count; ++i) {
    for (int attempt = 0; attempt < o.furniture_attempts; ++attempt) {
      const std::optional<geometry::Box2d> piece = DrawPiece(room, o, rng);
      if (!piece || BoxesOverlap(*piece, keep_clear)) continue;
      bool clear = true;
      for (const geometry::Box2d& other : pieces) {
        clear = clear && BoxDistance(*piece, other) >= o.narrow_gap_m;
      }
      if (!clear) continue;
      pieces.push_back(*piece);
      break;
    }
  }
  return pieces;
}

}  // namespace scout::sim
