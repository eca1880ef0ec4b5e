#ifndef SCOUT_SIM_BOX_UTIL_H_
#define SCOUT_SIM_BOX_UTIL_H_

#include <functional>
#include <random>
#include <vector>

#include "scout/geometry/box.h"

// Helpers shared by the generated worlds (internal to sim).
namespace scout::sim {

// A closed interval [lo, hi] along one axis, metres.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  // Returns hi - lo.
  double length() const { return hi - lo; }
};

// Returns the Euclidean distance between two boxes (0 if they touch or overlap).
double BoxDistance(const geometry::Box2d& a, const geometry::Box2d& b);

// Returns true if the open interiors of 'a' and 'b' overlap.
bool BoxesOverlap(const geometry::Box2d& a, const geometry::Box2d& b);

// Splits [lo, hi] into consecutive clear intervals of length in
// [min_length, max_length] (as far as the total allows) separated by walls of
// thickness 'wall_m'. The first starts at lo, the last ends at hi.
std::vector<Interval> SplitIntoSpaces(double lo, double hi, double wall_m, double min_length,
                                      double max_length, std::mt19937_64& rng);

// Same, with the separator after each space drawn by 'next_separator_m' (called
// once per separator, in order, before the space in front of it is drawn).
std::vector<Interval> SplitIntoSpaces(double lo, double hi,
                                      const std::function<double()>& next_separator_m,
                                      double min_length, double max_length, std::mt19937_64& rng);

// Returns the box [x.lo, x.hi] x [y.lo, y.hi].
geometry::Box2d MakeBox(const Interval& x, const Interval& y);

}  // namespace scout::sim

#endif  // SCOUT_SIM_BOX_UTIL_H_
