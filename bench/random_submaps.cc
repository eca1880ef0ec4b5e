#include "random_submaps.h"

#include <chrono>

namespace scout::frontier::bench {

RandomSubmaps MakeRandomSubmaps(uint64_t seed, const testing::RandomScenarioOptions& options,
                                double sensor_radius_min_m, double sensor_radius_max_m) {
  const auto start = std::chrono::steady_clock::now();
  testing::RandomScenario scenario(seed, options);
  RandomSubmaps out;
  out.events.reserve(options.num_submaps);
  out.true_poses.reserve(options.num_submaps);
  for (int id = 0; id < options.num_submaps; ++id) {
    out.true_poses.push_back(scenario.TruePose());
    out.events.push_back(scenario.MakeSubmap(
        id, out.true_poses.back(), scenario.Uniform(sensor_radius_min_m, sensor_radius_max_m)));
  }
  out.seconds_to_generate =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace scout::frontier::bench
