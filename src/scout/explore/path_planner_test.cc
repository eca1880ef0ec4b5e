#include "scout/explore/path_planner.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#include "scout/explore/path_distance_field.h"
#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

TraversabilityOptions PointRobot() {
  TraversabilityOptions o;
  o.robot_radius_m = 0.0;
  o.safety_margin_m = 0.0;
  o.goal_snap_radius_m = 0.0;
  return o;
}

// Brute force: relax every edge until nothing changes (Bellman-Ford), with
// the planner's rule that a diagonal step needs both orthogonal cells free.
double BruteForceDistance(const grid::OccupancyMap& m, grid::CellIndex from, grid::CellIndex to) {
  const int w = m.limits.width(), h = m.limits.height();
  const auto free = [&](int x, int y) { return m.at({x, y}) == grid::CellState::kFree; };
  std::vector<double> d(size_t(w) * h, std::numeric_limits<double>::infinity());
  d[from.y * w + from.x] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!free(x, y) || !std::isfinite(d[y * w + x])) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          for (int dy = -1; dy <= 1; ++dy) {
            if ((dx == 0 && dy == 0) || !free(x + dx, y + dy)) continue;
            if (dx != 0 && dy != 0 && (!free(x + dx, y) || !free(x, y + dy))) continue;
            const double nd = d[y * w + x] + std::hypot(dx, dy);
            double& t = d[(y + dy) * w + x + dx];
            if (nd < t - 1e-12) t = nd, changed = true;
          }
        }
      }
    }
  }
  return d[to.y * w + to.x] * m.limits.resolution();
}

// A serpentine maze: walls at every 4th column, alternately open at the top
// and the bottom, so the only way through winds up and down.
MapBuilder Serpentine() {
  MapBuilder b(41, 21, 0.1, grid::CellState::kFree);
  b.Wall(0, 0, 40, 0).Wall(0, 20, 40, 20).Wall(0, 0, 0, 20).Wall(40, 0, 40, 20);
  for (int x = 4, i = 0; x < 40; x += 4, ++i) {
    if (i % 2 == 0) b.Wall(x, 1, x, 17);  // open at the top (y 18, 19)
    if (i % 2 == 1) b.Wall(x, 3, x, 19);  // open at the bottom (y 1, 2)
  }
  return b;
}

TEST(PathPlannerTest, FindsTheShortestPathThroughAMaze) {
  const MapBuilder b = Serpentine();
  const PlanningMap map(b.map(), PointRobot());
  const PathPlanner planner(PathPlannerOptions{});
  const auto path = planner.Plan(map, b.At(2, 2), b.At(38, 18));
  ASSERT_TRUE(path.has_value());
  const double truth = BruteForceDistance(b.map(), {2, 2}, {38, 18});
  EXPECT_NEAR(path->cell_path_length_m, truth, 1e-4);
  // The maze forces nine crossings of (most of) its height.
  EXPECT_GT(truth, 9 * 1.4);
  // The Dijkstra field agrees.
  const PathDistanceField field(map, b.At(2, 2));
  EXPECT_NEAR(field.at(grid::CellIndex{38, 18}), truth, 1e-4);
  // Shortcutting keeps line of sight and never lengthens the path.
  EXPECT_LE(path->length_m, path->cell_path_length_m + 1e-9);
  EXPECT_EQ(path->points.front(), b.At(2, 2));
  EXPECT_EQ(path->points.back(), b.At(38, 18));
  for (size_t i = 1; i < path->points.size(); ++i) {
    EXPECT_TRUE(map.SegmentTraversable(path->points[i - 1], path->points[i])) << i;
  }
}

// The planner keeps its search state between plans (per thread): plans on
// maps of other sizes, failed searches that closed every cell, and many plans
// in a row must leave nothing behind that changes the next one.
TEST(PathPlannerTest, APlanDoesNotDependOnThePlansBeforeIt) {
  const MapBuilder maze = Serpentine();
  const PlanningMap maze_map(maze.map(), PointRobot());
  MapBuilder boxed(60, 50, 0.1, grid::CellState::kFree);
  boxed.Wall(15, 15, 25, 15).Wall(15, 25, 25, 25).Wall(15, 15, 15, 25).Wall(25, 15, 25, 25);
  const PlanningMap boxed_map(boxed.map(), TraversabilityOptions{});
  const PathPlanner planner(PathPlannerOptions{});
  const auto plan = [&] { return planner.Plan(maze_map, maze.At(2, 2), maze.At(38, 18)); };
  std::optional<PlannedPath> fresh;
  std::thread([&] { fresh = plan(); }).join();  // a thread that planned nothing before
  ASSERT_TRUE(fresh.has_value());
  for (int round = 0; round < 3; ++round) {
    EXPECT_FALSE(planner.Plan(boxed_map, boxed.At(5, 5), boxed.At(20, 20)).has_value());
    ASSERT_TRUE(planner.Plan(boxed_map, boxed.At(5, 5), boxed.At(50, 40)).has_value());
    const std::optional<PlannedPath> again = plan();
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(again->points, fresh->points);
    EXPECT_EQ(again->cell_path_length_m, fresh->cell_path_length_m);
    EXPECT_EQ(again->expansions, fresh->expansions);
  }
}

TEST(PathPlannerTest, ReturnsNothingWhenTheGoalIsWalledOff) {
  MapBuilder b(40, 30, 0.1, grid::CellState::kFree);
  b.Wall(15, 15, 25, 15).Wall(15, 25, 25, 25).Wall(15, 15, 15, 25).Wall(25, 15, 25, 25);
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const PathPlanner planner(PathPlannerOptions{});
  EXPECT_FALSE(planner.Plan(map, b.At(5, 5), b.At(20, 20)).has_value());
  // Control: the same goal with one side of the box removed is reachable.
  b.Free(25, 16, 25, 24);
  const PlanningMap open(b.map(), TraversabilityOptions{});
  EXPECT_TRUE(planner.Plan(open, b.At(5, 5), b.At(20, 20)).has_value());
}

TEST(PathPlannerTest, OpenRoomGivesAStraightLine) {
  MapBuilder b(40, 40, 0.1, grid::CellState::kFree);
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const auto path = PathPlanner({}).Plan(map, {0.53, 0.71}, {3.3, 2.9});
  ASSERT_TRUE(path.has_value());
  ASSERT_EQ(path->points.size(), 2u);
  EXPECT_NEAR(path->length_m, (Eigen::Vector2d(3.3, 2.9) - Eigen::Vector2d(0.53, 0.71)).norm(),
              1e-9);
}

TEST(PathPlannerTest, UnknownCellsAreTraversableOnlyWhenConfigured) {
  MapBuilder b(40, 20, 0.1, grid::CellState::kFree);
  b.Fill(20, 0, 20, 19, grid::CellState::kUnknown);  // an unseen band across the map
  TraversabilityOptions o = PointRobot();
  EXPECT_FALSE(PathPlanner({}).Plan(PlanningMap(b.map(), o), b.At(5, 5), b.At(35, 5)));
  o.unknown_traversable = true;
  EXPECT_TRUE(PathPlanner({}).Plan(PlanningMap(b.map(), o), b.At(5, 5), b.At(35, 5)));
}

TEST(PathPlannerTest, WhereTheRobotDroveStaysPassable) {
  // Two rooms joined by a door 0.4 m wide in the map: below the 0.50 m a
  // 0.20 m robot with a 0.05 m narrow margin needs, so no plan crosses it,
  // unless the robot's own trajectory came through it.
  MapBuilder b(60, 30, 0.1, grid::CellState::kFree);
  b.Wall(30, 0, 30, 12).Wall(30, 17, 30, 29);  // door: cells 13-16
  const Eigen::Vector2d left = b.At(10, 15), right = b.At(50, 15);
  PlanningMap sealed(b.map(), TraversabilityOptions{});
  EXPECT_FALSE(PathPlanner({}).Plan(sealed, left, right));
  PlanningMap driven(b.map(), TraversabilityOptions{});
  driven.AllowDriven({b.At(40, 15), b.At(30.5, 15.5), b.At(20, 15)});
  const std::optional<PlannedPath> path = PathPlanner({}).Plan(driven, left, right);
  ASSERT_TRUE(path.has_value());
  EXPECT_TRUE(driven.narrow(b.map().limits.FlatIndex({30, 15})));
  EXPECT_FALSE(driven.traversable(b.map().limits.FlatIndex({30, 12})));  // walls stay walls
  // Trajectory points too far apart (a relocalisation jump) are not joined.
  TraversabilityOptions short_gap;
  short_gap.driven_max_gap_m = 0.5;
  PlanningMap jumped(b.map(), short_gap);
  jumped.AllowDriven({b.At(40, 15), b.At(20, 15)});
  EXPECT_FALSE(PathPlanner({}).Plan(jumped, left, right));
}

TEST(PathPlannerTest, StartInsideTheInflatedBandLeavesIt) {
  MapBuilder b(40, 40, 0.1, grid::CellState::kFree);
  b.Wall(0, 0, 39, 0);
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const Eigen::Vector2d robot = b.At(10, 2);  // 0.2 m from the wall: blocked
  ASSERT_FALSE(map.Traversable(map.limits().CellContaining(robot)));
  const auto path = PathPlanner({}).Plan(map, robot, b.At(30, 30));
  ASSERT_TRUE(path.has_value());
  EXPECT_EQ(path->points.front(), robot);
  // It leaves the band without getting closer to the wall than it was, and
  // once out it stays out.
  size_t out = 1;
  while (out < path->points.size() &&
         !map.Traversable(map.limits().CellContaining(path->points[out]))) {
    EXPECT_GE(path->points[out].y(), robot.y() - 1e-9) << out;
    ++out;
  }
  ASSERT_LT(out, path->points.size());
  EXPECT_LE((path->points[out] - robot).norm(), 0.5);
  for (size_t i = out; i < path->points.size(); ++i) {
    EXPECT_TRUE(map.Traversable(map.limits().CellContaining(path->points[i]))) << i;
  }
}

TEST(PathPlannerTest, ClearancePenaltyKeepsAwayFromWalls) {
  // A 3 m wide corridor; start and goal near its lower wall.
  MapBuilder b(80, 32, 0.1, grid::CellState::kFree);
  b.Wall(0, 0, 79, 0).Wall(0, 31, 79, 31);
  const Eigen::Vector2d start = b.At(5, 5), goal = b.At(75, 5);
  // How far the path gets from the lower wall on its way.
  const auto farthest = [](const PlannedPath& p) {
    double y = 0;
    for (const Eigen::Vector2d& q : p.points) y = std::max(y, q.y());
    return y;
  };
  const PlanningMap map(b.map(), TraversabilityOptions{}, /*with_clearance=*/true);
  const auto plain = PathPlanner({}).Plan(map, start, goal);
  PathPlannerOptions careful;
  careful.clearance_weight = 5.0;
  careful.clearance_band_m = 0.8;
  const auto safe = PathPlanner(careful).Plan(map, start, goal);
  ASSERT_TRUE(plain && safe);
  EXPECT_LT(farthest(*plain), 0.6);
  EXPECT_GT(farthest(*safe), 1.1);
  EXPECT_THROW(PathPlanner(careful).Plan(PlanningMap(b.map(), {}), start, goal),
               std::invalid_argument);
}

// A w x h map (0.1 m cells) with about 30 % of its cells occupied at random.
MapBuilder RandomMaze(int w, int h) {
  MapBuilder b(w, h, 0.1, grid::CellState::kFree);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (*rc::gen::inRange(0, 100) < 30) b.Wall(x, y, x, y);
    }
  }
  return b;
}

RC_GTEST_PROP(PathPlannerProperty, MatchesBruteForceOnRandomMazes, ()) {
  const int w = *rc::gen::inRange(4, 16), h = *rc::gen::inRange(4, 16);
  MapBuilder b = RandomMaze(w, h);
  const grid::CellIndex s{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  const grid::CellIndex t{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  b.Free(s.x, s.y, s.x, s.y).Free(t.x, t.y, t.x, t.y);
  const PlanningMap map(b.map(), PointRobot());
  const auto path = PathPlanner({}).Plan(map, b.At(s.x, s.y), b.At(t.x, t.y));
  const double truth = BruteForceDistance(b.map(), s, t);
  RC_ASSERT(path.has_value() == std::isfinite(truth));
  if (path) {
    RC_ASSERT(std::abs(path->cell_path_length_m - truth) < 1e-4);
    RC_ASSERT(path->length_m <= path->cell_path_length_m + 1e-9);
    for (size_t i = 1; i < path->points.size(); ++i) {
      RC_ASSERT(map.SegmentTraversable(path->points[i - 1], path->points[i]));
    }
  }
}

// Plans that share what a failed plan learnt (ReachableCells) are the plans
// made without it, goal for goal: the goal manager plans to a selection's
// candidates in turn, and after one fails the others are answered at once.
RC_GTEST_PROP(PathPlannerProperty, ReachableCellsOfAFailedPlanChangeNoPlan, ()) {
  const int w = *rc::gen::inRange(4, 30), h = *rc::gen::inRange(4, 30);
  MapBuilder b = RandomMaze(w, h);
  const grid::CellIndex s{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  b.Free(s.x, s.y, s.x, s.y);
  TraversabilityOptions o = PointRobot();
  o.goal_snap_radius_m = *rc::gen::inRange(0, 4) * 0.05;
  const PlanningMap map(b.map(), o);
  const StartRegion start(map, b.At(s.x, s.y));
  const PathPlanner planner({});
  ReachableCells reachable;
  int failed = 0;
  for (int goals = *rc::gen::inRange(1, 12); goals > 0; --goals) {
    // Anywhere on the map and a little beyond it, not only at cell centres.
    const Eigen::Vector2d goal(*rc::gen::inRange(-5, 10 * w + 5) * 0.01 * 1.03,
                               *rc::gen::inRange(-5, 10 * h + 5) * 0.01 * 0.97);
    const std::optional<PlannedPath> want = planner.Plan(map, start, goal);
    const std::optional<PlannedPath> got = planner.Plan(map, start, goal, reachable);
    RC_ASSERT(got.has_value() == want.has_value());
    failed += !want.has_value();
    RC_ASSERT(reachable.known() == (failed > 0));
    if (want) {
      RC_ASSERT(got->points == want->points);
      RC_ASSERT(got->expansions == want->expansions);
    }
  }
  const PlanningMap other(b.map(), o);
  if (reachable.known()) {
    RC_ASSERT_THROWS_AS(planner.Plan(other, start, b.At(0, 0), reachable), std::invalid_argument);
  }
}

// The distance field's Dijkstra gives every cell the brute-force path length.
RC_GTEST_PROP(PathDistanceFieldProperty, MatchesBruteForceOnRandomMazes, ()) {
  const int w = *rc::gen::inRange(3, 12), h = *rc::gen::inRange(3, 12);
  MapBuilder b = RandomMaze(w, h);
  const grid::CellIndex s{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  b.Free(s.x, s.y, s.x, s.y);
  const PlanningMap map(b.map(), PointRobot());
  const PathDistanceField field(map, b.At(s.x, s.y));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double truth = BruteForceDistance(b.map(), s, {x, y});
      const float d = field.at(grid::CellIndex{x, y});
      RC_ASSERT(std::isfinite(d) == std::isfinite(truth));
      if (std::isfinite(truth)) RC_ASSERT(std::abs(d - truth) < 1e-4);
    }
  }
}

// A field settled in parts, to random distances, knows exactly the complete
// field's distances below settled_m(), reports the cells clearly beyond it
// unreachable (none of a search's tentative distances), and once settled to
// the end equals the complete field (the goal manager's re-ranking and the
// baselines stop the search early).
RC_GTEST_PROP(PathDistanceFieldProperty, SettlingInPartsEqualsTheCompleteField, ()) {
  const int w = *rc::gen::inRange(3, 40), h = *rc::gen::inRange(3, 40);
  MapBuilder b = RandomMaze(w, h);
  const grid::CellIndex s{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  b.Free(s.x, s.y, s.x, s.y);
  const PlanningMap map(b.map(), PointRobot());
  const StartRegion start(map, b.At(s.x, s.y));
  const PathDistanceField complete(map, start);
  RC_ASSERT(complete.complete());
  const auto check = [&](const PathDistanceField& part) {
    for (int64_t i = 0; i < map.limits().num_cells(); ++i) {
      const float want = complete.at(i);
      // settled_m() lies a millionth below the first unsettled distance.
      if (want < part.settled_m()) {
        RC_ASSERT(part.at(i) == want);
      } else if (want > part.settled_m() * (1.0 + 1e-5)) {
        RC_ASSERT(part.at(i) == PathDistanceField::kUnreachable);
      } else {
        RC_ASSERT(part.at(i) == want || part.at(i) == PathDistanceField::kUnreachable);
      }
    }
  };
  PathDistanceField part(map, start, *rc::gen::inRange(0, 40) * 0.1);
  check(part);
  for (int steps = *rc::gen::inRange(0, 4); steps > 0; --steps) {
    part.SettleUpTo(*rc::gen::inRange(0, 50) * 0.1);
    check(part);
  }
  part.SettleUpTo(std::numeric_limits<double>::infinity());
  RC_ASSERT(part.complete());
  for (int64_t i = 0; i < map.limits().num_cells(); ++i) RC_ASSERT(part.at(i) == complete.at(i));
}

TEST(PlanningMapTest, ReusingThePreviousMapInflatesANewObstacleFully) {
  MapBuilder b(40, 40, 0.05, grid::CellState::kFree);
  const PlanningMap previous(b.map(), TraversabilityOptions{});
  b.Wall(20, 20, 20, 20);
  const PlanningMap reused(b.map(), TraversabilityOptions{}, false, &previous);
  const PlanningMap fresh(b.map(), TraversabilityOptions{});
  // 0.40 m inflation: blocked 8 cells out along the axes, not 9.
  EXPECT_TRUE(reused.blocked(b.map().limits.FlatIndex({28, 20})));
  EXPECT_FALSE(reused.blocked(b.map().limits.FlatIndex({29, 20})));
  EXPECT_EQ(reused.traversability_codes(), fresh.traversability_codes());
}

// A planning map built from the previous one equals one built afresh, for
// changes anywhere (near the edges too), none, or another lattice.
RC_GTEST_PROP(PlanningMapProperty, ReusingThePreviousMapEqualsBuildingAfresh, ()) {
  const int w = *rc::gen::inRange(1, 40), h = *rc::gen::inRange(1, 40);
  // Sparse obstacles too, so a change reaches cells no other obstacle blocks.
  const int occupied_per_mille = *rc::gen::element(5, 30, 200);
  const auto random_state = [&] {
    const int r = *rc::gen::inRange(0, 1000);
    return r < occupied_per_mille
               ? grid::CellState::kOccupied
               : (r < 2 * occupied_per_mille ? grid::CellState::kUnknown : grid::CellState::kFree);
  };
  MapBuilder before(w, h, 0.05, grid::CellState::kFree);
  grid::OccupancyMap first = before.map();
  for (grid::CellState& c : first.cells) c = random_state();
  TraversabilityOptions o;
  o.unknown_traversable = *rc::gen::arbitrary<bool>();
  o.narrow_margin_m = *rc::gen::element(0.1, 0.3);  // with and without narrow passages
  const PlanningMap previous(first, o);
  grid::OccupancyMap second = first;
  if (*rc::gen::inRange(0, 5) == 0) {
    // Another lattice: built afresh.
    second.limits = grid::MapLimits(0.05, first.limits.origin() + Eigen::Vector2d(0.05, 0), w, h);
  }
  // Changes inside a random rectangle (possibly none).
  const int x0 = *rc::gen::inRange(0, w), y0 = *rc::gen::inRange(0, h);
  const int x1 = *rc::gen::inRange(x0, w), y1 = *rc::gen::inRange(y0, h);
  const int changes = *rc::gen::inRange(0, 6);
  for (int k = 0; k < changes; ++k) {
    const int x = *rc::gen::inRange(x0, x1 + 1), y = *rc::gen::inRange(y0, y1 + 1);
    second.cells[second.limits.FlatIndex({x, y})] = random_state();
  }
  const PlanningMap reused(second, o, false, &previous);
  const PlanningMap fresh(second, o);
  for (int64_t i = 0; i < second.limits.num_cells(); ++i) {
    RC_ASSERT(reused.blocked(i) == fresh.blocked(i));
  }
  RC_ASSERT(reused.traversability_codes() == fresh.traversability_codes());
  RC_ASSERT(reused.MaxStepFactor() == fresh.MaxStepFactor());
  RC_ASSERT(reused.states() == fresh.states());
}

// CellsWithin tests only the rows and columns near the disc: it must return
// exactly the cells a test of every cell finds, in row-major order, on grids
// with origins and resolutions that do not line up with the points.
RC_GTEST_PROP(CellsWithinProperty, EqualsTestingEveryCell, ()) {
  const double res = *rc::gen::inRange(1, 20) * 0.01;
  const int w = *rc::gen::inRange(1, 30), h = *rc::gen::inRange(1, 30);
  const Eigen::Vector2d origin(*rc::gen::inRange(-1000, 1000) * 1e-3,
                               *rc::gen::inRange(-1000, 1000) * 1e-3);
  const grid::MapLimits limits(res, origin, w, h);
  // Points on cell corners, edges and centres as well as anywhere.
  const auto coordinate = [&](double o, int n) {
    const int half_cells = *rc::gen::inRange(-4, 2 * n + 4);
    const double jitter = *rc::gen::element(0.0, 0.0, 1e-12, -1e-12, 0.37);
    return o + (half_cells * 0.5 + jitter) * res;
  };
  const Eigen::Vector2d p(coordinate(origin.x(), w), coordinate(origin.y(), h));
  const double radius = *rc::gen::element(0.0, 0.5 * res, res, 1.5 * res, std::sqrt(2.0) * res,
                                          *rc::gen::inRange(0, 3000) * 1e-3);
  std::vector<grid::CellIndex> expected;
  const grid::CellIndex centre = limits.CellContaining(p);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const grid::CellIndex c{x, y};
      if (c == centre || (limits.CellCenter(c) - p).squaredNorm() <= radius * radius) {
        expected.push_back(c);
      }
    }
  }
  RC_ASSERT(CellsWithin(limits, p, radius) == expected);
}

}  // namespace
}  // namespace scout::explore
