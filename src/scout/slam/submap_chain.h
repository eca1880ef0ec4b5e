#ifndef SCOUT_SLAM_SUBMAP_CHAIN_H_
#define SCOUT_SLAM_SUBMAP_CHAIN_H_

#include <utility>
#include <vector>

namespace scout::slam {

// A loop closure seen as a link from one submap to another, with the
// trajectory length it stands for.
struct SubmapLink {
  int submap_id = 0;
  double travel_m = 0.0;
};

// Trajectory length of the shortest chain from 'sources' (submap id, length
// already travelled to reach it) to every submap, where consecutive submaps i
// and i + 1 are start_travel_m[i + 1] - start_travel_m[i] apart (the
// trajectory between their first nodes) and links[i] lists submap i's loop
// links (each given from both ends). Drift grows along the trajectory, but a
// loop closure ties the two places it joins, so this length, not the
// trajectory between them, bounds how far apart two submaps' estimates can
// have drifted. Unreached submaps (none, with every submap in the sequence)
// stay infinite.
std::vector<double> ShortestChainTravel(const std::vector<double>& start_travel_m,
                                        const std::vector<std::vector<SubmapLink>>& links,
                                        const std::vector<std::pair<int, double>>& sources);

}  // namespace scout::slam

#endif  // SCOUT_SLAM_SUBMAP_CHAIN_H_
