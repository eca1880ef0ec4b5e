#ifndef SCOUT_IO_TRAJECTORY_ASSOCIATION_H_
#define SCOUT_IO_TRAJECTORY_ASSOCIATION_H_

#include <optional>
#include <utility>
#include <vector>

#include "scout/io/trajectory.h"
#include "scout/io/trajectory_metrics.h"

namespace scout::io {

// Pairs every estimate pose with the reference pose nearest to it in time,
// when that one is at most 'max_dt_s' away (both in the same time base). A
// reference pose may serve several estimate poses. The pairs carry the
// estimate's time and come in estimate order. Inputs need not be sorted.
std::vector<PosePair> AssociateByTime(const std::vector<StampedPose>& estimate,
                                      const std::vector<StampedPose>& reference, double max_dt_s);

// Pairs every estimate pose with the reference pose of the same index (node
// id), where there is one; the pairs carry the estimate's time, in order.
std::vector<PosePair> PairByIndex(const std::vector<StampedPose>& estimate,
                                  const std::vector<std::optional<geometry::Rigid2d>>& reference);

// Finds the scans two recordings of the same run share, when their time bases
// differ (a raw ROS bag and a corrected CARMEN log of it): two scans are the
// same reading when every common beam agrees within half of 'tolerance_m'
// (plus float32 slack), where 'tolerance_m' is the resolution the coarser
// recording printed ranges with (0.01 m for CARMEN logs). Scans whose beam
// counts differ by one (360 vs 361 beams over 180 degrees) are compared over
// their common leading beams; counts differing by more never match. Ranges
// that are not finite match only non-finite ranges.
//
// Returns index pairs (i in 'a', j in 'b'), strictly increasing in both i and
// j: as many as possible, and among equally many (identical scans while the
// robot stands still) those whose j stays closest to the progression given by
// the unambiguous matches. Candidates come from a hash of the rounded ranges;
// scans whose ranges straddle a rounding boundary are then found by direct
// comparison with the b scans between their matched neighbours.
std::vector<std::pair<int, int>> MatchScansByRanges(const std::vector<std::vector<float>>& a,
                                                    const std::vector<std::vector<float>>& b,
                                                    double tolerance_m);

}  // namespace scout::io

#endif  // SCOUT_IO_TRAJECTORY_ASSOCIATION_H_
