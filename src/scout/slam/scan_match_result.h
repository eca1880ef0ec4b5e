#ifndef SCOUT_SLAM_SCAN_MATCH_RESULT_H_
#define SCOUT_SLAM_SCAN_MATCH_RESULT_H_

#include "scout/geometry/rigid_transform.h"

namespace scout::slam {

// A scan matcher's answer: the pose of the scan in the grid's frame and the
// matcher's score of it (higher is better; see each matcher for its scale).
struct ScanMatchResult {
  geometry::Rigid2d pose;
  double score = 0.0;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_SCAN_MATCH_RESULT_H_
