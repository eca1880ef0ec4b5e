#include "scout/grid/incremental_fusion.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace scout::grid {
namespace {

// Cells the cached sums grow by beyond what a submap needs, so that a map
// growing a little at a time does not copy the sums at every new submap.
constexpr int kGrowthMarginCells = 256;

// Returns true if both transforms map every point identically: the same
// angle may carry different cos/sin when one pose was composed.
bool SamePose(const geometry::Rigid2d& a, const geometry::Rigid2d& b) {
  const Eigen::Vector2d unit_x(1.0, 0.0);
  return a.translation() == b.translation() && a.theta() == b.theta() &&
         a.Rotate(unit_x) == b.Rotate(unit_x);
}

}  // namespace

IncrementalSubmapFusion::IncrementalSubmapFusion(double resolution_m)
    : resolution_m_(resolution_m) {
  if (!(resolution_m > 0.0)) {
    throw std::invalid_argument("IncrementalSubmapFusion: resolution_m must be > 0, got " +
                                std::to_string(resolution_m));
  }
}

const OccupancyMap& IncrementalSubmapFusion::Update(const std::vector<FusionInput>& submaps) {
  ++statistics_.updates;
  std::vector<PlacedGrid> placed;
  placed.reserve(submaps.size());
  for (const FusionInput& s : submaps) {
    if (!s.grid) {
      throw std::invalid_argument("IncrementalSubmapFusion: submap " + std::to_string(s.id) +
                                  " has no grid");
    }
    placed.push_back({s.grid.get(), s.global_pose});
  }
  fusion::LatticeRect lattice;
  map_.limits = fusion::FusedLimits(placed, resolution_m_, &lattice);

  // The base takes finished submaps over their whole extent, not clipped to
  // this map, as a later map may be larger.
  size_t num_base = ValidateBase(submaps);
  fusion::LatticeRect changed;
  for (; num_base < submaps.size() && submaps[num_base].finished; ++num_base) {
    const fusion::LatticeRect cells = fusion::SubmapCells(placed[num_base], resolution_m_);
    GrowBase(cells);
    fusion::AddSubmap(placed[num_base], resolution_m_, cells, &base_);
    const FusionInput& s = submaps[num_base];
    base_submaps_.push_back({s.id, s.grid, s.global_pose});
    changed = changed.United(cells);
    ++statistics_.base_additions;
  }
  ClassifyBase(changed);

  CopyBaseStates(lattice);
  fusion::LatticeRect active;
  for (size_t i = num_base; i < submaps.size(); ++i) {
    active = active.United(fusion::SubmapCells(placed[i], resolution_m_).Intersected(lattice));
  }
  if (active.empty()) return map_;
  // Start from the base sums, then add the rest in input order: the same
  // float additions, in the same order, as FuseSubmaps makes.
  scratch_.Reset(active);
  const fusion::LatticeRect overlap = active.Intersected(base_.rect);
  for (int y = overlap.y0; y < overlap.y1(); ++y) {
    const int64_t from = base_.Index(overlap.x0, y);
    const int64_t to = scratch_.Index(overlap.x0, y);
    std::copy_n(base_.log_odds.begin() + from, overlap.width, scratch_.log_odds.begin() + to);
    std::copy_n(base_.known.begin() + from, overlap.width, scratch_.known.begin() + to);
  }
  for (size_t i = num_base; i < submaps.size(); ++i) {
    fusion::AddSubmap(placed[i], resolution_m_, active, &scratch_);
    ++statistics_.active_additions;
  }
  for (int y = active.y0; y < active.y1(); ++y) {
    const int64_t from = scratch_.Index(active.x0, y);
    const int64_t to =
        static_cast<int64_t>(y - lattice.y0) * lattice.width + (active.x0 - lattice.x0);
    for (int i = 0; i < active.width; ++i) {
      map_.cells[to + i] =
          fusion::FusedState(scratch_.log_odds[from + i], scratch_.known[from + i] != 0);
    }
  }
  return map_;
}

size_t IncrementalSubmapFusion::ValidateBase(const std::vector<FusionInput>& submaps) {
  const size_t n = base_submaps_.size();
  bool valid = n <= submaps.size();
  for (size_t i = 0; valid && i < n; ++i) {
    const CachedSubmap& cached = base_submaps_[i];
    const FusionInput& s = submaps[i];
    valid =
        cached.id == s.id && cached.grid == s.grid && SamePose(cached.global_pose, s.global_pose);
  }
  if (valid) return n;
  // Sums cannot be taken back exactly, so any change means starting over.
  base_submaps_.clear();
  base_.Reset(base_.rect);
  std::fill(base_states_.begin(), base_states_.end(), CellState::kUnknown);
  ++statistics_.base_rebuilds;
  return 0;
}

void IncrementalSubmapFusion::GrowBase(const fusion::LatticeRect& cells) {
  if (base_.rect.Contains(cells)) return;
  const fusion::LatticeRect old = base_.rect;
  const fusion::LatticeRect needed = old.United(cells);
  // Pad only the sides that grew: the map grows where the robot explores.
  const int left = old.empty() || needed.x0 < old.x0 ? kGrowthMarginCells : 0;
  const int bottom = old.empty() || needed.y0 < old.y0 ? kGrowthMarginCells : 0;
  const int right = old.empty() || needed.x1() > old.x1() ? kGrowthMarginCells : 0;
  const int top = old.empty() || needed.y1() > old.y1() ? kGrowthMarginCells : 0;
  const fusion::LatticeRect grown{needed.x0 - left, needed.y0 - bottom, needed.width + left + right,
                                  needed.height + bottom + top};
  fusion::LogOddsSums sums;
  sums.Reset(grown);
  std::vector<CellState> states(sums.log_odds.size(), CellState::kUnknown);
  for (int y = old.y0; y < old.y1(); ++y) {
    const int64_t from = base_.Index(old.x0, y);
    const int64_t to = sums.Index(old.x0, y);
    std::copy_n(base_.log_odds.begin() + from, old.width, sums.log_odds.begin() + to);
    std::copy_n(base_.known.begin() + from, old.width, sums.known.begin() + to);
    std::copy_n(base_states_.begin() + from, old.width, states.begin() + to);
  }
  base_ = std::move(sums);
  base_states_ = std::move(states);
}

void IncrementalSubmapFusion::ClassifyBase(const fusion::LatticeRect& rect) {
  const fusion::LatticeRect r = rect.Intersected(base_.rect);
  for (int y = r.y0; y < r.y1(); ++y) {
    const int64_t row = base_.Index(r.x0, y);
    for (int64_t i = row; i < row + r.width; ++i) {
      base_states_[i] = fusion::FusedState(base_.log_odds[i], base_.known[i] != 0);
    }
  }
}

void IncrementalSubmapFusion::CopyBaseStates(const fusion::LatticeRect& lattice) {
  map_.cells.assign(lattice.empty() ? 0 : static_cast<size_t>(lattice.width) * lattice.height,
                    CellState::kUnknown);
  const fusion::LatticeRect overlap = lattice.Intersected(base_.rect);
  for (int y = overlap.y0; y < overlap.y1(); ++y) {
    const int64_t from = base_.Index(overlap.x0, y);
    const int64_t to =
        static_cast<int64_t>(y - lattice.y0) * lattice.width + (overlap.x0 - lattice.x0);
    std::copy_n(base_states_.begin() + from, overlap.width, map_.cells.begin() + to);
  }
}

}  // namespace scout::grid
