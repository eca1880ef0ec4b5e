#ifndef SCOUT_IO_SCAN_CONSISTENCY_H_
#define SCOUT_IO_SCAN_CONSISTENCY_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::io {

// How well the scans of a trajectory agree with each other where they see the
// same walls, measured without any reference: a trajectory whose poses are
// off by a fraction of a degree smears every wall it maps. For each scan
// after the first 'previous_scans', its returns are placed by their pose and
// each is paired with the nearest return of the 'previous_scans' scans before
// it; pairs farther apart than 'max_distance_m' (a wall the earlier scans did
// not see) are left out. The result is the mean pair distance of each scan,
// averaged over the scans. Local, like a relative pose error over the time of
// 'previous_scans' scans, but it also grades a reference trajectory: on the
// Freiburg 079 bag Scout's trajectory measures 12.3 mm and the corrected log
// used as its reference 16.2 mm.
struct ScanConsistencyOptions {
  int previous_scans = 10;
  double max_distance_m = 0.3;
};

struct ScanConsistency {
  double mean_distance_m = 0.0;  // NaN when no scan had a pair
  int scans = 0;                 // scans that had at least one pair
};

// 'points[i]' are the returns of the scan taken at 'poses[i]', in the sensor
// frame; both in trajectory order. Throws std::invalid_argument if the sizes
// differ or an option is out of range (previous_scans >= 1, max_distance_m > 0).
ScanConsistency MeasureScanConsistency(const std::vector<std::vector<Eigen::Vector2d>>& points,
                                       const std::vector<geometry::Rigid2d>& poses,
                                       const ScanConsistencyOptions& options = {});

}  // namespace scout::io

#endif  // SCOUT_IO_SCAN_CONSISTENCY_H_
