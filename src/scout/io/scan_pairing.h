#ifndef SCOUT_IO_SCAN_PAIRING_H_
#define SCOUT_IO_SCAN_PAIRING_H_

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::io {

// What the local (scan_consistency.h) and the revisit (revisit_consistency.h)
// consistency measures share: scans placed by their poses, and how close one
// scan's returns come to those of other scans.

// 'points[i]' (sensor frame) placed by 'poses[i]'; the sizes must match.
std::vector<std::vector<Eigen::Vector2d>> PlaceScans(
    const std::vector<std::vector<Eigen::Vector2d>>& points,
    const std::vector<geometry::Rigid2d>& poses);

struct ScanPairing {
  double sum_m = 0.0;  // of the pair distances
  int pairs = 0;       // returns of the scan with a pair
};

// Pairs each return of placed scan 'scan' with the nearest return of the
// placed scans 'others'; pairs farther apart than 'max_distance_m' are left
// out. Indices must be valid.
ScanPairing PairWithNearest(const std::vector<std::vector<Eigen::Vector2d>>& placed,
                            const std::vector<size_t>& others, size_t scan, double max_distance_m);

}  // namespace scout::io

#endif  // SCOUT_IO_SCAN_PAIRING_H_
