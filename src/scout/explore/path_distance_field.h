#ifndef SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_
#define SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "scout/explore/planning_map.h"
#include "scout/explore/start_region.h"

namespace scout::explore {

// Path distance from the robot to every cell over a PlanningMap: one Dijkstra
// (8-connected, steps of 1 and sqrt 2 cells, same step rule as the A* planner)
// gives the cost of every navigation point at once.
//
// The search may stop early and go on later: a field settled up to a path
// distance knows the cells nearer than that exactly and reports the others
// as kUnreachable. A goal selection needs only the candidates that could come
// first, a re-ranking while driving only those that could beat the goal, and
// the baselines only whether any frontier is reachable; in the museum the
// complete search over millions of cells, once per simulated second, took
// 39 % of a late run's CPU.
class PathDistanceField {
 public:
  static constexpr float kUnreachable = std::numeric_limits<float>::infinity();

  // Starts where the robot enters the traversable cells (StartRegion: its
  // own cell, or the cells its bare disc reaches when it stands in the
  // inflated band). With no such cell every distance is kUnreachable.
  PathDistanceField(const PlanningMap& map, const Eigen::Vector2d& robot);
  // Starts at the seeds of 'start', which must come from 'map'. Settles every
  // cell within 'settle_m' of the start by path (all reachable cells by
  // default).
  PathDistanceField(const PlanningMap& map, const StartRegion& start,
                    double settle_m = std::numeric_limits<double>::infinity());
  // Copies hold the search's state (megabytes): move them.
  PathDistanceField(const PathDistanceField&) = delete;
  PathDistanceField& operator=(const PathDistanceField&) = delete;
  PathDistanceField(PathDistanceField&&) = default;
  PathDistanceField& operator=(PathDistanceField&&) = default;

  // Goes on with the search until every cell within 'settle_m' is settled;
  // the distances already known stay as they are. Requires the map the field
  // was made from to be unchanged.
  void SettleUpTo(double settle_m);
  // True when every reachable cell is settled.
  bool complete() const { return settled_cells_ == kUnreachable; }
  // Every cell nearer than this (metres) is settled (infinity when
  // complete); a cell reporting kUnreachable meanwhile is farther or not
  // reachable. A millionth below the first unsettled distance, so that it
  // stays below the float distances at() returns.
  double settled_m() const {
    return complete() ? std::numeric_limits<double>::infinity()
                      : settled_cells_ * double{res_} * (1.0 - 1e-6);
  }

  // Returns the path distance in metres to the cell (kUnreachable if none, or
  // not settled yet).
  float at(int64_t flat) const {
    return Settled(distance_cells_[flat + 2 * (flat / limits_.width()) + padded_width() + 1]);
  }
  // As above; kUnreachable outside the map.
  float at(const grid::CellIndex& cell) const {
    return limits_.Contains(cell) ? Settled(distance_cells_[Padded(cell)]) : kUnreachable;
  }
  // The seed cell nearest the robot by path, if any.
  const std::optional<grid::CellIndex>& start() const { return start_; }
  // Different for every field constructed (kept by a move), so that what was
  // found on one field is not taken for another's (FrontierPartition).
  uint64_t id() const { return id_; }

  // Returns the least distance over the cells within 'radius_m' of 'p' (the cell
  // containing 'p' always counts), and that cell; nothing when none is reached.
  // The radius absorbs the rounding between a submap's lattice and the map's.
  struct Reached {
    float distance_m;
    grid::CellIndex cell;
  };
  std::optional<Reached> NearestReached(const Eigen::Vector2d& p, double radius_m) const;

 private:
  int64_t padded_width() const { return limits_.width() + 2; }
  int64_t Padded(const grid::CellIndex& c) const {
    return (int64_t{c.y} + 1) * padded_width() + c.x + 1;
  }
  // A cell's distance in metres if settled, else kUnreachable.
  float Settled(float cells) const { return cells < settled_cells_ ? cells * res_ : kUnreachable; }
  // Runs the search through the bucket of distances [k, k + 1) cells for
  // every k <= last_bucket (or to its end).
  void Run(int64_t last_bucket);

  uint64_t id_;
  grid::MapLimits limits_;
  float res_;  // metres per cell
  std::optional<grid::CellIndex> start_;
  // Path distances in cells (metres: times res_). The grid is padded by one
  // unreachable cell on every side, so the search's inner loop needs no
  // bounds checks (index with Padded).
  std::vector<float> distance_cells_;
  // Cells below this distance (in cells) are settled: the next bucket's
  // distance while the search is under way, kUnreachable once it ended.
  float settled_cells_ = kUnreachable;

  // The search's state between calls (released once it ended): traversability
  // codes padded like distance_cells_ with a settled flag, step costs by code,
  // and Dial's bucket queue (see Run).
  std::vector<uint8_t> code_;
  float straight_cost_[3] = {0.0f, 1.0f, 1.0f};
  float diagonal_cost_[3] = {0.0f, 1.0f, 1.0f};
  std::vector<std::vector<uint32_t>> bucket_;
  int64_t next_bucket_ = 0;  // k of the next bucket to run
  int64_t pending_ = 0;      // entries in the buckets
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_
