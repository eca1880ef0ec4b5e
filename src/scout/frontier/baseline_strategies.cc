#include "scout/frontier/baseline_strategies.h"

namespace scout::frontier {

UpdateCost FullStrategy::OnOptimized(const std::vector<geometry::Rigid2d>&) {
  return QueryAllSubmaps(/*use_hints=*/false);
}

UpdateCost DfdStrategy::OnOptimized(const std::vector<geometry::Rigid2d>&) {
  return QueryAllSubmaps(/*use_hints=*/true);
}

}  // namespace scout::frontier
