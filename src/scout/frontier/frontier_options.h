#ifndef SCOUT_FRONTIER_FRONTIER_OPTIONS_H_
#define SCOUT_FRONTIER_FRONTIER_OPTIONS_H_

namespace scout::frontier {

// Every tunable number of the frontier engine; defaults from ALGORITHMS.md §2–4.
struct FrontierOptions {
  // Cells within this distance of an occupied cell are blocked for the robot
  // (robot radius 0.20 m + safety 0.20 m).
  double inflation_radius_m = 0.40;
  // bfs/direct: a submap counts as moved when |dx| or |dy| exceeds epsilon, or
  // |dtheta| exceeds epsilon / (2 pi R) (paper eq. 3).
  double epsilon_m = 0.05;
  // R of paper eq. 3: the lidar's range.
  double lidar_range_m = 8.0;
  // exact: a pair of submaps is re-anchored (all points re-checked) once their
  // relative pose moved any point by this much since the last anchoring.
  // Larger values keep more per-point margins in memory and re-anchor less.
  double exact_slack_m = 0.5;
  // Grid changes (one per scan insertion) are held, and only the newest grid
  // of each changed submap is processed when the frontier is next needed (an
  // optimisation event, or FrontierEngine::Flush()). Local frontier extraction
  // then runs once per batch instead of once per scan, and the result at every
  // flush is the same as processing each change. false processes every change
  // as it arrives.
  bool defer_grid_changes = true;
};

// Throws scout::InputError naming the field when an option is out of range.
void Validate(const FrontierOptions& options);

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_FRONTIER_OPTIONS_H_
