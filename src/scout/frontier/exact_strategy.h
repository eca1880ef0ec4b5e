#ifndef SCOUT_FRONTIER_EXACT_STRATEGY_H_
#define SCOUT_FRONTIER_EXACT_STRATEGY_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "scout/frontier/update_strategy.h"
#include "scout/geometry/box.h"

namespace scout::frontier {

// "exact" (Scout's own): after an optimisation, re-queries only the points
// whose answer can have changed, so its answers always equal "full".
//
// Why it is exact. A point p of submap i is a global frontier iff no other
// submap j objects at q_j = T_j^-1 T_i p (outside j's grid nobody objects, so
// the R-tree only filters). Each j's answer at q_j depends only on the relative
// pose T_j^-1 T_i. For every ordered pair (i, j) whose boxes meet, a *watch*
// remembers, per point, the position q_ref where j's answer was last looked up,
// that answer, and j's margin there (AnswerMap::Margin: every position closer
// than it has the same answer). While |q_j - q_ref| < margin the answer cannot
// have changed. Points far from every other-answer cell (margin >= slack S)
// are not stored; they are covered as long as no point of i moved by S in j's
// frame since the watch was anchored, which one bound per pair proves
// (geometry::MaxDisplacementWithin). Each entry keeps a key that lower-bounds
// its margin left after the pair's motion since the key anchor, so one pass
// over the keys, without lookups or transforms, finds the few entries that
// need an exact check (none if the bound is below the smallest key). A pair whose
// boxes do not meet has no point of i inside j's grid, so nothing objects.
//
// Witnesses. A point that is not a frontier needs one objecting submap, not
// all answers (most points are covered several times over): each such point
// keeps one *witness* j, whose watch holds an objecting entry for it, and only
// that watch has to track it. The watches of the other submaps track only the
// frontier points. When the witness stops objecting, every watch of the
// point's submap is asked at the current poses: the first that objects becomes
// the witness; if none does, the point is a frontier and every watch stores or
// covers it as above. So re-anchoring a pair looks up the frontier points and
// the points it witnesses, not all of them.
//
// Grid changes re-anchor the watches of the changed submap (its answers and its
// points changed); their lookups are counted in the grid-change cost.
class ExactStrategy : public UpdateStrategy {
 public:
  using UpdateStrategy::UpdateStrategy;
  std::string_view name() const override { return "exact"; }
  UpdateCost OnSubmapChanged(const SubmapChange& change) override;
  UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) override;

  // Number of stored per-point margins over all watches (memory diagnostics).
  int64_t num_entries() const;

 private:
  // j's answer at q_ref is not kept: it stays until the margin is left, and
  // what it decides is in witness_ (objecting made j the point's witness).
  struct Entry {
    float key_m;         // lower bound of the margin relative to the key anchor
    float ref_margin_m;  // margin of j at q_ref
    float ref_x_m;       // q_ref, in j's frame
    float ref_y_m;
    uint32_t point;  // index of the point in submap i
  };
  struct Watch {
    int j = -1;
    geometry::Rigid2d coverage_anchor;  // relative pose when all points were looked up
    geometry::Rigid2d key_anchor;       // relative pose the entry keys refer to
    Eigen::Vector2d center = Eigen::Vector2d::Zero();      // disc holding coverage_anchor * p
    Eigen::Vector2d key_center = Eigen::Vector2d::Zero();  // the same disc under key_anchor
    double radius_m = 0.0;
    std::vector<Entry> entries;
    // Per point of i: whether 'entries' holds one for it (never two: a point
    // that loses its witness and is added again keeps its entry). Bits: the
    // watches' points add up to hundreds of millions in a 200 m world.
    std::vector<bool> has_entry;
    float min_key_m = 0.0f;  // no entry's key is smaller
    // Pose versions of i and j when the watch was last brought up to date:
    // while neither submap moves, the watch needs no work.
    uint64_t seen_version_i = 0;
    uint64_t seen_version_j = 0;
  };

  geometry::Rigid2d Relative(int i, int j) const;
  // Looks up every point of i in j at the current poses.
  void Anchor(int i, Watch* watch);
  // Brings one watch up to date with the current poses.
  void Refresh(int i, Watch* watch);
  // Calls visit(entry) for every entry of the watch whose point it still
  // tracks and drops the others (another submap became their witness), so
  // passes and checks do not grow with the run.
  template <typename Visit>
  void PassOverTracked(int i, Watch* watch, const Visit& visit);
  // Looks up point k of i in the watch's submap and stores an entry unless the
  // slack covers it (objecting answers are always stored).
  void AddEntry(int i, uint32_t k, Watch* watch, double slack_m);
  // Whether the watch on j must track point k of i: k is a frontier or j is
  // its witness.
  bool Tracks(int i, uint32_t k, int j) const {
    return witness_[i][k] == kNoWitness || witness_[i][k] == j;
  }
  // Records that j now answers 'objects' for point k of i: a frontier point
  // gets j as its witness; a point whose witness j stopped objecting is queued
  // for ResolveLost.
  void Observe(int i, uint32_t k, int j, bool objects);
  // Finds a new witness for every queued point of i, or makes it a frontier
  // tracked by every watch. Called where no watch's entries are being iterated.
  void ResolveLost(int i);
  // A disc centred at the mean of submap i's points that holds them
  // all, in i's frame (cached until i's points change).
  struct PointsDisc {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    double radius_m = 0.0;
    bool valid = false;
  };
  const PointsDisc& DiscOf(int i);
  // Stored margins are capped (a smaller margin is always safe), which bounds
  // how far from a grid change a watch can be affected.
  double MarginCap() const { return 2.0 * catalog_.options().exact_slack_m; }
  // Looks up point p (at q in the watch's submap) again and stores the result
  // in 'entry', keyed against the watch's key anchor.
  void Reevaluate(int i, Watch& watch, const AnswerMap& answers, const Eigen::Vector2d& p,
                  const Eigen::Vector2d& q, Entry* entry);
  // After the watch's submap changed its answers inside 'region' (its frame):
  // re-checks every point whose recorded margin reaches into the region.
  void ReviewNearChange(int i, Watch* watch, const geometry::Box2d& region);
  void EnsureSize(int num_submaps);
  // Recomputes the keys for the current relative pose (no lookups).
  void Rekey(int i, Watch* watch);
  Watch* FindWatch(int i, int j);
  // After a grid change of 'change.id': keeps the entries of its surviving
  // points (the other submaps did not change), drops vanished points and looks
  // up new ones, in every watch of its points.
  void RemapOwnWatches(const SubmapChange& change);
  // Creates and anchors the watch of submap i's points on submap j.
  void AddWatch(int i, int j);
  // Creates watches for every submap whose box meets i's points and refreshes
  // the existing ones.
  void UpdateWatchesOf(int i);
  void Mark(int i, uint32_t k);
  void BeginUpdate();
  UpdateCost EndUpdate(double time_us);

  std::vector<std::vector<Watch>> watches_;  // by submap i (whose points are watched)
  std::vector<std::vector<int>> watchers_;   // by submap j: every i with a watch on j
  std::vector<uint8_t> watched_;  // scratch of UpdateWatchesOf and OnSubmapChanged, 0 between calls
  // Per point: the submap whose watch holds an objecting entry for it,
  // kNoWitness for a global frontier, kLost while queued in lost_.
  static constexpr int32_t kNoWitness = -1;
  static constexpr int32_t kLost = -2;
  std::vector<std::vector<int32_t>> witness_;
  std::vector<PointsDisc> discs_;  // by submap
  // What each submap looked like to the last optimisation round: a submap
  // whose pose, grid box and points box are all unchanged since, and none of
  // whose neighbours changed, has nothing to update (see OnOptimized).
  struct SeenPlacement {
    uint64_t pose_version = 0;
    geometry::Box2d box;
    geometry::Box2d points_box;
    bool valid = false;
  };
  std::vector<SeenPlacement> seen_;
  std::vector<uint8_t> affected_;  // scratch of OnOptimized
  std::vector<uint32_t> lost_;     // points (of the submap being updated) without a witness
  // Distinct points / submaps touched in the current update.
  std::vector<std::vector<uint32_t>> point_stamp_;
  std::vector<uint32_t> submap_stamp_;
  uint32_t stamp_ = 0;
  UpdateCost pending_;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_EXACT_STRATEGY_H_
