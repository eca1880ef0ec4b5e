#include "scout/frontier/baseline_strategies.h"

#include <numeric>

#include "scout/frontier/stopwatch.h"

namespace scout::frontier {

UpdateCost FullStrategy::OnOptimized(const std::vector<geometry::Rigid2d>&) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  std::vector<int> all(catalog_.size());
  std::iota(all.begin(), all.end(), 0);
  QuerySubmaps(all, /*use_hints=*/false, &cost);
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

UpdateCost DfdStrategy::OnOptimized(const std::vector<geometry::Rigid2d>&) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  std::vector<int> all(catalog_.size());
  std::iota(all.begin(), all.end(), 0);
  QuerySubmaps(all, /*use_hints=*/true, &cost);
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

}  // namespace scout::frontier
