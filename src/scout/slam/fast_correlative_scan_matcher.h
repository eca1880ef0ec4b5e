#ifndef SCOUT_SLAM_FAST_CORRELATIVE_SCAN_MATCHER_H_
#define SCOUT_SLAM_FAST_CORRELATIVE_SCAN_MATCHER_H_

#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/map_limits.h"
#include "scout/grid/probability_grid.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/scan_match_result.h"

namespace scout::slam {

struct FastCorrelativeScanMatcherOptions {
  // Half-width of the square of translations searched (ALGORITHMS §7: 7 m).
  double linear_search_window_m = 7.0;
  // Half-width of the interval of rotations searched (ALGORITHMS §7: 30°).
  double angular_search_window_rad = 30.0 * std::numbers::pi / 180.0;
  // Number of precomputed grids; the coarsest pools 2^(depth-1) cells (ALGORITHMS §7: 7).
  int branch_and_bound_depth = 7;
  // Ambiguity test: a match is rejected when a candidate farther than
  // ambiguity_radius_m from it scores within ambiguity_score_margin of it.
  // Corridors and rows of identical rooms otherwise produce confident loop
  // closures metres off along the corridor (measured in the simulated
  // office: doors and rooms repeating along a corridor). 0 disables the test.
  double ambiguity_radius_m = 0.3;
  double ambiguity_score_margin = 0.05;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const FastCorrelativeScanMatcherOptions& options);

// Returns the angular step of the correlative search: the rotation that moves
// a point at 'max_range_m' by about one cell of 'resolution_m' (Hess et al.
// 2016, eq. 7). Used by both correlative matchers.
double AngularSearchStep(double max_range_m, double resolution_m);

// Branch-and-bound correlative scan matcher (Hess et al. 2016, section V.C),
// for loop closure. The discrete candidate set around an initial estimate
// (t0, θ0) is: angles θ0 + k·δθ, |k| <= ceil(window_rad / δθ), δθ =
// AngularSearchStep(largest point range, resolution); for each angle the
// points are placed by Rigid2d(t0, θ0 + k·δθ) and discretized to their
// cells, then shifted by (i, j) cells, |i|, |j| <= ceil(window_m / resolution).
// A candidate's score is the mean probability of its points' cells, where an
// unknown cell (or one outside the grid) counts as kMinProbability: unexplored
// space must not look like a match. The result is exactly the best candidate
// of that set (an exhaustive search would find the same score).
class FastCorrelativeScanMatcher {
 public:
  // Precomputes the max-pooled grids of 'grid' and keeps 'grid' itself as the
  // finest level (shared, not copied: the caller usually keeps it anyway).
  // Throws std::invalid_argument on invalid options or a null grid.
  FastCorrelativeScanMatcher(std::shared_ptr<const grid::ProbabilityGrid> grid,
                             const FastCorrelativeScanMatcherOptions& options);
  // As above with a copy of 'grid' ('grid' need not outlive this).
  FastCorrelativeScanMatcher(const grid::ProbabilityGrid& grid,
                             const FastCorrelativeScanMatcherOptions& options);

  // Best pose (grid frame) of 'points' (given in the scan frame) within the
  // window around 'initial_pose_estimate', score = mean probability of the
  // points' cells; nullopt if best score < min_score (or 'points' is empty)
  // or if the match is ambiguous (see FastCorrelativeScanMatcherOptions).
  std::optional<ScanMatchResult> Match(const geometry::Rigid2d& initial_pose_estimate,
                                       const PointCloud& points, double min_score) const;
  // As Match with the windows given instead of the options'. With
  // 'ambiguous', an ambiguous match (nullopt returned) goes there: the caller
  // can tell it from no match and still see the best pose.
  std::optional<ScanMatchResult> Match(const geometry::Rigid2d& initial_pose_estimate,
                                       const PointCloud& points, double min_score,
                                       double linear_window_m, double angular_window_rad,
                                       std::optional<ScanMatchResult>* ambiguous = nullptr) const;

  // As Match, but searching every rotation and every translation that keeps
  // the grid's centre within the window centred on it (global localisation).
  std::optional<ScanMatchResult> MatchFullSubmap(const PointCloud& points, double min_score) const;

  const grid::MapLimits& limits() const { return limits_; }
  const FastCorrelativeScanMatcherOptions& options() const { return options_; }

 private:
  // Level d holds, for every cell c, the max raw value over the cells
  // [c.x, c.x + 2^d) x [c.y, c.y + 2^d) of the grid; cells are offset by
  // 2^d - 1 so that windows reaching into the grid from below are stored too.
  // Level 0 is the grid itself, so leaves score exactly. Levels
  // >= 1 only bound scores from above, and a byte per cell does (rounded up
  // to 1/255 of the value range): half the memory of 16 bits, and the coarse
  // levels, read most often, stay in cache better.
  template <typename T>
  struct PrecomputedGrid {
    int offset = 0;  // 2^d - 1
    int width = 0;
    int height = 0;
    std::vector<T> values;
  };
  // Per angle: the scan's cells at the initial translation and their bounds.
  struct DiscreteScan {
    std::vector<grid::CellIndex> cells;
    int min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    // Per depth, the cells as flat indices into that level (see SumCells),
    // made by the first score there that lies wholly inside it.
    mutable std::vector<std::vector<int32_t>> flat_cells;
  };
  struct Candidate;

  // Candidates whose translation offset lies within 'radius' cells of
  // ('x', 'y') are not taken as answers.
  struct Exclusion {
    int x = 0, y = 0;
    double radius = 0.0;
  };

  std::optional<ScanMatchResult> Search(const geometry::Rigid2d& initial_pose_estimate,
                                        const PointCloud& points, double linear_window_m,
                                        double angular_window_rad, double min_score,
                                        bool check_ambiguity,
                                        std::optional<ScanMatchResult>* ambiguous = nullptr) const;

  FastCorrelativeScanMatcherOptions options_;
  grid::MapLimits limits_;
  // Sum of the raw values under 'scan' shifted by (x, y) cells at 'depth', in
  // level 0 units (an upper bound at depth >= 1, exact at depth 0).
  int64_t Score(int depth, const DiscreteScan& scan, int x, int y) const;

  std::shared_ptr<const grid::ProbabilityGrid> grid_;  // level 0, read as is
  std::vector<PrecomputedGrid<uint8_t>> coarse_;       // coarse_[d - 1] is level d
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_FAST_CORRELATIVE_SCAN_MATCHER_H_
