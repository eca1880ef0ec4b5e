#include "scout/synthetic/grid_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace scout::synthetic {

GridSearch::GridSearch(const grid::MapLimits& limits, std::vector<uint8_t> traversable)
    : limits_(limits), traversable_(std::move(traversable)) {
  if (static_cast<int64_t>(traversable_.size()) != limits_.num_cells()) {
    throw std::invalid_argument("GridSearch: traversable mask does not match the limits");
  }
  if (limits_.num_cells() > std::numeric_limits<int32_t>::max()) {
    throw std::invalid_argument("GridSearch: grid too large");
  }
  distance_cells_.resize(traversable_.size());
  parent_.resize(traversable_.size());
  mark_.assign(traversable_.size(), 0);
}

int64_t GridSearch::Run(int64_t source, double max_distance_m,
                        const std::function<bool(int64_t, double)>& on_settled) {
  ++run_;
  const uint32_t discovered = 2 * run_;
  const uint32_t settled = discovered + 1;
  const double resolution_m = limits_.resolution();
  const float max_distance_cells = static_cast<float>(max_distance_m / resolution_m);
  using Entry = std::pair<float, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance_cells_[source] = 0.f;
  parent_[source] = static_cast<int32_t>(source);
  mark_[source] = discovered;
  queue.push({0.f, static_cast<int32_t>(source)});
  const float kDiagonal = std::sqrt(2.f);
  const int width = limits_.width();
  while (!queue.empty()) {
    const auto [distance, flat] = queue.top();
    queue.pop();
    if (mark_[flat] == settled || distance > distance_cells_[flat]) continue;
    if (distance > max_distance_cells) return -1;
    mark_[flat] = settled;
    if (on_settled(flat, distance * resolution_m)) return flat;
    const grid::CellIndex cell = limits_.CellOfFlatIndex(flat);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const grid::CellIndex next{cell.x + dx, cell.y + dy};
        if (!limits_.Contains(next)) continue;
        const int32_t next_flat = static_cast<int32_t>(limits_.FlatIndex(next));
        if (!traversable_[next_flat] || mark_[next_flat] == settled) continue;
        // A diagonal move must not cut the corner of an untraversable cell.
        if (dx != 0 && dy != 0 &&
            (!traversable_[flat + dx] || !traversable_[flat + static_cast<int64_t>(dy) * width])) {
          continue;
        }
        const float next_distance = distance + (dx != 0 && dy != 0 ? kDiagonal : 1.f);
        if (mark_[next_flat] == discovered && distance_cells_[next_flat] <= next_distance) {
          continue;
        }
        mark_[next_flat] = discovered;
        distance_cells_[next_flat] = next_distance;
        parent_[next_flat] = flat;
        queue.push({next_distance, next_flat});
      }
    }
  }
  return -1;
}

std::vector<int64_t> GridSearch::PathTo(int64_t cell) const {
  std::vector<int64_t> path = {cell};
  while (parent_[path.back()] != path.back()) path.push_back(parent_[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace scout::synthetic
