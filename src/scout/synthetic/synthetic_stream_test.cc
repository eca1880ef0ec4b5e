#include "scout/synthetic/synthetic_stream.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <variant>

#include "scout/common/error.h"
#include "scout/sim/office_world.h"

namespace scout::synthetic {
namespace {

using geometry::Rigid2d;

// A small office (20 m x 20 m, rooms of 3-4 m): a full run takes about a second.
sim::World SmallOffice(uint64_t seed) {
  sim::OfficeWorldOptions options;
  options.width_m = 20.0;
  options.height_m = 20.0;
  options.min_room_size_m = 3.0;
  options.max_room_size_m = 4.0;
  return sim::GenerateOfficeWorld(seed, options);
}

struct Recorded {
  std::vector<events::SubmapEvent> events;
  StreamStats stats;
  std::vector<Rigid2d> true_submap_poses;
};

Recorded RunStream(const sim::World& world, uint64_t seed, int max_scans) {
  SyntheticStreamOptions options;
  options.max_scans = max_scans;
  SyntheticEventStream stream(world, options, seed);
  Recorded recorded;
  recorded.stats = stream.Run([&](const events::SubmapEvent& e) { recorded.events.push_back(e); });
  recorded.true_submap_poses = stream.true_submap_poses();
  return recorded;
}

// FNV-1a over the bytes of every pose and grid value of the events.
uint64_t HashEvents(const std::vector<events::SubmapEvent>& events) {
  uint64_t hash = 1469598103934665603ULL;
  const auto mix = [&](const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ULL;
  };
  const auto mix_pose = [&](const Rigid2d& pose) {
    const double values[3] = {pose.x(), pose.y(), pose.theta()};
    mix(values, sizeof(values));
  };
  for (const events::SubmapEvent& event : events) {
    if (const auto* changed = std::get_if<events::SubmapChanged>(&event)) {
      mix(&changed->id, sizeof(changed->id));
      mix_pose(changed->local_pose);
      const std::vector<uint16_t>& values = changed->grid->values();
      mix(values.data(), values.size() * sizeof(uint16_t));
      const Eigen::Vector2d origin = changed->grid->limits().origin();
      mix(origin.data(), 2 * sizeof(double));
      for (const Eigen::Vector2d& p : changed->scan_origins) mix(p.data(), 2 * sizeof(double));
    } else {
      for (const Rigid2d& pose : std::get<events::Optimized>(event).global_poses) mix_pose(pose);
    }
  }
  return hash;
}

TEST(SyntheticEventStream, SameSeedGivesIdenticalEvents) {
  const sim::World world = SmallOffice(1);
  const Recorded a = RunStream(world, 5, 800);
  const Recorded b = RunStream(world, 5, 800);
  const Recorded c = RunStream(world, 6, 800);
  ASSERT_EQ(a.events.size(), b.events.size());
  EXPECT_EQ(HashEvents(a.events), HashEvents(b.events));
  EXPECT_NE(HashEvents(a.events), HashEvents(c.events));
}

TEST(SyntheticEventStream, SubmapsGetTwiceScansPerSubmapInsertionsThenFinish) {
  const Recorded run = RunStream(SmallOffice(2), 1, 4000);
  const int scans_per_submap = SyntheticStreamOptions{}.scans_per_submap;
  EXPECT_EQ(run.stats.submaps, (run.stats.scans + scans_per_submap - 1) / scans_per_submap);
  std::map<int, int> insertions;
  std::map<int, bool> finished;
  std::map<int, Rigid2d> local_pose;
  for (const events::SubmapEvent& event : run.events) {
    const auto* changed = std::get_if<events::SubmapChanged>(&event);
    if (changed == nullptr) continue;
    ASSERT_FALSE(finished[changed->id]) << "submap " << changed->id << " changed after finishing";
    const int count = ++insertions[changed->id];
    ASSERT_EQ(static_cast<int>(changed->scan_origins.size()), count);
    EXPECT_EQ(changed->finished, count == 2 * scans_per_submap);
    finished[changed->id] = changed->finished;
    if (count == 1) local_pose[changed->id] = changed->local_pose;
    EXPECT_EQ(changed->local_pose.translation(), local_pose[changed->id].translation());
  }
  ASSERT_EQ(static_cast<int>(insertions.size()), run.stats.submaps);
  for (const auto& [id, count] : insertions) {
    if (id + 2 < run.stats.submaps) {
      EXPECT_TRUE(finished[id]) << "submap " << id;
    } else {
      EXPECT_FALSE(finished[id]) << "submap " << id;  // still active at the end
    }
  }
}

TEST(SyntheticEventStream, OptimizationsCarryAPosePerExistingSubmap) {
  const Recorded run = RunStream(SmallOffice(2), 1, 4000);
  const SyntheticStreamOptions options;
  EXPECT_EQ(run.stats.optimizations, run.stats.scans / options.optimize_every_n_scans);
  int submaps_so_far = 0, optimizations = 0;
  for (const events::SubmapEvent& event : run.events) {
    if (const auto* changed = std::get_if<events::SubmapChanged>(&event)) {
      submaps_so_far = std::max(submaps_so_far, changed->id + 1);
    } else {
      ++optimizations;
      EXPECT_EQ(static_cast<int>(std::get<events::Optimized>(event).global_poses.size()),
                submaps_so_far);
    }
  }
  EXPECT_EQ(optimizations, run.stats.optimizations);
}

TEST(SyntheticEventStream, ClosesLoopsAndKeepsGlobalPosesNearTheTruth) {
  const Recorded run = RunStream(SmallOffice(3), 2, 0);
  EXPECT_GT(run.stats.loop_closures, 0);
  EXPECT_GT(run.stats.trajectory_length_m, 100.0);
  double max_error_m = 0.0, max_error_rad = 0.0, max_move_m = 0.0;
  std::vector<Rigid2d> previous;
  for (const events::SubmapEvent& event : run.events) {
    const auto* optimized = std::get_if<events::Optimized>(&event);
    if (optimized == nullptr) continue;
    for (size_t i = 0; i < optimized->global_poses.size(); ++i) {
      const Rigid2d& estimate = optimized->global_poses[i];
      const Rigid2d& truth = run.true_submap_poses[i];
      max_error_m = std::max(max_error_m, (estimate.translation() - truth.translation()).norm());
      max_error_rad = std::max(
          max_error_rad, std::abs(geometry::NormalizeAngle(estimate.theta() - truth.theta())));
      if (i < previous.size()) {
        max_move_m =
            std::max(max_move_m, (estimate.translation() - previous[i].translation()).norm());
      }
    }
    previous = optimized->global_poses;
  }
  EXPECT_LT(max_error_m, 0.3);
  EXPECT_LT(max_error_rad, 2.0 * std::numbers::pi / 180.0);
  // Solves do move submaps (by centimetres), or there would be nothing to update.
  EXPECT_GT(max_move_m, 0.01);
}

TEST(SyntheticEventStream, SubmapGridsAgreeWithTheTrueWorld) {
  const sim::World world = SmallOffice(4);
  const Recorded run = RunStream(world, 3, 1000);
  int occupied = 0, on_obstacle = 0;
  for (const events::SubmapEvent& event : run.events) {
    const auto* changed = std::get_if<events::SubmapChanged>(&event);
    if (changed == nullptr || !changed->finished) continue;
    const grid::ProbabilityGrid& grid = *changed->grid;
    const Rigid2d& submap_to_world = run.true_submap_poses[changed->id];
    for (int64_t i = 0; i < grid.limits().num_cells(); ++i) {
      const grid::CellIndex cell = grid.limits().CellOfFlatIndex(i);
      if (grid.State(cell) != grid::CellState::kOccupied) continue;
      ++occupied;
      // Within one cell of something that is not free in the true world.
      const Eigen::Vector2d p = submap_to_world * grid.limits().CellCenter(cell);
      const grid::CellIndex world_cell = world.map.limits.CellContaining(p);
      bool near_obstacle = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          near_obstacle = near_obstacle || world.map.at({world_cell.x + dx, world_cell.y + dy}) !=
                                               grid::CellState::kFree;
        }
      }
      on_obstacle += near_obstacle ? 1 : 0;
    }
  }
  ASSERT_GT(occupied, 1000);
  EXPECT_GT(on_obstacle, 0.99 * occupied);
}

TEST(SyntheticEventStream, RejectsInvalidOptions) {
  const sim::World world = SmallOffice(1);
  SyntheticStreamOptions options;
  options.scans_per_submap = 0;
  EXPECT_THROW(SyntheticEventStream(world, options, 1), InputError);
  options = SyntheticStreamOptions{};
  options.lidar.beams = 0;
  EXPECT_THROW(SyntheticEventStream(world, options, 1), InputError);
}

}  // namespace
}  // namespace scout::synthetic
