#include "scout/slam/submap_chain.h"

#include <functional>
#include <limits>
#include <queue>

namespace scout::slam {

std::vector<double> ShortestChainTravel(const std::vector<double>& start_travel_m,
                                        const std::vector<std::vector<SubmapLink>>& links,
                                        const std::vector<std::pair<int, double>>& sources) {
  const int n = static_cast<int>(start_travel_m.size());
  std::vector<double> travel(n, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;  // (travel, submap id), nearest first
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  const auto relax = [&](int to, double travel_m) {
    if (travel_m < travel[to]) queue.emplace(travel[to] = travel_m, to);
  };
  for (const auto& [id, travel_m] : sources) {
    if (id >= 0 && id < n) relax(id, travel_m);
  }
  while (!queue.empty()) {
    const auto [travel_m, id] = queue.top();
    queue.pop();
    if (travel_m > travel[id]) continue;  // a stale entry
    if (id > 0) relax(id - 1, travel_m + start_travel_m[id] - start_travel_m[id - 1]);
    if (id + 1 < n) relax(id + 1, travel_m + start_travel_m[id + 1] - start_travel_m[id]);
    if (static_cast<size_t>(id) < links.size()) {
      for (const SubmapLink& link : links[id]) {
        if (link.submap_id >= 0 && link.submap_id < n)
          relax(link.submap_id, travel_m + link.travel_m);
      }
    }
  }
  return travel;
}

}  // namespace scout::slam
