#ifndef SCOUT_SLAM_CONSTRAINT_BUILDER_H_
#define SCOUT_SLAM_CONSTRAINT_BUILDER_H_

#include <atomic>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/slam/ceres_scan_matcher.h"
#include "scout/slam/fast_correlative_scan_matcher.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/pose_graph_types.h"

namespace scout::slam {

// Loop-closure search settings (ALGORITHMS §7, Cartographer's 2D defaults).
struct ConstraintBuilderOptions {
  // Fraction of the eligible (node, submap) pairs that are searched, per
  // submap. Searching every pair would cost too much; nearby pairs overlap
  // heavily, so a fraction still finds the loop. Cartographer uses 0.3; on the
  // fr079 bag 0.05 gave the same trajectory (ATE 0.086 vs 0.088 m at 0.1) with
  // a sixth of the searches, which dominate the cost of SLAM.
  double sampling_ratio = 0.05;
  // Shifts which pairs that fraction picks, in [0, 1): a submap's first
  // sampled pair comes up to 1 / sampling_ratio pairs later. The loop
  // closures of a long run depend on which pairs were searched, and a
  // closure more or less can move a map by metres; replaying one dataset at
  // several phases shows how much a result owes to the sampling rather than
  // to a setting. 0 = Cartographer's sampler.
  double sampling_phase = 0.0;
  // A pair the ratio skips is searched anyway when the node is this much
  // trajectory away from the last node searched against that submap (0 =
  // ratio only). With 0.2 m between scans the ratio alone searches about
  // every 4 m; logs with one scan per metre would get a search every 20 m,
  // which on the Radish logs found no loop closure at all.
  double max_sample_spacing_m = 4.0;
  // Pairs whose estimated node position is farther than this from the
  // submap's origin are not searched.
  double max_constraint_distance_m = 15.0;
  // Branch-and-bound matches scoring below this (mean cell probability) are
  // rejected as not the same place.
  double min_score = 0.55;
  // Submaps built from few scans hold low probabilities (a hit moves a cell
  // from 0.5 to 0.55 only): the scans a submap was built from score about
  // 0.6 in it on the Radish logs (one scan per metre), against 0.78 on the
  // Freiburg 079 bag and 0.81-0.87 in the simulated worlds, so a fixed
  // min_score rejects the true matches of such submaps. With this fraction
  // f > 0, a submap accepts matches scoring at least min(min_score, f * the
  // mean score of its own scans' points at their own poses); submaps whose own
  // scans score min_score / f (0.69) or more are unchanged. Radish logs with
  // injected odometry noise, seeds 1-3: fhw ATE 0.32 / 0.44 / 0.27 m ->
  // 0.22 / 0.25 / 0.27 m, csail seed 3 0.23 -> 0.20 m, the others within
  // 0.01 m. The ambiguity margin of such a submap shrinks by its contrast,
  // (own score - 0.5) / (min_score / f - 0.5): a match and its rivals differ
  // less where walls stand out less from undecided cells (then csail seed 2
  // 0.76 -> 0.50 m, orebro seed 2 0.33 -> 0.15 m, the others within 0.03 m).
  // 0 = min_score and the margin everywhere.
  double min_score_fraction_of_own_scans = 0.8;
  // Overlap gate: a pair is searched only if at least this fraction of the
  // node's points, placed at the current estimate, falls on cells the submap
  // has observed. A node that does not overlap the submap can only match it
  // by accident: in the simulated office, 170 of 199 wrong closures (off by
  // 2-8 m) came from such pairs, and only 1 of 14 right ones. The gate is
  // loose (0.3) because drift lowers the overlap of true revisits: at 0.7
  // the pose-graph test's loop stayed open. 0 disables.
  double min_overlap = 0.3;
  // Free-space check: an accepted match is rejected when more than this
  // fraction of its rays crosses an occupied cell of the submap (p >= 0.6)
  // more than see_through_slack_m before the ray's end: the scan would see
  // through walls the submap knows. 1 disables.
  double max_see_through = 0.12;
  double see_through_slack_m = 0.15;
  // Translation window of the branch-and-bound search, from the prior: the
  // pose of a node relative to a submap can be wrong by no more than the
  // drift over the trajectory between them, so the window is
  // min_search_window_m + search_window_per_travel * (that trajectory's
  // length), at most fast_correlative_scan_matcher.linear_search_window_m.
  // A full 7 m window lets periodic buildings (rooms of equal width along a
  // corridor) close loops one room off: in the simulated office the wrong
  // pose scored 0.88 against the true pose's 0.69, so no test on the scan
  // alone can reject it. search_window_per_travel = 0: always the full window.
  double min_search_window_m = 1.0;
  double search_window_per_travel = 0.02;
  // The angular window likewise: min_angular_search_window_deg +
  // angular_search_window_deg_per_m * travel, at most
  // fast_correlative_scan_matcher.angular_search_window_rad (same switch:
  // search_window_per_travel = 0 searches the full windows). Closures 11-19
  // degrees off slipped through a fixed 30 degree window in the office.
  double min_angular_search_window_deg = 5.0;
  double angular_search_window_deg_per_m = 0.1;
  // Nodes with fewer points (after the loop-closure voxel filter) are not
  // searched: 3 points match anywhere with a high score (seen in the office
  // when the lidar faces open space beyond its range).
  int min_num_points = 50;
  // Wide ambiguity test: a match more than wide_ambiguity_min_innovation_m
  // from the estimate is searched again, centred on itself, in a window of
  // wide_ambiguity_window_factor times that distance (at most
  // wide_ambiguity_max_window_m), and rejected unless it is again the one
  // unambiguous best. The ambiguity test above only sees rivals inside the
  // search window; when drift has put the estimate metres off, the window can
  // hold a copy of the place (the hall next door) but not the place itself.
  // A window three times the distance reaches back past the estimate by twice
  // it. Simulated museum, seed 1, to 5300 s: closures 12 m off had bent the
  // map to ATE 4.04 m (coverage 0.84); with the test 0.23 m (0.92), and 0.33 m
  // with a factor of 2. Office seeds 2-5, the fr079 bag and the Radish logs
  // are unchanged; office seed 1 0.059 -> 0.067 m. 0 = off.
  double wide_ambiguity_min_innovation_m = 2.0;
  double wide_ambiguity_window_factor = 3.0;
  double wide_ambiguity_max_window_m = 14.0;
  // Near matches: the search accepts matches from
  // near_match_min_score_fraction times the submap's minimum score, and one
  // below the minimum is kept only if it lands within
  // near_match_max_innovation_m of the estimate (it must still be the one
  // unambiguous best in the whole window, now against rivals down to the
  // lower score). The score alone cannot tell a revisit from a look-alike,
  // but where the best match lands can: on the Radish logs with injected
  // odometry noise (seeds 1-2, every search's best pose checked against the
  // corrected poses), of the best poses scoring 0.7-1.0 times the minimum,
  // those within 0.3 m of the estimate were mostly right (about 1,280 of
  // 1,470) and those more than 1 m away almost all wrong (5 of 1,869 right).
  // fr079 bag ATE 0.0793 -> 0.0737 m (over sampling phases 0, 0.25, 0.5,
  // 0.75: mean 0.085 -> 0.079 m); freiburg-079 log seeds 1-12 better in 10,
  // median 0.080 -> 0.075 m; the other Radish logs mixed (runs within
  // 0.15 m: 68 -> 67 of 96). 0 = off.
  double near_match_max_innovation_m = 0.3;
  double near_match_min_score_fraction = 0.75;
  // Weights of accepted loop closures in the pose adjustment.
  double loop_closure_translation_weight = 1.1e4;
  double loop_closure_rotation_weight = 1e5;
  // Window 7 m / 30 degrees, depth 7.
  FastCorrelativeScanMatcherOptions fast_correlative_scan_matcher;
  // The refinement after branch and bound. Weaker priors than local SLAM's:
  // the prior here is the branch-and-bound result, only one cell accurate,
  // so the grid should dominate.
  // Unknown scores the minimum here: a loop closure must sit on walls the
  // submap has seen.
  CeresScanMatcherOptions ceres_scan_matcher{.occupied_space_weight = 20.0,
                                             .translation_weight = 10.0,
                                             .rotation_weight = 1.0,
                                             .max_num_iterations = 10,
                                             .unknown_probability = 0.1,
                                             .likelihood_field = {}};  // probabilities
};

// Throws std::invalid_argument naming the option when one is out of range.
void Validate(const ConstraintBuilderOptions& options);

// Returns true on a deterministic fraction 'ratio' of calls: the n-th call
// says yes when that keeps the yes-count at or above ratio * n - phase
// (phase in [0, 1) delays the first yes). Runs are therefore reproducible,
// unlike random sampling.
class FixedRatioSampler {
 public:
  explicit FixedRatioSampler(double ratio, double phase = 0.0) : ratio_(ratio), phase_(phase) {}
  bool Pulse();

 private:
  double ratio_;
  double phase_;
  long num_pulses_ = 0;
  long num_samples_ = 0;
};

// A scan inserted into a submap: its points (robot frame) and its pose in the
// submap frame.
struct SubmapScan {
  geometry::Rigid2d pose_in_submap;
  std::shared_ptr<const PointCloud> points;
};

// Finds loop-closure constraints between nodes (scans) and finished submaps.
// Not thread-safe, except that Search may run for several pairs at once (it
// only reads the matchers): one thread (the pose graph's worker) drives it.
class ConstraintBuilder {
 public:
  // Throws std::invalid_argument if 'options' are invalid.
  explicit ConstraintBuilder(const ConstraintBuilderOptions& options);

  // Registers the final grid of a finished submap (submap frame) and
  // precomputes its branch-and-bound matcher, kept for all later searches.
  // 'own_scans', the scans inserted into it, set its acceptance threshold
  // (min_score_fraction_of_own_scans); without them it is min_score.
  void AddFinishedSubmap(int submap_id, std::shared_ptr<const grid::ProbabilityGrid> grid,
                         const std::vector<SubmapScan>& own_scans = {});
  // The score a match in submap 'submap_id' must reach, and the margin of its
  // ambiguity test (the options' before the submap was added).
  double MinScore(int submap_id) const;
  double AmbiguityScoreMargin(int submap_id) const;
  bool HasSubmap(int submap_id) const { return submaps_.count(submap_id) > 0; }

  // Returns true if the pair (node, 'submap_id') should be searched: the
  // estimated node pose in the submap frame is within max_constraint_distance,
  // the node's 'points' overlap the submap (min_overlap) and the submap's
  // sampler fires, or the node ('node_travel_m' along the trajectory) is
  // max_sample_spacing_m from the last node searched against the submap.
  // Advances that sampler only for pairs passing the first two.
  bool ShouldSearch(int submap_id, const geometry::Rigid2d& initial_relative_pose,
                    const PointCloud& points, double node_travel_m);

  // How one search ended, for the loop-closure log.
  struct SearchReport {
    // kAccepted when a constraint was returned (the pose graph may drop it
    // later); never kDropped here.
    LoopClosureOutcome outcome = LoopClosureOutcome::kNoMatch;
    // The match (refined once it got that far; the best of an ambiguous
    // search), where the search found one.
    std::optional<geometry::Rigid2d> match;
    double score = std::numeric_limits<double>::quiet_NaN();      // its branch-and-bound score
    double min_score = std::numeric_limits<double>::quiet_NaN();  // the submap's
    double search_window_m = 0.0;  // half width of the translation window
    bool near = false;             // accepted as a near match
  };

  // Searches node 'node_id' ('points' in the node's robot frame) in the
  // finished submap 'submap_id' around 'initial_relative_pose' (node in
  // submap frame) and returns the loop closure if one scores >= min_score
  // (or is a near match, near_match_max_innovation_m). 'travel_m' is the
  // length of the trajectory between the node and the submap, which sizes
  // the search window. A match whose translation is more than
  // 'max_innovation_m' from 'initial_relative_pose' is rejected (counted by
  // num_gated). How the search ended goes to 'report' if given. Throws
  // std::invalid_argument if the submap was not added.
  std::optional<Constraint> Search(
      int submap_id, int node_id, const geometry::Rigid2d& initial_relative_pose,
      const PointCloud& points, double travel_m,
      double max_innovation_m = std::numeric_limits<double>::infinity(),
      SearchReport* report = nullptr);
  // The translation window searched for a node 'travel_m' of trajectory away.
  double SearchWindow(double travel_m) const;
  // The angular window (radians) searched for a node 'travel_m' away.
  double AngularSearchWindow(double travel_m) const;

  // Pairs searched, loop closures found, pairs skipped for lack of overlap,
  // searches without a match above the minimum score, ambiguous matches (a
  // pose ambiguity_radius_m or more away scores within the margin), matches
  // rejected by the free-space check, by the wide ambiguity test and by the
  // innovation gate, so far. Every search ends in exactly one of: without a
  // match, ambiguous, gated, wide ambiguous, seeing through, found.
  int num_searches() const { return num_searches_; }
  int num_constraints_found() const { return num_found_; }
  // Of those, near matches: below min_score, near the estimate
  // (near_match_max_innovation_m).
  int num_near_matches() const { return num_near_matches_; }
  int num_without_match() const { return num_without_match_; }
  int num_ambiguous() const { return num_ambiguous_; }
  int num_without_overlap() const { return num_without_overlap_; }
  int num_seeing_through() const { return num_seeing_through_; }
  int num_wide_ambiguous() const { return num_wide_ambiguous_; }
  int num_gated() const { return num_gated_; }

 private:
  struct SubmapMatcher {
    std::shared_ptr<const grid::ProbabilityGrid> grid;
    std::unique_ptr<FastCorrelativeScanMatcher> matcher;
    FixedRatioSampler sampler;
    std::optional<double> last_searched_travel_m;
    double min_score = 0.0;
  };

  ConstraintBuilderOptions options_;
  CeresScanMatcher ceres_scan_matcher_;
  std::map<int, SubmapMatcher> submaps_;
  std::atomic<int> num_searches_ = 0;  // counted by concurrent searches
  std::atomic<int> num_found_ = 0;
  std::atomic<int> num_without_overlap_ = 0;  // read by stats while searches run
  std::atomic<int> num_without_match_ = 0;
  std::atomic<int> num_near_matches_ = 0;
  std::atomic<int> num_ambiguous_ = 0;
  std::atomic<int> num_seeing_through_ = 0;
  std::atomic<int> num_wide_ambiguous_ = 0;
  std::atomic<int> num_gated_ = 0;
};

// The branch-and-bound score of 'points' (scan frame) placed by 'pose' (scan
// -> grid frame) in 'grid': the mean probability of their cells, unknown
// cells and the outside counting as the minimum probability. 0 for no points.
double MatchScore(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                  const PointCloud& points);

// Fraction of 'points' (scan frame) that, placed by 'pose' (scan -> grid
// frame), fall on observed cells of 'grid'.
double ObservedFraction(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                        const PointCloud& points);

// Fraction of the rays from 'pose' to 'points' that cross a cell of 'grid'
// with probability >= 0.6 more than 'slack_m' before reaching their point.
double SeeThroughFraction(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                          const PointCloud& points, double slack_m);

}  // namespace scout::slam

#endif  // SCOUT_SLAM_CONSTRAINT_BUILDER_H_
