#include "scout/frontier/submap_catalog.h"

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "scout/common/error.h"

namespace scout::frontier {
namespace {

// Box grown by this much so that a point inside a grid is inside its global
// box despite rounding.
constexpr double kBoxPadding_m = 1e-6;

// Returns the box (submap frame) of the cells whose answer differs between
// 'before' and 'after'; cells outside a grid do not object.
geometry::Box2d ChangedRegion(const AnswerMap& before, const AnswerMap& after) {
  // Both maps sit on the submap's lattice: cell (x, y) of 'after' is cell
  // (x, y) + shift of 'before' (an empty 'before' has no cells and never objects).
  const grid::CellIndex shift{after.lattice_offset().x - before.lattice_offset().x,
                              after.lattice_offset().y - before.lattice_offset().y};
  int min_x = std::numeric_limits<int>::max(), min_y = min_x;
  int max_x = std::numeric_limits<int>::min(), max_y = max_x;
  const auto mark = [&](int x, int y) {
    min_x = std::min(min_x, x), max_x = std::max(max_x, x);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
  };
  const grid::MapLimits& limits = after.limits();
  for (int y = 0; y < limits.height(); ++y) {
    for (int x = 0; x < limits.width(); ++x) {
      if (after.ObjectsAtCell({x, y}) != before.ObjectsAtCell({x + shift.x, y + shift.y})) {
        mark(x, y);
      }
    }
  }
  // Cells of the old grid outside the new one (grids only grow, but a producer
  // may shrink them) lose their objection.
  const grid::MapLimits& old_limits = before.limits();
  for (int y = 0; y < old_limits.height(); ++y) {
    for (int x = 0; x < old_limits.width(); ++x) {
      if (before.ObjectsAtCell({x, y}) && !limits.Contains({x - shift.x, y - shift.y})) {
        mark(x - shift.x, y - shift.y);
      }
    }
  }
  if (min_x > max_x) return geometry::Box2d();
  const double res = limits.resolution();
  const Eigen::Vector2d lo = limits.CellCenter({min_x, min_y}).array() - 0.5 * res;
  const Eigen::Vector2d hi = limits.CellCenter({max_x, max_y}).array() + 0.5 * res;
  // Cell lookups and this box compute cell borders in different ways; a point
  // on a border must not fall outside the box by rounding.
  return geometry::Box2d(lo, hi).Inflated(kBoxPadding_m);
}

}  // namespace

SubmapCatalog::SubmapCatalog(const FrontierOptions& options) : options_(options) {
  Validate(options_);
}

SubmapChange SubmapCatalog::Apply(const events::SubmapChanged& event) {
  if (event.id < 0 || event.id > size()) {
    throw InputError("SubmapChanged: submap id " + std::to_string(event.id) +
                     " is neither an existing submap nor the next one (" + std::to_string(size()) +
                     ")");
  }
  if (!event.grid) {
    throw InputError("SubmapChanged: submap " + std::to_string(event.id) + " carries no grid");
  }
  SubmapChange change;
  change.id = event.id;
  change.is_new = event.id == size();
  if (change.is_new) {
    submaps_.emplace_back();
    submaps_.back().local_pose = event.local_pose;
    SetGlobalPose(event.id, local_to_global_ * event.local_pose);
  }
  SubmapRecord& record = submaps_[event.id];
  const std::vector<grid::CellState> states = event.grid->States();
  const grid::MapLimits& limits = event.grid->limits();
  if (change.is_new) record.lattice_corner = limits.origin();
  AnswerMap answers(states, limits, record.lattice_corner);
  change.changed_region = ChangedRegion(record.answers, answers);
  change.previous_answers = std::move(record.answers);
  record.answers = std::move(answers);
  record.grid = event.grid;
  record.local_pose = event.local_pose;
  record.finished = event.finished;

  LocalFrontier frontier =
      ExtractReachableFrontier(states, limits, event.scan_origins, options_.inflation_radius_m);
  // A point is a cell of the submap's lattice, fixed when the submap first
  // appeared (a grown grid keeps the lattice and moves its origin by whole
  // cells). Its position is computed from that lattice index, so the same cell
  // has bit-identical coordinates in every grid version: a surviving point then
  // keeps its answer exactly, even when it lies on another submap's cell border.
  const double res = limits.resolution();
  const auto lattice_key = [&](const Eigen::Vector2d& p, Eigen::Vector2d* snapped) {
    const int64_t kx = std::llround((p.x() - record.lattice_corner.x()) / res - 0.5);
    const int64_t ky = std::llround((p.y() - record.lattice_corner.y()) / res - 0.5);
    if (snapped != nullptr) {
      *snapped = record.lattice_corner + Eigen::Vector2d((static_cast<double>(kx) + 0.5) * res,
                                                         (static_cast<double>(ky) + 0.5) * res);
    }
    return (kx << 32) ^ (ky & 0xffffffff);
  };
  std::unordered_map<int64_t, int> old_index;
  old_index.reserve(record.frontier.points_m.size());
  for (size_t k = 0; k < record.frontier.points_m.size(); ++k) {
    old_index.emplace(lattice_key(record.frontier.points_m[k], nullptr), static_cast<int>(k));
  }
  change.previous_index.resize(frontier.points_m.size());
  for (size_t k = 0; k < frontier.points_m.size(); ++k) {
    const auto it = old_index.find(lattice_key(frontier.points_m[k], &frontier.points_m[k]));
    change.previous_index[k] = it == old_index.end() ? -1 : it->second;
  }
  record.frontier = std::move(frontier);
  record.local_points_box = geometry::Box2d();
  for (const Eigen::Vector2d& p : record.frontier.points_m) record.local_points_box.Extend(p);
  SetGlobalPose(event.id, record.global_pose);  // refreshes the box of a grown grid
  return change;
}

std::vector<geometry::Rigid2d> SubmapCatalog::Apply(const events::Optimized& event) {
  if (static_cast<int>(event.global_poses.size()) > size()) {
    throw InputError("Optimized: carries " + std::to_string(event.global_poses.size()) +
                     " submap poses but only " + std::to_string(size()) + " submaps exist");
  }
  std::vector<geometry::Rigid2d> previous = GlobalPoses();
  const int covered = static_cast<int>(event.global_poses.size());
  for (int id = 0; id < covered; ++id) SetGlobalPose(id, event.global_poses[id]);
  if (covered > 0) {
    // Cartographer's rule: new local SLAM output follows the correction of the
    // newest optimised submap.
    local_to_global_ = event.global_poses[covered - 1] * submaps_[covered - 1].local_pose.inverse();
  }
  for (int id = covered; id < size(); ++id) {
    SetGlobalPose(id, local_to_global_ * submaps_[id].local_pose);
  }
  return previous;
}

std::vector<geometry::Rigid2d> SubmapCatalog::GlobalPoses() const {
  std::vector<geometry::Rigid2d> poses;
  poses.reserve(submaps_.size());
  for (const SubmapRecord& r : submaps_) poses.push_back(r.global_pose);
  return poses;
}

geometry::Box2d SubmapCatalog::GlobalPointsBox(int i) const {
  const SubmapRecord& r = submaps_[i];
  return geometry::TransformBox(r.global_pose, r.local_points_box).Inflated(kBoxPadding_m);
}

int64_t SubmapCatalog::total_points() const {
  int64_t n = 0;
  for (const SubmapRecord& r : submaps_) n += static_cast<int64_t>(r.frontier.points_m.size());
  return n;
}

void SubmapCatalog::SetGlobalPose(int id, const geometry::Rigid2d& pose) {
  SubmapRecord& r = submaps_[id];
  if (r.pose_version == 0 || pose.x() != r.global_pose.x() || pose.y() != r.global_pose.y() ||
      pose.theta() != r.global_pose.theta()) {
    ++r.pose_version;
    r.global_pose = pose;
    r.global_pose_inverse = pose.inverse();
  }
  const geometry::Box2d box =
      r.grid ? geometry::TransformBox(pose, r.grid->limits().Bounds()).Inflated(kBoxPadding_m)
             : geometry::Box2d();
  // Most submaps do not move in a solve: keep the R-tree as it is for them.
  if (box.min != r.global_box.min || box.max != r.global_box.max) {
    r.global_box = box;
    index_.Set(id, r.global_box);
  }
}

}  // namespace scout::frontier
