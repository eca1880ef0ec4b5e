#ifndef SCOUT_FRONTIER_STABBING_QUERY_H_
#define SCOUT_FRONTIER_STABBING_QUERY_H_

#include <Eigen/Core>
#include <vector>

#include "scout/frontier/submap_catalog.h"

namespace scout::frontier {

// ALGORITHMS §3: returns true if point 'p' (frame of submap 'i') is a global
// frontier point: no other submap whose global box contains it objects.
// 'hint' (in/out, -1 for none) names the submap that objected last; it is
// asked first and updated to the objecting submap, or -1. Pass nullptr to
// query without a hint. 'scratch' avoids an allocation per call.
bool StabbingQuery(const SubmapCatalog& catalog, int i, const Eigen::Vector2d& p, int* hint,
                   std::vector<int>* scratch);

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_STABBING_QUERY_H_
