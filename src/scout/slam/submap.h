#ifndef SCOUT_SLAM_SUBMAP_H_
#define SCOUT_SLAM_SUBMAP_H_

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/range_data_inserter.h"
#include "scout/slam/point_cloud.h"

namespace scout::slam {

struct SubmapOptions {
  // Cell edge of submap grids.
  double resolution_m = 0.05;
  // Scans after which the next submap starts; a submap receives twice this
  // many (ALGORITHMS §7: the paper's 70).
  int num_range_data = 70;
  // ... or once the newer submap's scans span this much travel, whichever
  // comes first (0 = scans only). Sparse logs (one scan per metre) would
  // otherwise make each submap 70 m of corridor, with no loop closure inside.
  double max_travel_m = 15.0;
  // Hit / miss probabilities of scan insertion (ALGORITHMS §7: 0.55 / 0.49).
  grid::RangeDataInserterOptions insertion;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const SubmapOptions& options);

// A submap: a probability grid in its own frame, placed in the local SLAM
// frame at the origin of its first scan (axis aligned, so its cells never
// need rotating to be shown in the local frame).
class Submap {
 public:
  // Starts an empty submap whose frame origin is 'origin' (local frame).
  // Throws std::invalid_argument unless resolution_m > 0.
  Submap(events::SubmapId id, const Eigen::Vector2d& origin, double resolution_m);

  events::SubmapId id() const { return id_; }
  // Submap frame -> local frame.
  const geometry::Rigid2d& local_pose() const { return local_pose_; }
  // Returns an immutable snapshot of the grid. Holding it is cheap until the
  // next insertion, which then copies the grid once (copy-on-write): release
  // snapshots that are no longer needed.
  std::shared_ptr<const grid::ProbabilityGrid> grid() const { return grid_; }
  int num_range_data() const { return static_cast<int>(scan_origins_.size()); }
  // Summed distance between consecutive scan origins.
  double travel_m() const { return travel_m_; }
  bool finished() const { return finished_; }
  // Sensor origin of every inserted scan, in the submap frame.
  const std::vector<Eigen::Vector2d>& scan_origins() const { return scan_origins_; }
  // Number of grid copies insertions had to make because a snapshot was held.
  int num_grid_copies() const { return num_grid_copies_; }

  // Inserts a scan taken at 'origin' with 'returns' and 'misses' (all in the
  // local frame). Throws std::logic_error if the submap is finished.
  void InsertRangeData(const Eigen::Vector2d& origin, const PointCloud& returns,
                       const PointCloud& misses, const grid::RangeDataInserter& inserter);
  // Marks the submap as receiving no further scans.
  void Finish() { finished_ = true; }

  // Returns the event describing the submap's current state.
  events::SubmapChanged ToEvent() const;

 private:
  events::SubmapId id_;
  geometry::Rigid2d local_pose_;
  std::shared_ptr<grid::ProbabilityGrid> grid_;
  std::vector<Eigen::Vector2d> scan_origins_;
  double travel_m_ = 0.0;
  bool finished_ = false;
  int num_grid_copies_ = 0;
};

// The two submaps scans are inserted into (Hess et al. 2016): a newer one
// starts when the newest is half full (num_range_data scans, or max_travel_m
// of travel), and the older one is finished when the newer is half full, so
// consecutive submaps overlap by half and the older always has a well-filled
// grid to match against.
class ActiveSubmaps {
 public:
  // What one insertion did; ids are dense from 0 in creation order.
  struct Insertion {
    // The submaps the scan went into, oldest first (each holds it now).
    std::vector<std::shared_ptr<const Submap>> submaps;
    std::vector<events::SubmapId> created;
    std::vector<events::SubmapId> finished;
  };

  // Throws std::invalid_argument on invalid options.
  explicit ActiveSubmaps(const SubmapOptions& options);

  // Inserts a scan (local frame) taken at 'origin'.
  Insertion InsertRangeData(const Eigen::Vector2d& origin, const PointCloud& returns,
                            const PointCloud& misses);

  // The active submaps, oldest first (empty before the first scan). Scan
  // matching uses the oldest: it has seen the most.
  const std::vector<std::shared_ptr<Submap>>& submaps() const { return submaps_; }
  int num_submaps_created() const { return next_id_; }

 private:
  bool HalfFull(const Submap& submap) const;

  SubmapOptions options_;
  grid::RangeDataInserter inserter_;
  std::vector<std::shared_ptr<Submap>> submaps_;
  events::SubmapId next_id_ = 0;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_SUBMAP_H_
