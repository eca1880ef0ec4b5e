#ifndef SCOUT_SYNTHETIC_CORRECTION_MODEL_H_
#define SCOUT_SYNTHETIC_CORRECTION_MODEL_H_

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/synthetic/loop_closure_detector.h"

namespace scout::synthetic {

// How the synthetic SLAM's pose estimates err and get corrected. The submap
// grids themselves are exact (built from true relative poses, as Cartographer
// assumes its submaps are); only the poses carry error:
//
// 1. Local SLAM drift. The local SLAM frame drifts from the truth like
//    odometry: every motion between two scans adds an independent error at the
//    robot (translation along both axes, rotation about the robot), with
//    variance growing linearly with the distance driven and the angle turned,
//    i.e. a random walk whose standard deviation grows with the square root
//    of the motion. A new submap's local pose is its true pose seen through the
//    drifted local frame. Local poses are never corrected (as in Cartographer).
//
// 2. New submaps in the global frame. A submap created between two solves is
//    placed in the global frame by the local-to-global transform of the newest
//    submap of the last solve (what a SLAM front end does): it inherits that
//    submap's residual error plus the drift since.
//
// The error of a submap is the rigid transform from its true pose to its
// estimate, in its own frame; corrections shrink it along the screw motion
// (ScaleMotion), so they move a submap straight towards its true pose.
//
// 3. Every solve (each optimize_every_n_scans scans) nudges the recent
//    submaps, most of all the newest: a submap of age a (0 = newest) loses the
//    fraction newest_pull_fraction * pull_decay_per_submap^a of its error, as
//    scan matching against the map already built constrains it, and gets
//    Gaussian jitter of standard deviation newest_jitter_* *
//    pull_decay_per_submap^a, as an iterative solver never lands on exactly
//    the same optimum. Submaps whose expected move (pull plus jitter) is below
//    min_nudge_m and min_nudge_rad are left exactly where they are, as old
//    submaps are by a converged solver.
//
// 4. Loop closures. When the true trajectory since the last solve came within
//    loop_closure_distance_m of a scan of a submap at least
//    min_loop_closure_age_submaps older than the newest and created at least
//    min_loop_closure_travel_m of driving earlier, the next solve closes
//    the loop with the oldest such submap A: the error accumulated along the
//    loop is taken out, interpolated along the chain. A submap between A and
//    the newest submap C loses the fraction f of its error, f growing
//    linearly with the distance driven from A to its creation (f = 1 for C),
//    and gets constraint noise of f * loop_closure_error_*. A and older
//    submaps stay put, so C's pose relative to A ends up off by about A's
//    own remaining error.
//
// All units: metres, radians; "per sqrt m" is the standard deviation after
// 1 m of motion.
struct CorrectionModelOptions {
  // Drift standard deviation, per axis, after 1 m driven (10 m: ~1 %).
  double drift_translation_m_per_sqrt_m = 0.03;
  // Heading drift standard deviation after 1 m driven (10 m: ~0.5 degree).
  double drift_heading_rad_per_sqrt_m = 0.0028;
  // Heading drift standard deviation after turning 1 rad on the spot
  // (a full turn: ~0.7 degree).
  double drift_heading_rad_per_sqrt_rad = 0.005;
  // Fraction of its error the newest submap loses in a solve.
  double newest_pull_fraction = 0.5;
  // Factor per submap of age on the pull fraction and the jitter.
  double pull_decay_per_submap = 0.5;
  // Jitter of the newest submap in a solve (standard deviations).
  double newest_jitter_m = 0.003;
  double newest_jitter_rad = 0.0005;
  // Submaps whose expected move in a solve is below both of these do not move.
  double min_nudge_m = 1e-5;
  double min_nudge_rad = 1e-6;
  // A loop closes when the robot comes this close to a scan of an old submap.
  double loop_closure_distance_m = 3.0;
  // ...of a submap at least this many submaps older than the newest...
  int min_loop_closure_age_submaps = 5;
  // ...and created at least this much driving ago (shorter returns, e.g.
  // turning round in a room, are ordinary overlap, handled by the nudges).
  double min_loop_closure_travel_m = 20.0;
  // Error of the loop-closure constraint (standard deviations, at C).
  double loop_closure_error_m = 0.01;
  double loop_closure_error_rad = 0.002;
  // Scan positions kept per submap for loop detection are this far apart.
  double loop_closure_sample_spacing_m = 0.5;
};

// The pose estimates of a synthetic submap SLAM, given the true poses.
// Throws InputError naming the first bad option ("corrections.<key>").
void Validate(const CorrectionModelOptions& options);

class CorrectionModel {
 public:
  // Throws InputError naming the option if 'options' is invalid.
  CorrectionModel(const CorrectionModelOptions& options, uint64_t seed);

  // Drifts the local SLAM frame by the error of the true motion 'from' -> 'to'.
  void Move(const geometry::Rigid2d& from, const geometry::Rigid2d& to);

  // Adds the next submap, whose frame has true pose 'true_pose', created after
  // 'travelled_m' metres of trajectory. Returns its local pose (submap frame
  // -> local SLAM frame).
  geometry::Rigid2d AddSubmap(const geometry::Rigid2d& true_pose, double travelled_m);

  // Records a scan at true position 'position', taken after 'travelled_m' of
  // trajectory and inserted into 'submap_ids'.
  void AddScan(const Eigen::Vector2d& position, double travelled_m,
               const std::vector<int>& submap_ids);

  // Runs one solve. Returns true if it closed a loop.
  bool Optimize();

  // Global pose estimate (submap frame -> global frame) of every submap.
  const std::vector<geometry::Rigid2d>& global_poses() const { return global_; }
  // The current transform from true poses to local SLAM poses (world frame).
  const geometry::Rigid2d& drift() const { return drift_; }

 private:
  void CloseLoop(int oldest, int newest);
  // The error of submap 'id': true pose^-1 * estimated global pose.
  geometry::Rigid2d ErrorOf(int id) const;
  void NudgeRecent(int newest);

  CorrectionModelOptions options_;
  std::mt19937_64 rng_;
  geometry::Rigid2d drift_;
  std::vector<geometry::Rigid2d> true_;
  std::vector<geometry::Rigid2d> local_;
  std::vector<geometry::Rigid2d> global_;
  std::vector<double> travelled_m_;
  // Newest submap of the last solve (its local-to-global places new submaps).
  int reference_ = -1;
  // Oldest submap the robot came back to since the last solve.
  int loop_candidate_ = -1;
  LoopClosureDetector detector_;
};

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_CORRECTION_MODEL_H_
