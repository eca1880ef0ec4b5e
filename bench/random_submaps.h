#ifndef SCOUT_BENCH_RANDOM_SUBMAPS_H_
#define SCOUT_BENCH_RANDOM_SUBMAPS_H_

// Benchmark helper: a catalog-sized set of random overlapping submaps from
// testing::RandomScenario, generated once and shared by the benchmarks that
// need the same layout (the grids are immutable snapshots, so sharing is safe).

#include <cstdint>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/frontier/random_scenario.h"

namespace scout::frontier::bench {

struct RandomSubmaps {
  std::vector<events::SubmapChanged> events;  // SubmapChanged for ids 0..n-1
  std::vector<geometry::Rigid2d> true_poses;  // the pose each submap was cut at
  double seconds_to_generate = 0.0;           // wall time of RandomScenario alone
};

// 'sensor_radius_min/max_m' bound the known disc around each submap's origin;
// drawing it per submap varies the frontier ring like a real trajectory does.
RandomSubmaps MakeRandomSubmaps(uint64_t seed, const testing::RandomScenarioOptions& options,
                                double sensor_radius_min_m, double sensor_radius_max_m);

}  // namespace scout::frontier::bench

#endif  // SCOUT_BENCH_RANDOM_SUBMAPS_H_
