// Per-submap cost of a grid change (ALGORITHMS §2–3): reachable local frontier
// extraction, answer-map construction, and the whole SubmapCatalog::Apply that
// runs both, on one realistic 16 m x 16 m submap at 5 cm.

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/frontier/answer_map.h"
#include "scout/frontier/frontier_options.h"
#include "scout/frontier/local_frontiers.h"
#include "scout/frontier/submap_catalog.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/range_data_inserter.h"

namespace scout::frontier {
namespace {

constexpr double kResolution = 0.05;
constexpr double kHalfSize = 8.0;    // the submap covers [-8, 8) m in both axes: 320 x 320 cells
constexpr double kLidarRange = 8.0;  // ALGORITHMS §4 default R
constexpr int kBeamsPerScan = 720;   // 0.5 degree over 360 degrees

struct Segment {
  Eigen::Vector2d a, b;
};

// An office-like layout in the submap frame: a corridor along x with rooms on
// both sides, a doorway into every room, and a few pillars. The walls reach
// beyond the grid, so the corridor ends and the rooms only seen through their
// doors leave unknown space and frontiers, as in a real submap.
std::vector<Segment> OfficeWalls() {
  std::vector<Segment> walls;
  const auto wall = [&](double x0, double y0, double x1, double y1) {
    walls.push_back({{x0, y0}, {x1, y1}});
  };
  const auto box = [&](double cx, double cy, double half) {
    wall(cx - half, cy - half, cx + half, cy - half);
    wall(cx + half, cy - half, cx + half, cy + half);
    wall(cx + half, cy + half, cx - half, cy + half);
    wall(cx - half, cy + half, cx - half, cy - half);
  };
  constexpr double kDoorHalf = 0.5;
  // Rooms north of the corridor span 4 m in x, the ones south are offset by 2 m
  // so doors on both sides do not line up.
  for (const auto& [y_corridor, y_back, first_divider] :
       {std::tuple{1.0, 6.0, -13.0}, std::tuple{-1.0, -6.0, -11.0}}) {
    double door_left = first_divider;  // the corridor wall runs from one door to the next
    for (double x = first_divider; x <= 13.0; x += 4.0) {
      wall(x, y_corridor, x, y_back);  // divider between two rooms
      const double door = x + 2.0;
      wall(door_left, y_corridor, door - kDoorHalf, y_corridor);
      door_left = door + kDoorHalf;
    }
    wall(first_divider, y_back, 13.0, y_back);
  }
  // Pillars and furniture-sized clutter inside some rooms.
  box(-3.0, 3.5, 0.3);
  box(2.5, 4.5, 0.2);
  box(0.0, -3.0, 0.4);
  box(4.8, -4.0, 0.25);
  box(-6.5, -3.5, 0.3);
  return walls;
}

// Returns the distance along the unit ray origin + t * dir to the nearest wall,
// or infinity.
double CastRay(const std::vector<Segment>& walls, const Eigen::Vector2d& origin,
               const Eigen::Vector2d& dir) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : walls) {
    const Eigen::Vector2d e = s.b - s.a;
    const double denom = dir.x() * e.y() - dir.y() * e.x();
    if (std::abs(denom) < 1e-12) continue;  // parallel: a grazing ray hits the next wall
    const Eigen::Vector2d w = s.a - origin;
    const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
    const double u = (w.x() * dir.y() - w.y() * dir.x()) / denom;
    if (t > 0 && u >= 0 && u <= 1) best = std::min(best, t);
  }
  return best;
}

// Returns the distance along the ray to the border of the grid square: the
// ray ends there (a miss) so the inserter never grows the grid and the grid
// stays 320 x 320, as a fixed-size submap would.
double DistanceToBorder(const Eigen::Vector2d& origin, const Eigen::Vector2d& dir) {
  constexpr double kInside = kHalfSize - 1e-6;
  double t = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    if (dir[axis] > 1e-12) t = std::min(t, (kInside - origin[axis]) / dir[axis]);
    if (dir[axis] < -1e-12) t = std::min(t, (-kInside - origin[axis]) / dir[axis]);
  }
  return t;
}

// A submap as local SLAM would build it: a few scans along the corridor
// ray-cast against OfficeWalls() and inserted with the Cartographer-style
// inserter. Built once and shared by all benchmarks of this file.
struct RoomSubmap {
  grid::ProbabilityGrid grid;
  std::vector<grid::CellState> states;
  std::vector<Eigen::Vector2d> scan_origins;
};

const RoomSubmap& Room() {
  static const RoomSubmap room = [] {
    RoomSubmap r;
    const int cells = static_cast<int>(std::lround(2 * kHalfSize / kResolution));
    r.grid = grid::ProbabilityGrid(
        grid::MapLimits(kResolution, Eigen::Vector2d(-kHalfSize, -kHalfSize), cells, cells));
    const std::vector<Segment> walls = OfficeWalls();
    const grid::RangeDataInserter inserter{grid::RangeDataInserterOptions{}};
    // The robot drives 4 m along the corridor; a submap of 70 scans sees the
    // same space many times, which a few origins already reproduce.
    for (double x = -2.0; x <= 2.0 + 1e-9; x += 0.8) {
      const Eigen::Vector2d origin(x, 0.1 * std::sin(3 * x));
      r.scan_origins.push_back(origin);
      std::vector<Eigen::Vector2d> returns, misses;
      for (int b = 0; b < kBeamsPerScan; ++b) {
        // Offset per scan so the beams of different scans interleave.
        const double angle = 2 * std::numbers::pi * (b + 0.37 * x) / kBeamsPerScan;
        const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
        const double hit = CastRay(walls, origin, dir);
        const double end = std::min(kLidarRange, DistanceToBorder(origin, dir));
        if (hit < end) {
          returns.push_back(origin + hit * dir);
        } else {
          misses.push_back(origin + end * dir);
        }
      }
      inserter.Insert(origin, returns, misses, &r.grid);
    }
    if (r.grid.limits().width() != cells || r.grid.limits().height() != cells) {
      throw std::logic_error("room submap grew beyond 320 x 320 cells");
    }
    r.states = r.grid.States();
    return r;
  }();
  return room;
}

void SetCellCounters(benchmark::State& state, const RoomSubmap& room) {
  int64_t free = 0, occupied = 0;
  for (const grid::CellState s : room.states) {
    free += s == grid::CellState::kFree;
    occupied += s == grid::CellState::kOccupied;
  }
  state.SetItemsProcessed(state.iterations() * room.grid.limits().num_cells());
  state.counters["cells"] = static_cast<double>(room.grid.limits().num_cells());
  state.counters["free"] = static_cast<double>(free);
  state.counters["occupied"] = static_cast<double>(occupied);
}

// ALGORITHMS §2 on one submap: EDT inflation, wavefront from the scan origins,
// frontier test. items/s = grid cells per second.
void BM_ExtractReachableFrontier(benchmark::State& state) {
  const RoomSubmap& room = Room();
  const double inflation = FrontierOptions{}.inflation_radius_m;
  size_t points = 0;
  for (auto _ : state) {
    const LocalFrontier frontier =
        ExtractReachableFrontier(room.states, room.grid.limits(), room.scan_origins, inflation);
    points = frontier.points_m.size();
    benchmark::DoNotOptimize(frontier.cells.data());
  }
  SetCellCounters(state, room);
  state.counters["frontier_points"] = static_cast<double>(points);
}
BENCHMARK(BM_ExtractReachableFrontier)->Unit(benchmark::kMillisecond);

// The answer map (objecting cells and their margins) every grid change builds.
void BM_AnswerMapConstruction(benchmark::State& state) {
  const RoomSubmap& room = Room();
  int64_t objecting = 0;
  for (auto _ : state) {
    const AnswerMap answers(room.states, room.grid.limits());
    objecting = answers.num_objecting_cells();
    benchmark::DoNotOptimize(&answers);
  }
  SetCellCounters(state, room);
  state.counters["objecting"] = static_cast<double>(objecting);
}
BENCHMARK(BM_AnswerMapConstruction)->Unit(benchmark::kMillisecond);

// Reading the cell states out of the probability grid, which the catalog does
// before both of the above.
void BM_GridStates(benchmark::State& state) {
  const RoomSubmap& room = Room();
  for (auto _ : state) {
    const std::vector<grid::CellState> states = room.grid.States();
    benchmark::DoNotOptimize(states.data());
  }
  SetCellCounters(state, room);
}
BENCHMARK(BM_GridStates)->Unit(benchmark::kMillisecond);

// Everything the shared catalog does for a new submap (states, answer map,
// extraction, point bookkeeping), i.e. the per-grid-change cost before any
// strategy runs.
void BM_CatalogApplyNewSubmap(benchmark::State& state) {
  const RoomSubmap& room = Room();
  events::SubmapChanged event;
  event.id = 0;
  event.grid = std::make_shared<grid::ProbabilityGrid>(room.grid);
  event.scan_origins = room.scan_origins;
  event.finished = true;
  for (auto _ : state) {
    // A fresh catalog is cheap (no submaps); it makes every iteration a new submap.
    SubmapCatalog catalog{FrontierOptions{}};
    const SubmapChange change = catalog.Apply(event);
    benchmark::DoNotOptimize(change.previous_index.data());
  }
  SetCellCounters(state, room);
}
BENCHMARK(BM_CatalogApplyNewSubmap)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scout::frontier
