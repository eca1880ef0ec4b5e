#include "scout/frontier/update_strategy.h"

#include <numeric>

#include "scout/common/error.h"
#include "scout/frontier/baseline_strategies.h"
#include "scout/frontier/exact_strategy.h"
#include "scout/frontier/selective_strategies.h"
#include "scout/frontier/stabbing_query.h"
#include "scout/frontier/stopwatch.h"

namespace scout::frontier {

bool UpdateStrategy::StabbingQueryFor(int i, int k, int* hint) {
  return StabbingQuery(catalog_, i, catalog_.submap(i).frontier.points_m[k], hint, &scratch_);
}

void UpdateStrategy::QuerySubmaps(const std::vector<int>& ids, bool use_hints, UpdateCost* cost) {
  for (const int i : ids) {
    const int n = static_cast<int>(catalog_.submap(i).frontier.points_m.size());
    for (int k = 0; k < n; ++k) QueryPoint(i, k, use_hints);
    cost->queried_points += n;
    if (n > 0) {
      ++cost->queried_submaps;
      cost->submap_ids.push_back(i);
    }
  }
}

UpdateCost UpdateStrategy::QueryAllSubmaps(bool use_hints) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  std::vector<int> all(catalog_.size());
  std::iota(all.begin(), all.end(), 0);
  QuerySubmaps(all, use_hints, &cost);
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

std::vector<int> UpdateStrategy::RemapPoints(const SubmapChange& change) {
  if (change.is_new) {
    is_frontier_.emplace_back();
    hint_.emplace_back();
  }
  std::vector<uint8_t> answers(change.previous_index.size(), 0);
  std::vector<int> hints(change.previous_index.size(), -1);
  std::vector<int> fresh;
  for (size_t k = 0; k < change.previous_index.size(); ++k) {
    const int old = change.previous_index[k];
    if (old >= 0) {
      answers[k] = is_frontier_[change.id][old];
      hints[k] = hint_[change.id][old];
    } else {
      fresh.push_back(static_cast<int>(k));
    }
  }
  is_frontier_[change.id] = std::move(answers);
  hint_[change.id] = std::move(hints);
  return fresh;
}

UpdateCost UpdateStrategy::OnSubmapChanged(const SubmapChange& change) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  const bool hints = uses_hints();
  const std::vector<int> fresh = RemapPoints(change);
  for (const int k : fresh) QueryPoint(change.id, k, hints);
  cost.queried_points += static_cast<int64_t>(fresh.size());
  if (!fresh.empty()) {
    ++cost.queried_submaps;
    cost.submap_ids.push_back(change.id);
  }
  if (!change.changed_region.empty()) {
    const int j = change.id;
    const geometry::Box2d global_region =
        geometry::TransformBox(catalog_.submap(j).global_pose, change.changed_region);
    for (const int i : catalog_.index().Intersecting(global_region)) {
      if (i == j || !catalog_.GlobalPointsBox(i).Intersects(global_region)) continue;
      const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
      int64_t queried = 0;
      for (size_t k = 0; k < points.size(); ++k) {
        if (!change.changed_region.Contains(catalog_.PointInSubmap(i, points[k], j))) continue;
        QueryPoint(i, static_cast<int>(k), hints);
        ++queried;
      }
      cost.queried_points += queried;
      if (queried > 0) {
        ++cost.queried_submaps;
        cost.submap_ids.push_back(i);
      }
    }
  }
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

const std::vector<std::string>& StrategyNames() {
  static const std::vector<std::string> names = {"full", "dfd", "bfs", "direct", "exact"};
  return names;
}

std::unique_ptr<UpdateStrategy> MakeStrategy(std::string_view name, const SubmapCatalog& catalog) {
  if (name == "full") return std::make_unique<FullStrategy>(catalog);
  if (name == "dfd") return std::make_unique<DfdStrategy>(catalog);
  if (name == "bfs") return std::make_unique<BfsStrategy>(catalog);
  if (name == "direct") return std::make_unique<DirectStrategy>(catalog);
  if (name == "exact") return std::make_unique<ExactStrategy>(catalog);
  throw InputError("unknown frontier strategy '" + std::string(name) +
                   "': expected one of full, dfd, bfs, direct, exact");
}

}  // namespace scout::frontier
