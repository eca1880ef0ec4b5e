// A closed loop without SLAM: a hand-drawn world, a range-limited
// line-of-sight "sensor" that copies true cells into the robot's map, a
// unicycle, and the GoalManager driving it. Checks that the explore module's
// pieces work together: exploration finishes, covers the reachable space,
// never collides, and is not trapped by a frontier behind a too-narrow gap.

#include <gtest/gtest.h>

#include <cmath>

#include "scout/explore/goal_manager.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// 16 m x 10 m: two rooms and a corridor joined by 1.5 m doors, and a closet
// whose only opening is 0.3 m wide.
MapBuilder World() {
  MapBuilder b(160, 100, 0.1, grid::CellState::kFree);
  b.Wall(0, 0, 159, 0).Wall(0, 99, 159, 99).Wall(0, 0, 0, 99).Wall(159, 0, 159, 99);
  b.Wall(80, 0, 80, 99).Free(80, 40, 80, 55);  // door between left and right halves
  b.Wall(0, 50, 80, 50).Free(20, 50, 35, 50);  // door between the left rooms
  b.Wall(140, 80, 140, 99).Wall(140, 80, 159, 80).Free(148, 80, 150, 80);  // closet
  b.Wall(100, 20, 104, 24);                                                // a pillar
  return b;
}

// Copies into 'known' every true cell within 'range_m' of 'p' that a ray from
// 'p' reaches before an occupied cell.
bool Sense(const grid::OccupancyMap& world, grid::OccupancyMap& known, const Eigen::Vector2d& p,
           double range_m) {
  bool changed = false;
  const grid::MapLimits& l = world.limits;
  const double res = l.resolution();
  const grid::CellIndex c0 = l.CellContaining(p);
  const int r = static_cast<int>(range_m / res);
  for (int y = c0.y - r; y <= c0.y + r; ++y) {
    for (int x = c0.x - r; x <= c0.x + r; ++x) {
      if (!l.Contains({x, y})) continue;
      const Eigen::Vector2d target = l.CellCenter({x, y});
      const double dist = (target - p).norm();
      if (dist > range_m) continue;
      bool visible = true;
      const int steps = static_cast<int>(dist / (0.4 * res));
      for (int i = 1; i < steps && visible; ++i) {
        const grid::CellIndex on = l.CellContaining(p + (target - p) * (double(i) / steps));
        visible =
            !(on == grid::CellIndex{x, y}) ? world.at(on) != grid::CellState::kOccupied : true;
      }
      if (visible && known.at({x, y}) != world.at({x, y})) {
        known.set({x, y}, world.at({x, y}));
        changed = true;
      }
    }
  }
  return changed;
}

struct LoopResult {
  ExploreStatus status;
  ExploreCounters counters;
  double time_s = 0.0, path_m = 0.0, coverage = 0.0;
  int collisions = 0;
};

// Runs exploration with 'policy' until finished or 900 simulated seconds.
LoopResult RunLoop(std::string_view policy) {
  const MapBuilder world = World();
  grid::OccupancyMap known = world.map();
  std::fill(known.cells.begin(), known.cells.end(), grid::CellState::kUnknown);
  const Eigen::Vector2d start = world.At(15, 20);
  GoalManagerOptions o;
  o.return_to_start = true;
  GoalManager gm(o, {}, {}, {}, MakeGoalPolicy(policy, {}));
  gm.Start();

  LoopResult r;
  geometry::Rigid2d pose(start, 0.3);
  const double dt = 0.1;
  std::vector<Eigen::Vector2d> frontier;
  for (; r.time_s < 900 && r.status.state != ExploreState::kFinished; r.time_s += dt) {
    // The map updates at 2 Hz, as a SLAM front end would publish it.
    const int tick = static_cast<int>(std::lround(r.time_s / dt));
    const bool changed = tick % 5 == 0 && Sense(world.map(), known, pose.translation(), 4.0);
    if (changed) {
      frontier.clear();
      for (int y = 0; y < known.limits.height(); ++y) {
        for (int x = 0; x < known.limits.width(); ++x) {
          if (known.at({x, y}) != grid::CellState::kFree) continue;
          for (const auto& d : kNeighbourOffsets) {
            if (known.at({x + d[0], y + d[1]}) == grid::CellState::kUnknown) {
              frontier.push_back(known.limits.CellCenter({x, y}));
              break;
            }
          }
        }
      }
    }
    ExploreInput in;
    in.time_s = r.time_s;
    in.robot_pose = pose;
    in.map = &known;
    in.frontier = &frontier;
    in.map_changed = changed;
    r.status = gm.Update(in);
    const double v = r.status.command.linear_mps, w = r.status.command.angular_radps;
    const Eigen::Vector2d before = pose.translation();
    const Eigen::Vector2d heading(std::cos(pose.theta()), std::sin(pose.theta()));
    pose = geometry::Rigid2d(pose.translation() + v * dt * heading, pose.theta() + w * dt);
    r.path_m += (pose.translation() - before).norm();
    for (const grid::CellIndex& c : CellsWithin(world.map().limits, pose.translation(), 0.2)) {
      r.collisions += world.map().at(c) == grid::CellState::kOccupied;
    }
  }
  // Coverage: the share of cells the robot's centre could reach in the true
  // world that are mapped free.
  const PlanningMap truth(world.map(), TraversabilityOptions{});
  const PathDistanceField reach(truth, start);
  int64_t reachable = 0, mapped = 0;
  for (int64_t i = 0; i < world.map().limits.num_cells(); ++i) {
    if (!std::isfinite(reach.at(i))) continue;
    ++reachable;
    mapped += known.cells[i] == grid::CellState::kFree;
  }
  r.coverage = double(mapped) / reachable;
  r.counters = gm.counters();
  const ExploreCounters& k = r.counters;
  std::cout << "[ " << policy << " ] t=" << r.time_s << " s path=" << r.path_m
            << " m coverage=" << r.coverage << " state=" << ToString(r.status.state)
            << " issued=" << k.goals_issued << " reached=" << k.goals_reached
            << " failed=" << k.goals_failed << " unreachable=" << k.goals_unreachable
            << " superseded=" << k.goals_superseded << " retried=" << k.goals_retried << "\n";
  return r;
}

TEST(ExploreLoopTest, ScoutExploresEverythingReachableWithoutCollisions) {
  const LoopResult r = RunLoop("scout");
  ASSERT_EQ(r.status.state, ExploreState::kFinished) << "t = " << r.time_s;
  EXPECT_TRUE(r.status.returned_home);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GT(r.coverage, 0.99);
  // The closet's frontier (seen through its 0.3 m gap) is never a goal.
  EXPECT_EQ(r.counters.goals_unreachable, 0);
  EXPECT_EQ(r.counters.goals_failed, 0);
}

TEST(ExploreLoopTest, BaselinesRunInTheSameLoop) {
  for (const char* name : {"nearest", "explore-lite", "meanshift-centres"}) {
    const LoopResult r = RunLoop(name);
    EXPECT_EQ(r.collisions, 0) << name;
    EXPECT_GT(r.counters.goals_issued, 0) << name;
  }
}

}  // namespace
}  // namespace scout::explore
