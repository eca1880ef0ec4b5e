// The explore loop's per-cycle map work on the generated office world's true
// map (the largest map an office run plans on): the planning map, the path
// distance field every goal selection builds, and the coverage measurement
// done at every map update. These dominate `scout explore`'s "goals" and
// "map_fusion" wall time (summary.json wall_time_breakdown_s). Then the
// clustering and ranking of a half-explored museum's frontier, and last the
// whole loop on a small building, for its speed against simulated time.

#include <benchmark/benchmark.h>

#include <cmath>
#include <optional>
#include <vector>

#include "scout/exploration/exploration_loop.h"
#include "scout/exploration/exploration_options.h"
#include "scout/exploration/ground_truth.h"
#include "scout/exploration/test_worlds.h"
#include "scout/explore/mean_shift.h"
#include "scout/explore/navigation_points.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/planning_map.h"
#include "scout/sim/make_world.h"

namespace {

using scout::exploration::ExplorationOptions;
using scout::exploration::GroundTruth;
using scout::exploration::PlanningTraversability;
using scout::explore::PathDistanceField;
using scout::explore::PlanningMap;

struct Office {
  explicit Office(const char* name = "office") : world(scout::sim::MakeWorld(name, 1)) {}
  scout::sim::World world;
  ExplorationOptions options;
  // A stand-in for a whole run's trajectory: back and forth across the map in
  // rows 2 m apart, a node every 0.2 m (about 540 m, an office run's length).
  std::vector<Eigen::Vector2d> Trajectory() const {
    const scout::geometry::Box2d box = world.map.limits.Bounds();
    std::vector<Eigen::Vector2d> t;
    bool leftwards = false;
    for (double y = box.min.y() + 1.0; y < box.max.y() - 1.0; y += 2.0) {
      for (double s = 0.0; s <= (box.max.x() - box.min.x()) - 2.0; s += 0.2) {
        t.emplace_back(leftwards ? box.max.x() - 1.0 - s : box.min.x() + 1.0 + s, y);
      }
      leftwards = !leftwards;
    }
    return t;
  }
};

const Office& TheOffice() {
  static const Office office;
  return office;
}

// The generated museum (seed 1): its runs spend most of their wall time on
// the path distance field and the coverage measurement, whose cost per cell
// grows with the map (cache misses).
const Office& TheMuseum() {
  static const Office museum("museum");
  return museum;
}

const Office& WorldOf(const benchmark::State& state) {
  return state.range(0) == 0 ? TheOffice() : TheMuseum();
}

void BM_PlanningMap(benchmark::State& state) {
  const Office& o = TheOffice();
  const auto trav = PlanningTraversability(o.options);
  const std::vector<Eigen::Vector2d> driven = o.Trajectory();
  for (auto _ : state) {
    PlanningMap map(o.world.map, trav, o.options.explore.planner.clearance_weight > 0.0);
    map.AllowDriven(driven);
    benchmark::DoNotOptimize(map.traversable(0));
  }
}
BENCHMARK(BM_PlanningMap)->Unit(benchmark::kMillisecond);

// The planning map after a map update between two optimisations: the
// previous one is reused and only the cells near a change are inflated
// again (here a 4 m wide band of cells near the start turned occupied).
void BM_PlanningMapReused(benchmark::State& state) {
  const Office& o = TheOffice();
  const auto trav = PlanningTraversability(o.options);
  const PlanningMap previous(o.world.map, trav);
  scout::grid::OccupancyMap changed = o.world.map;
  const scout::grid::CellIndex start = changed.limits.CellContaining(o.world.start);
  for (int dx = -40; dx <= 40; ++dx) {
    const scout::grid::CellIndex c{start.x + dx, start.y + 10};
    if (changed.limits.Contains(c)) changed.set(c, scout::grid::CellState::kOccupied);
  }
  for (auto _ : state) {
    PlanningMap map(changed, trav, false, &previous);
    benchmark::DoNotOptimize(map.traversable(0));
  }
}
BENCHMARK(BM_PlanningMapReused)->Unit(benchmark::kMillisecond);

void BM_PathDistanceField(benchmark::State& state) {
  const Office& o = WorldOf(state);
  const PlanningMap map(o.world.map, PlanningTraversability(o.options));
  int64_t reached = 0;
  for (auto _ : state) {
    const PathDistanceField field(map, o.world.start);
    benchmark::DoNotOptimize(field.at(int64_t{0}));
    reached = 0;
    for (int64_t i = 0; i < map.limits().num_cells(); ++i) reached += std::isfinite(field.at(i));
  }
  state.counters["reached_cells"] = static_cast<double>(reached);
}
BENCHMARK(BM_PathDistanceField)->ArgName("museum")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_MappedFreeM2(benchmark::State& state) {
  const Office& o = WorldOf(state);
  const GroundTruth truth(o.world.map, o.world.name, o.world.start,
                          PlanningTraversability(o.options), o.options.robot.robot.radius_m);
  // A small drift, as between an estimated map and the world.
  const scout::geometry::Rigid2d world_from_map(0.07, -0.04, 0.01);
  for (auto _ : state) {
    benchmark::DoNotOptimize(truth.MappedFreeM2(o.world.map, world_from_map));
  }
}
BENCHMARK(BM_MappedFreeM2)->ArgName("museum")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A museum half explored: from points every 4 m along rows 6 m apart over
// the west half, rays every half degree to 8 m (the lidar's spacing and
// range) mark the cells they cross free and the wall they end on occupied;
// the rest stays unknown. As in a run's map, far rays leave unknown cells
// between them, so the frontier (free cells next to unknown ones) has about
// 21,700 points (museum seed 2's had 12,000 after 1060 s and 27,000 after
// 1975 s): what goal selection clusters and ranks at every re-plan.
struct HalfExploredMuseum {
  HalfExploredMuseum() {
    const scout::grid::OccupancyMap& truth = TheMuseum().world.map;
    const scout::grid::MapLimits& l = truth.limits;
    map.limits = l;
    map.cells.assign(l.num_cells(), scout::grid::CellState::kUnknown);
    const scout::geometry::Box2d box = l.Bounds();
    const double mid_x = 0.5 * (box.min.x() + box.max.x());
    const double step_m = 0.5 * l.resolution();
    std::optional<Eigen::Vector2d> first_eye;
    for (double y = box.min.y() + 3.0; y < box.max.y(); y += 6.0) {
      for (double x = box.min.x() + 3.0; x < mid_x; x += 4.0) {
        const Eigen::Vector2d eye(x, y);
        if (truth.at(l.CellContaining(eye)) != scout::grid::CellState::kFree) continue;
        if (!first_eye) first_eye = eye;
        for (int k = 0; k < 720; ++k) {
          const double a = k * M_PI / 360.0;
          const Eigen::Vector2d dir(std::cos(a), std::sin(a));
          for (double s = 0.0; s <= 8.0; s += step_m) {
            const scout::grid::CellIndex c = l.CellContaining(eye + s * dir);
            if (!l.Contains(c)) break;
            if (truth.at(c) == scout::grid::CellState::kOccupied) {
              map.set(c, scout::grid::CellState::kOccupied);
              break;
            }
            map.set(c, scout::grid::CellState::kFree);
          }
        }
      }
    }
    for (int y = 1; y + 1 < l.height(); ++y) {
      for (int x = 1; x + 1 < l.width(); ++x) {
        if (map.at({x, y}) != scout::grid::CellState::kFree) continue;
        if (map.at({x + 1, y}) == scout::grid::CellState::kUnknown ||
            map.at({x - 1, y}) == scout::grid::CellState::kUnknown ||
            map.at({x, y + 1}) == scout::grid::CellState::kUnknown ||
            map.at({x, y - 1}) == scout::grid::CellState::kUnknown) {
          frontier.push_back(l.CellCenter({x, y}));
        }
      }
    }
    // The robot stands at the first viewpoint in free space.
    robot = first_eye.value_or(box.min + Eigen::Vector2d(3.0, 3.0));
  }
  scout::grid::OccupancyMap map;
  std::vector<Eigen::Vector2d> frontier;
  Eigen::Vector2d robot;
};

const HalfExploredMuseum& TheHalfExploredMuseum() {
  static const HalfExploredMuseum museum;
  return museum;
}

void BM_MeanShiftFrontier(benchmark::State& state) {
  const HalfExploredMuseum& m = TheHalfExploredMuseum();
  const scout::explore::MeanShiftOptions options;
  size_t clusters = 0;
  for (auto _ : state) {
    const scout::explore::MeanShiftClusters c = scout::explore::MeanShift(m.frontier, options);
    clusters = c.centres.size();
    benchmark::DoNotOptimize(c.label.data());
  }
  state.counters["frontier_points"] = static_cast<double>(m.frontier.size());
  state.counters["clusters"] = static_cast<double>(clusters);
}
BENCHMARK(BM_MeanShiftFrontier)->Unit(benchmark::kMillisecond);

// Ranking the navigation points of that frontier on a complete path distance
// field (each point's nearest reached cell, info gain, revenue), the first
// ranking of a partition: a partition ranked again on the same field keeps
// the reached cells it found (FrontierPartition::reached), so each iteration
// ranks a fresh copy.
void BM_NavigationPointsFrontier(benchmark::State& state) {
  const HalfExploredMuseum& m = TheHalfExploredMuseum();
  const ExplorationOptions options;
  const PlanningMap map(m.map, PlanningTraversability(options));
  const PathDistanceField field(map, m.robot);
  const scout::explore::NavigationPointOptions nav;
  const scout::explore::FrontierPartition partition =
      scout::explore::PartitionFrontier(map, m.frontier, nav);
  size_t points = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const scout::explore::FrontierPartition fresh = partition;
    state.ResumeTiming();
    const auto ranked =
        scout::explore::ComputeNavigationPoints(map, field, fresh, m.robot, std::nullopt, nav);
    points = ranked.size();
    benchmark::DoNotOptimize(ranked.data());
  }
  state.counters["navigation_points"] = static_cast<double>(points);
}
BENCHMARK(BM_NavigationPointsFrontier)->Unit(benchmark::kMillisecond);

// The whole closed loop (simulator, SLAM, frontiers, goals) on the 9 m x 6 m
// building of exploration_loop_test, which asserts what the run achieves; this
// measures how fast it runs. sim_per_wall is simulated seconds per wall
// second (the office target asks for at least 20).
void BM_ExploreSmallBuilding(benchmark::State& state) {
  const scout::sim::World world = scout::exploration::testing::SmallBuilding();
  double sim_s = 0.0;
  for (auto _ : state) {
    scout::exploration::ExplorationLoop loop(world, {}, 7);
    const scout::exploration::ExplorationResult r = loop.Run();
    sim_s += r.sim_time_s;
  }
  state.counters["sim_s"] = benchmark::Counter(sim_s, benchmark::Counter::kAvgIterations);
  state.counters["sim_per_wall"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ExploreSmallBuilding)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
