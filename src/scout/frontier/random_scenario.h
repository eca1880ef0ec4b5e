#ifndef SCOUT_FRONTIER_RANDOM_SCENARIO_H_
#define SCOUT_FRONTIER_RANDOM_SCENARIO_H_

// Test and benchmark helper: random overlapping submaps cut from a random
// world, with random pose sequences. Not part of the library.

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "scout/events/submap_events.h"

namespace scout::frontier::testing {

struct RandomScenarioOptions {
  double world_size_m = 12.0;
  double resolution_m = 0.1;
  int num_submaps = 8;
  double submap_size_m = 4.0;
  double sensor_radius_m = 1.8;  // cells farther than this from the origin stay unknown
  double wall_density = 0.08;    // fraction of world cells occupied
};

// A random world: free space with random wall segments and blobs.
class RandomScenario {
 public:
  RandomScenario(uint64_t seed, const RandomScenarioOptions& o) : rng_(seed), o_(o) {
    cells_ = static_cast<int>(o.world_size_m / o.resolution_m);
    world_.assign(static_cast<size_t>(cells_) * cells_, 0);
    const int blobs = static_cast<int>(o.wall_density * cells_ * cells_ / 6.0);
    for (int b = 0; b < blobs; ++b) {
      int x = Int(cells_), y = Int(cells_);
      const bool horizontal = Int(2) == 0;
      const int len = 1 + Int(10);
      for (int k = 0; k < len; ++k) {
        if (x >= 0 && y >= 0 && x < cells_ && y < cells_) world_[y * cells_ + x] = 1;
        (horizontal ? x : y) += 1;
      }
    }
  }

  // True pose of a submap: random position and heading inside the world, or,
  // with 'lattice_aligned', heading 0 and a position on multiples of half a
  // cell, so other aligned submaps' points fall exactly on cell centres and
  // borders (where margins are 0).
  geometry::Rigid2d TruePose(bool lattice_aligned = false) {
    const double margin = o_.submap_size_m / 2;
    const double x = Uniform(margin, o_.world_size_m - margin);
    const double y = Uniform(margin, o_.world_size_m - margin);
    if (lattice_aligned) {
      const double half = o_.resolution_m / 2;
      return geometry::Rigid2d(std::round(x / half) * half, std::round(y / half) * half, 0.0);
    }
    return geometry::Rigid2d(x, y, Uniform(-std::numbers::pi, std::numbers::pi));
  }

  // A submap grid centred on its frame origin, sampled from the world at
  // 'pose', seeing a disc of 'radius_m' around the origin (plus the
  // scan-origin list with that one origin). 'grown_cells' enlarges the grid on
  // every side by whole cells, as a growing submap grid does.
  events::SubmapChanged MakeSubmap(int id, const geometry::Rigid2d& pose, double radius_m,
                                   int grown_cells = 0) {
    const int n = static_cast<int>(o_.submap_size_m / o_.resolution_m) + 2 * grown_cells;
    const Eigen::Vector2d origin =
        Eigen::Vector2d::Constant(-o_.submap_size_m / 2 - grown_cells * o_.resolution_m);
    auto grid =
        std::make_shared<grid::ProbabilityGrid>(grid::MapLimits(o_.resolution_m, origin, n, n));
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const Eigen::Vector2d c = grid->limits().CellCenter({x, y});
        if (c.norm() > radius_m) continue;
        const Eigen::Vector2d w = pose * c;
        const int wx = static_cast<int>(std::floor(w.x() / o_.resolution_m));
        const int wy = static_cast<int>(std::floor(w.y() / o_.resolution_m));
        const bool wall =
            wx < 0 || wy < 0 || wx >= cells_ || wy >= cells_ || world_[wy * cells_ + wx];
        grid->SetProbability({x, y}, wall ? 0.8f : 0.2f);
      }
    }
    events::SubmapChanged e;
    e.id = id;
    e.grid = grid;
    e.local_pose = pose;
    e.scan_origins = {Eigen::Vector2d::Zero()};
    e.finished = true;
    return e;
  }

  double Uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) / static_cast<double>(1ull << 53);
  }
  int Int(int n) { return static_cast<int>(rng_() % static_cast<uint64_t>(n)); }
  std::mt19937_64& rng() { return rng_; }

 private:
  std::mt19937_64 rng_;
  RandomScenarioOptions o_;
  int cells_ = 0;
  std::vector<uint8_t> world_;
};

// Returns 'pose' perturbed by up to 'translation_m' / 'rotation_rad'.
inline geometry::Rigid2d Perturb(RandomScenario& s, const geometry::Rigid2d& pose,
                                 double translation_m, double rotation_rad) {
  return geometry::Rigid2d(pose.x() + s.Uniform(-translation_m, translation_m),
                           pose.y() + s.Uniform(-translation_m, translation_m),
                           pose.theta() + s.Uniform(-rotation_rad, rotation_rad));
}

}  // namespace scout::frontier::testing

#endif  // SCOUT_FRONTIER_RANDOM_SCENARIO_H_
