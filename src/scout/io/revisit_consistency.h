#ifndef SCOUT_IO_REVISIT_CONSISTENCY_H_
#define SCOUT_IO_REVISIT_CONSISTENCY_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::io {

// How well a trajectory agrees with itself where it comes back to a place it
// saw long before (a loop), measured without any reference. The local
// measure (scan_consistency.h) compares each scan with the few scans before
// it, so a loop closed ten centimetres off, or a corridor drawn twice side by
// side, passes it; here each scan is compared with the scans of the earlier
// visit. On the Radish aces log (seed 1, injected odometry noise) Scout's
// trajectory measured 69 mm and the corrected log's 48 mm, where locally it
// was the other way round (36 against 38 mm).
struct RevisitOptions {
  double min_separation_s = 30.0;  // an earlier visit is at least this much older ...
  double max_distance_m = 1.0;     // ... and its pose this close ...
  double max_turn_deg = 45.0;      // ... and this close in heading (the scans overlap)
  int max_earlier_scans = 5;       // at most this many earlier scans, the nearest
};

// For each scan, the earlier scans it revisits by 'poses' (indices into
// 'poses', nearest first; empty: none). 'times_s[i]' is scan i's time.
// Throws std::invalid_argument if the sizes differ or an option is out of
// range (min_separation_s >= 0, max_distance_m > 0, max_turn_deg >= 0,
// max_earlier_scans >= 1).
std::vector<std::vector<int>> FindRevisits(const std::vector<geometry::Rigid2d>& poses,
                                           const std::vector<double>& times_s,
                                           const RevisitOptions& options = {});

// Per scan, the earlier scans either list names (ascending). Grading two
// trajectories (an estimate and its reference) on the union keeps either
// from passing by not finding its own revisits: a map drawn twice puts the
// two visits of a place metres apart, and only the other trajectory pairs
// them. Throws std::invalid_argument if the sizes differ.
std::vector<std::vector<int>> MergeRevisits(const std::vector<std::vector<int>>& a,
                                            const std::vector<std::vector<int>>& b);

struct RevisitConsistency {
  // Over the scans with revisits: the mean, per scan, of the distance from
  // each return to the nearest return of its earlier scans, pairs farther
  // apart than max_distance_m left out (NaN when no scan had a pair) ...
  double mean_distance_m = 0.0;
  // ... and the fraction of their returns that had a pair (NaN without
  // revisits): two visits placed farther apart than max_distance_m show
  // here, not in the mean.
  double paired_fraction = 0.0;
  int scans = 0;  // scans with revisits
};

// 'points[i]' are the returns of scan i in the sensor frame, 'poses[i]' its
// pose, 'revisits' as FindRevisits returns. Throws std::invalid_argument if
// the sizes differ, an index is out of range or max_distance_m <= 0.
RevisitConsistency MeasureRevisitConsistency(
    const std::vector<std::vector<Eigen::Vector2d>>& points,
    const std::vector<geometry::Rigid2d>& poses, const std::vector<std::vector<int>>& revisits,
    double max_distance_m = 0.3);

}  // namespace scout::io

#endif  // SCOUT_IO_REVISIT_CONSISTENCY_H_
