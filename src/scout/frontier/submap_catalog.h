#ifndef SCOUT_FRONTIER_SUBMAP_CATALOG_H_
#define SCOUT_FRONTIER_SUBMAP_CATALOG_H_

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/frontier/answer_map.h"
#include "scout/frontier/frontier_options.h"
#include "scout/frontier/local_frontiers.h"
#include "scout/frontier/submap_index.h"
#include "scout/geometry/box.h"

namespace scout::frontier {

// Everything the update strategies share about one submap.
struct SubmapRecord {
  std::shared_ptr<const grid::ProbabilityGrid> grid;
  AnswerMap answers;
  geometry::Rigid2d local_pose;
  geometry::Rigid2d global_pose;
  geometry::Rigid2d global_pose_inverse;
  // Incremented whenever global_pose changes (0 before it is first set).
  uint64_t pose_version = 0;
  // Global box of the grid (slightly inflated so rounding never drops a cell).
  geometry::Box2d global_box;
  LocalFrontier frontier;
  // Box of the frontier points in the submap frame (empty without points).
  geometry::Box2d local_points_box;
  bool finished = false;
  // The origin (a cell corner) of the submap's first grid: all later grids
  // share its lattice of cells.
  Eigen::Vector2d lattice_corner = Eigen::Vector2d::Zero();
};

// What applying one SubmapChanged did.
struct SubmapChange {
  int id = 0;
  bool is_new = false;
  // For every frontier point after the change: its index before, or -1 if new.
  std::vector<int> previous_index;
  // Cells whose stabbing answer changed, as a box in the submap frame (empty if none).
  geometry::Box2d changed_region;
  // The submap's answer map before the change (empty limits for a new submap).
  AnswerMap previous_answers;
};

// The state shared by all update strategies: submap grids, answer maps, local
// frontiers, current global poses and the R-tree over global boxes. It applies
// events; strategies then bring their own answers up to date.
class SubmapCatalog {
 public:
  explicit SubmapCatalog(const FrontierOptions& options);

  // Applies a grid change: recomputes the submap's answer map and reachable
  // local frontier. A new submap (id == size()) is placed globally by the
  // current local-to-global transform. Throws InputError for an id that is
  // neither existing nor the next one, or a missing grid.
  SubmapChange Apply(const events::SubmapChanged& event);
  // Applies new global poses; returns the poses before. Submaps the event does
  // not cover (created after the solve began) follow the new local-to-global
  // transform. Throws InputError if it names more submaps than exist.
  std::vector<geometry::Rigid2d> Apply(const events::Optimized& event);

  int size() const { return static_cast<int>(submaps_.size()); }
  const SubmapRecord& submap(int id) const { return submaps_[id]; }
  const SubmapIndex& index() const { return index_; }
  const FrontierOptions& options() const { return options_; }
  std::vector<geometry::Rigid2d> GlobalPoses() const;

  // Returns the global position of point 'p' of submap 'i'.
  Eigen::Vector2d GlobalPosition(int i, const Eigen::Vector2d& p) const {
    return submaps_[i].global_pose * p;
  }
  // Returns where the global position 'global' lies in submap 'j''s frame.
  Eigen::Vector2d GlobalInSubmap(const Eigen::Vector2d& global, int j) const {
    return submaps_[j].global_pose_inverse * global;
  }
  // Returns where point 'p' of submap 'i' lies in submap 'j''s frame. Every
  // strategy computes positions through this function (or the two above, in
  // the same order), so all of them look up bit-identical positions.
  Eigen::Vector2d PointInSubmap(int i, const Eigen::Vector2d& p, int j) const {
    return GlobalInSubmap(GlobalPosition(i, p), j);
  }
  // Returns the global box of submap 'i''s frontier points.
  geometry::Box2d GlobalPointsBox(int i) const;
  // Total local frontier points over all submaps.
  int64_t total_points() const;

 private:
  void SetGlobalPose(int id, const geometry::Rigid2d& pose);

  FrontierOptions options_;
  std::vector<SubmapRecord> submaps_;
  SubmapIndex index_;
  geometry::Rigid2d local_to_global_;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_SUBMAP_CATALOG_H_
