#include "scout/frontier/stabbing_query.h"

namespace scout::frontier {

bool StabbingQuery(const SubmapCatalog& catalog, int i, const Eigen::Vector2d& p, int* hint,
                   std::vector<int>* scratch) {
  if (hint != nullptr && *hint >= 0 && *hint != i && *hint < catalog.size() &&
      catalog.submap(*hint).answers.Objects(catalog.PointInSubmap(i, p, *hint))) {
    return false;
  }
  scratch->clear();
  catalog.index().AppendContaining(catalog.GlobalPosition(i, p), scratch);
  for (const int j : *scratch) {
    if (j == i || (hint != nullptr && j == *hint)) continue;
    if (catalog.submap(j).answers.Objects(catalog.PointInSubmap(i, p, j))) {
      if (hint != nullptr) *hint = j;
      return false;
    }
  }
  if (hint != nullptr) *hint = -1;
  return true;
}

}  // namespace scout::frontier
