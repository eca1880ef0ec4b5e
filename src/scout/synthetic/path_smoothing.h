#ifndef SCOUT_SYNTHETIC_PATH_SMOOTHING_H_
#define SCOUT_SYNTHETIC_PATH_SMOOTHING_H_

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace scout::synthetic {

// Returns 'path' with as many intermediate points dropped as possible:
// greedily from each kept point to the farthest later point that is at most
// 'max_shortcut_m' away and visible, i.e. 'is_clear(p)' holds at every
// 'check_step_m' along the straight segment. First and last points are kept.
std::vector<Eigen::Vector2d> ShortcutPath(
    const std::vector<Eigen::Vector2d>& path,
    const std::function<bool(const Eigen::Vector2d&)>& is_clear, double max_shortcut_m,
    double check_step_m);

// Returns 'path' split into segments of at most 'spacing_m', then rounded by
// 'iterations' passes of Chaikin corner cutting (end points stay fixed).
std::vector<Eigen::Vector2d> RoundCorners(const std::vector<Eigen::Vector2d>& path,
                                          double spacing_m, int iterations);

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_PATH_SMOOTHING_H_
