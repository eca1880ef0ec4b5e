#ifndef SCOUT_FRONTIER_ANSWER_MAP_H_
#define SCOUT_FRONTIER_ANSWER_MAP_H_

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scout/grid/cell_state.h"
#include "scout/grid/map_limits.h"

namespace scout::frontier {

// What one submap answers to stabbing queries (ALGORITHMS §3), for every
// position in its frame: it *objects* at a position whose cell is known and is
// not a frontier cell of the submap; unknown cells, frontier cells and
// everything outside the grid do not object.
//
// It also knows, for any position q, a *margin*: a distance such that every
// position closer than it to q gets the same answer. The exact update strategy
// uses it to prove that a moved point keeps its answer.
class AnswerMap {
 public:
  AnswerMap() = default;
  // 'states' is row-major over 'limits'. 'lattice_corner' is a cell corner of
  // the submap's fixed lattice (the origin of its first grid): positions are
  // assigned to cells relative to it, so a position on a cell border lands in
  // the same cell in every (grown) version of the grid.
  AnswerMap(const std::vector<grid::CellState>& states, const grid::MapLimits& limits,
            const Eigen::Vector2d& lattice_corner);
  // The same, with the grid's own origin as the lattice corner.
  AnswerMap(const std::vector<grid::CellState>& states, const grid::MapLimits& limits)
      : AnswerMap(states, limits, limits.origin()) {}

  const grid::MapLimits& limits() const { return limits_; }

  // Returns the lattice index of the grid's cell (0, 0).
  grid::CellIndex lattice_offset() const { return {lattice_offset_x_, lattice_offset_y_}; }
  // Returns the cell of the grid containing position 'q' (it may lie outside).
  grid::CellIndex CellContaining(const Eigen::Vector2d& q) const {
    const double res = limits_.resolution();
    return {static_cast<int>(std::floor((q.x() - lattice_corner_.x()) / res)) - lattice_offset_x_,
            static_cast<int>(std::floor((q.y() - lattice_corner_.y()) / res)) - lattice_offset_y_};
  }
  // Returns true if the submap objects at position 'q' (submap frame).
  bool Objects(const Eigen::Vector2d& q) const { return ObjectsAtCell(CellContaining(q)); }
  bool ObjectsAtCell(const grid::CellIndex& c) const {
    return limits_.Contains(c) && (cells_[limits_.FlatIndex(c)] & kObjectsBit);
  }

  // Returns a distance (m, >= 0) such that Objects(q') == Objects(q) for every
  // q' with |q' - q| < Margin(q). Conservative: never larger than the true
  // distance to the nearest cell with the other answer.
  double Margin(const Eigen::Vector2d& q) const;

  // Number of objecting cells.
  int64_t num_objecting_cells() const { return num_objecting_; }

  // Smallest distance from an objecting cell to the grid's border (infinity if
  // no cell objects): a position outside the grid has at least its distance to
  // the grid plus this as its margin.
  double objecting_to_border_m() const {
    return num_objecting_ == 0 ? std::numeric_limits<double>::infinity() : objecting_to_border_m_;
  }

 private:
  static constexpr uint8_t kObjectsBit = 0x80;
  // Low 7 bits: distance from the cell centre to the nearest centre of a cell
  // with the other answer, in quarter cells, rounded down, saturating at 127.
  static constexpr uint8_t kDistanceMask = 0x7f;

  double WindowMargin(const Eigen::Vector2d& q, const grid::CellIndex& c, bool objects) const;

  grid::MapLimits limits_;
  Eigen::Vector2d lattice_corner_ = Eigen::Vector2d::Zero();
  // Cell (0, 0) of the grid is lattice cell (offset_x, offset_y).
  int lattice_offset_x_ = 0;
  int lattice_offset_y_ = 0;
  std::vector<uint8_t> cells_;
  int64_t num_objecting_ = 0;
  // Smallest distance from any objecting cell's square to the grid border.
  double objecting_to_border_m_ = 0.0;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_ANSWER_MAP_H_
