#include "scout/sim/box_util.h"

#include <algorithm>
#include <cmath>

#include "scout/sim/random.h"

namespace scout::sim {

double BoxDistance(const geometry::Box2d& a, const geometry::Box2d& b) {
  const double dx = std::max({0.0, a.min.x() - b.max.x(), b.min.x() - a.max.x()});
  const double dy = std::max({0.0, a.min.y() - b.max.y(), b.min.y() - a.max.y()});
  return std::hypot(dx, dy);
}

bool BoxesOverlap(const geometry::Box2d& a, const geometry::Box2d& b) {
  return a.min.x() < b.max.x() && b.min.x() < a.max.x() && a.min.y() < b.max.y() &&
         b.min.y() < a.max.y();
}

std::vector<Interval> SplitIntoSpaces(double lo, double hi, double wall_m, double min_length,
                                      double max_length, std::mt19937_64& rng) {
  return SplitIntoSpaces(
      lo, hi, [wall_m] { return wall_m; }, min_length, max_length, rng);
}

std::vector<Interval> SplitIntoSpaces(double lo, double hi,
                                      const std::function<double()>& next_separator_m,
                                      double min_length, double max_length, std::mt19937_64& rng) {
  std::vector<Interval> spaces;
  double start = lo;
  // Keep drawing while what is left cannot be one space of at most max_length.
  while (hi - start > max_length) {
    const double rest = hi - start;
    const double separator_m = next_separator_m();
    // Leave room for the separator and at least one more space of min_length.
    const double upper = std::min(max_length, rest - separator_m - min_length);
    const double length =
        upper >= min_length ? UniformReal(rng, min_length, upper) : 0.5 * (rest - separator_m);
    spaces.push_back({start, start + length});
    start += length + separator_m;
  }
  spaces.push_back({start, hi});
  return spaces;
}

geometry::Box2d MakeBox(const Interval& x, const Interval& y) {
  return geometry::Box2d(Eigen::Vector2d(x.lo, y.lo), Eigen::Vector2d(x.hi, y.hi));
}

}  // namespace scout::sim
