#include "scout/explore/navigation_points.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

#include "scout/explore/goal_policies.h"
#include "scout/explore/path_planner.h"
#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

bool Contains(const std::vector<Eigen::Vector2d>& set, const Eigen::Vector2d& p) {
  return std::any_of(set.begin(), set.end(), [&](const auto& q) { return (q - p).norm() < 1e-9; });
}

// A room, a two-cell wall with a gap of 'gap_cells' rows, and a frontier
// (x = 40) beyond it facing unknown space.
MapBuilder GapMap(int gap_cells) {
  MapBuilder b(60, 40);
  b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown);
  b.Free(1, 1, 40, 38).Wall(29, 1, 30, 38);
  b.Free(29, 20 - gap_cells / 2, 30, 20 - gap_cells / 2 + gap_cells - 1);
  return b;
}

TEST(NavigationPointsTest, FrontierBehindTooNarrowGapYieldsNoPoint) {
  // 0.3 m gap: the 0.4 m inflation closes it.
  const MapBuilder narrow = GapMap(3);
  const PlanningMap map(narrow.map(), TraversabilityOptions{});
  const Eigen::Vector2d robot = narrow.At(10, 20);
  const PathDistanceField field(map, robot);
  ASSERT_TRUE(field.start().has_value());
  const auto frontier = narrow.FrontierPoints();
  ASSERT_FALSE(frontier.empty());
  NavigationPointStats stats;
  EXPECT_TRUE(ComputeNavigationPoints(map, field, frontier, robot, {}, {}, &stats).empty());
  EXPECT_GT(stats.unreachable_components, 0);

  // 1.2 m gap: the same frontier becomes reachable.
  const MapBuilder wide = GapMap(12);
  const PlanningMap wide_map(wide.map(), TraversabilityOptions{});
  const PathDistanceField wide_field(wide_map, robot);
  const auto points =
      ComputeNavigationPoints(wide_map, wide_field, wide.FrontierPoints(), robot, {}, {});
  ASSERT_FALSE(points.empty());
  for (const NavigationPoint& p : points) EXPECT_NEAR(p.position.x(), 4.05, 1e-9);
}

// Open space below (robot), a frontier row at y = 30 facing unknown space,
// and a wall at x = 30 rising from y = 15 through the frontier into the unknown.
MapBuilder SplitMap() {
  MapBuilder b(60, 50);
  b.Wall(0, 0, 59, 49).Free(1, 1, 58, 30).Fill(1, 31, 58, 48, grid::CellState::kUnknown);
  b.Wall(30, 15, 30, 48);
  return b;
}

TEST(NavigationPointsTest, FrontierSplitByWallGivesTwoPointsNeverTheCentre) {
  const MapBuilder b = SplitMap();
  std::vector<Eigen::Vector2d> frontier;
  for (int x = 24; x <= 36; ++x) {
    if (x != 30) frontier.push_back(b.At(x, 30));
  }
  // Mean-shift alone makes one cluster whose centre lies in the wall.
  const MeanShiftClusters clusters = MeanShift(frontier, {});
  ASSERT_EQ(clusters.centres.size(), 1u);
  EXPECT_EQ(b.map().at(b.map().limits.CellContaining(clusters.centres[0])),
            grid::CellState::kOccupied);

  const PlanningMap map(b.map(), TraversabilityOptions{});
  const Eigen::Vector2d robot = b.At(10, 7);
  const PathDistanceField field(map, robot);
  NavigationPointStats stats;
  const auto points = ComputeNavigationPoints(map, field, frontier, robot, {}, {}, &stats);
  EXPECT_EQ(stats.clusters, 1);
  EXPECT_EQ(stats.components, 2);
  ASSERT_EQ(points.size(), 2u);
  const double wall_x = b.At(30, 0).x();
  EXPECT_NE(points[0].position.x() < wall_x, points[1].position.x() < wall_x);
  for (const NavigationPoint& p : points) {
    EXPECT_TRUE(Contains(frontier, p.position));
    EXPECT_EQ(p.component_size, 6);
    EXPECT_TRUE(std::isfinite(p.cost_m));
  }
  // The left point is the frontier point nearest the robot by path: x = 24
  // (x = 26..29 lie in the wall's inflation band; from (10, 7) the octile
  // path to x = 24 is 14√2 + 9 cells, to x = 25 it is 15√2 + 8).
  const auto& left = points[0].position.x() < wall_x ? points[0] : points[1];
  EXPECT_NEAR(left.position.x(), b.At(24, 30).x(), 1e-9);
}

// A corridor with the robot in the middle: its left end opens into a large
// unknown area, its right end into a six-column unknown pocket. Same path cost.
TEST(NavigationPointsTest, RevenuePrefersLargerUnknownAreaAtEqualCost) {
  MapBuilder b(80, 30);
  b.Wall(0, 0, 79, 29)
      .Fill(1, 1, 78, 28, grid::CellState::kUnknown)
      .Wall(11, 1, 78, 9)
      .Wall(11, 20, 78, 28)
      .Free(11, 10, 69, 19);
  b.Wall(76, 10, 78, 19);  // pocket = x 70..75 stays unknown
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const Eigen::Vector2d robot = b.At(40, 15);
  const PathDistanceField field(map, robot);
  const auto points = ComputeNavigationPoints(map, field, b.FrontierPoints(), robot, {}, {});
  ASSERT_GE(points.size(), 2u);
  const NavigationPoint& first = points.front();
  const NavigationPoint& last = points.back();
  EXPECT_LT(first.position.x(), robot.x());
  EXPECT_GT(last.position.x(), robot.x());
  EXPECT_NEAR(first.cost_m, last.cost_m, 0.15);
  EXPECT_GT(first.info_gain_m2, 2.0 * last.info_gain_m2);
  EXPECT_GT(first.revenue, last.revenue);

  // Hysteresis: with the current goal at the pocket, the pocket wins.
  const auto sticky =
      ComputeNavigationPoints(map, field, b.FrontierPoints(), robot, last.position, [] {
        NavigationPointOptions o;
        o.hysteresis_gain = 10.0;
        return o;
      }());
  EXPECT_GT(sticky.front().position.x(), robot.x());

  // With info_visible_range_m the gain is what a lidar at the point would
  // see: all of the large area's 10 x 28 unknown cells (the walls stop the
  // rays at the map's edge), and the ranking stays.
  NavigationPointOptions visible;
  visible.info_visible_range_m = 4.0;
  const auto seen = ComputeNavigationPoints(map, field, b.FrontierPoints(), robot, {}, visible);
  ASSERT_EQ(seen.size(), points.size());
  EXPECT_EQ(seen.front().position, first.position);
  EXPECT_DOUBLE_EQ(seen.front().info_gain_m2,
                   UnknownAreaVisible(map, first.position, 4.0, visible.outside_map_is_unknown));
  EXPECT_NEAR(seen.front().info_gain_m2, 2.8, 1e-9);
  EXPECT_GT(seen.front().info_gain_m2, 1.5 * first.info_gain_m2);
}

// The unknown area a lidar at the point would see: all of an open unknown
// disc, the disc less the shadow of a wall, and nothing when free space lies
// between the point and the wall and unknown space only behind it. Rays count
// the cells they touch, so the area lies between that of the range and that
// of the range plus one cell.
TEST(NavigationPointsTest, VisibleUnknownAreaStopsAtWalls) {
  const double range_m = 2.0, cell_m = 0.1;
  const auto disc_m2 = [](double r) { return M_PI * r * r; };
  // The circular segment beyond a chord 'd' from the centre, and the rest.
  const auto segment_m2 = [](double r, double d) {
    return r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
  };
  const auto lit_m2 = [&](double r, double d) { return disc_m2(r) - segment_m2(r, d); };
  const auto visible = [&](const MapBuilder& b, const Eigen::Vector2d& p, double r, bool outside) {
    return UnknownAreaVisible(PlanningMap(b.map(), TraversabilityOptions{}), p, r, outside);
  };
  MapBuilder open(60, 60);
  open.Wall(0, 0, 59, 59).Fill(1, 1, 58, 58, grid::CellState::kUnknown);
  const Eigen::Vector2d p = open.At(30, 30);
  EXPECT_GE(visible(open, p, range_m, false), 0.97 * disc_m2(range_m));
  EXPECT_LE(visible(open, p, range_m, false), disc_m2(range_m + cell_m));

  // A wall whose near face is 0.45 m from the point.
  MapBuilder walled = open;
  walled.Wall(35, 1, 35, 58);
  EXPECT_GE(visible(walled, p, range_m, false), 0.97 * lit_m2(range_m, 0.45));
  EXPECT_LE(visible(walled, p, range_m, false), lit_m2(range_m + cell_m, 0.45));

  walled.Free(1, 1, 34, 58);
  EXPECT_EQ(visible(walled, p, range_m, false), 0.0);
  // Outside the map counts as unknown when asked: a point 0.15 m from the
  // edge of a free map sees the segment of the disc beyond it.
  MapBuilder edge(30, 30);
  edge.Free(0, 0, 29, 29);
  EXPECT_EQ(visible(edge, edge.At(15, 15), 1.0, true), 0.0);
  EXPECT_EQ(visible(edge, edge.At(28, 15), 1.0, false), 0.0);
  EXPECT_GE(visible(edge, edge.At(28, 15), 1.0, true), 0.97 * segment_m2(1.0, 0.15));
  EXPECT_LE(visible(edge, edge.At(28, 15), 1.0, true), segment_m2(1.0 + cell_m, 0.15));
}

TEST(NavigationPointsTest, ConnectivityLeaksNeitherThroughDiagonalWalls) {
  MapBuilder b(20, 20, 0.1, grid::CellState::kFree);
  for (int i = 0; i < 20; ++i) b.Wall(i, i, i, i);  // a diagonal chain of occupied cells
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const auto label = SplitByConnectivity(map, {b.At(3, 10), b.At(10, 3), b.At(4, 12)}, 1.0);
  EXPECT_NE(label[0], label[1]);
  EXPECT_EQ(label[0], label[2]);
}

// A goal selection ranks one partition several times on one path distance
// field, settled farther each time, and keeps the cells it found reached
// (FrontierPartition::reached): every ranking must equal one on a partition
// that has seen no field.
RC_GTEST_PROP(NavigationPointsProperty, RankingAgainOnAFieldSettledFartherEqualsAFreshRanking, ()) {
  const int w = *rc::gen::inRange(8, 40), h = *rc::gen::inRange(8, 40);
  MapBuilder b(w, h, 0.05, grid::CellState::kUnknown);
  b.Free(1, 1, w - 2, h - 2);
  const int walls = *rc::gen::inRange(0, 6);
  for (int k = 0; k < walls; ++k) {
    const int x = *rc::gen::inRange(0, w), y = *rc::gen::inRange(0, h);
    const int len = *rc::gen::inRange(1, 30);
    if (*rc::gen::arbitrary<bool>()) {
      b.Wall(x, y, x + len, y);
    } else {
      b.Wall(x, y, x, y + len);
    }
  }
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  RC_PRE(!frontier.empty());
  TraversabilityOptions trav;
  trav.robot_radius_m = 0.1;
  trav.safety_margin_m = 0.05;
  trav.narrow_margin_m = 0.02;
  const PlanningMap map(b.map(), trav);
  const Eigen::Vector2d robot = b.At(*rc::gen::inRange(1, w - 1), *rc::gen::inRange(1, h - 1));
  NavigationPointOptions options;
  options.mean_shift.bandwidth_m = 0.3;
  const FrontierPartition kept = PartitionFrontier(map, frontier, options);
  PathDistanceField field(map, StartRegion(map, robot), *rc::gen::inRange(0, 20) * 0.05);
  for (const double settle_m : {0.3, 0.8, 1.5, std::numeric_limits<double>::infinity()}) {
    field.SettleUpTo(settle_m);
    const std::vector<NavigationPoint> again =
        ComputeNavigationPoints(map, field, kept, robot, std::nullopt, options);
    const std::vector<NavigationPoint> fresh = ComputeNavigationPoints(
        map, field, PartitionFrontier(map, frontier, options), robot, std::nullopt, options);
    RC_ASSERT(again.size() == fresh.size());
    for (size_t i = 0; i < again.size(); ++i) {
      RC_ASSERT(again[i].position == fresh[i].position);
      RC_ASSERT(again[i].cost_m == fresh[i].cost_m);
      RC_ASSERT(again[i].reached_cell == fresh[i].reached_cell);
      RC_ASSERT(again[i].revenue == fresh[i].revenue);
      RC_ASSERT(again[i].component_size == fresh[i].component_size);
    }
  }
}

// The connectivity split labels points as an independent flood of each
// point's 4-connected region of non-occupied cells inside the window would:
// the same label exactly when connected, numbered by first appearance, and
// a label of its own for a point on an occupied cell or outside the window.
RC_GTEST_PROP(NavigationPointsProperty, ConnectivitySplitMatchesAFloodPerPoint, ()) {
  const int w = *rc::gen::inRange(1, 25), h = *rc::gen::inRange(1, 25);
  MapBuilder b(w, h, 0.1, grid::CellState::kFree);
  const int occupied_percent = *rc::gen::inRange(0, 60);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (*rc::gen::inRange(0, 100) < occupied_percent) b.Wall(x, y, x, y);
    }
  }
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const grid::MapLimits& limits = map.limits();
  std::vector<Eigen::Vector2d> points;
  const int n = *rc::gen::inRange(1, 12);
  for (int i = 0; i < n; ++i) {
    // Some points beyond the map too.
    points.emplace_back(*rc::gen::inRange(-5, 10 * w + 5) * 0.01 * 1.0 + 0.003,
                        *rc::gen::inRange(-5, 10 * h + 5) * 0.01 * 1.0 + 0.003);
  }
  const double margin_m = *rc::gen::element(0.0, 0.1, 0.35, 5.0);
  const std::vector<int> label = SplitByConnectivity(map, points, margin_m);

  // The oracle: the window as SplitByConnectivity defines it, and per point
  // the set of cells its flood reaches.
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const Eigen::Vector2d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  grid::CellIndex a = limits.CellContaining(lo - Eigen::Vector2d(margin_m, margin_m));
  grid::CellIndex c = limits.CellContaining(hi + Eigen::Vector2d(margin_m, margin_m));
  a = {std::max(a.x, 0), std::max(a.y, 0)};
  c = {std::min(c.x, w - 1), std::min(c.y, h - 1)};
  const auto inside = [&](const grid::CellIndex& q) {
    return q.x >= a.x && q.y >= a.y && q.x <= c.x && q.y <= c.y &&
           map.state(limits.FlatIndex(q)) != grid::CellState::kOccupied;
  };
  const auto flood = [&](const grid::CellIndex& start) {
    std::set<std::pair<int, int>> seen;
    if (!inside(start)) return seen;
    std::vector<grid::CellIndex> todo = {start};
    seen.insert({start.x, start.y});
    while (!todo.empty()) {
      const grid::CellIndex u = todo.back();
      todo.pop_back();
      for (const auto& d : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const grid::CellIndex v{u.x + d.first, u.y + d.second};
        if (inside(v) && seen.insert({v.x, v.y}).second) todo.push_back(v);
      }
    }
    return seen;
  };
  std::vector<int> expected(points.size());
  int next = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const grid::CellIndex ci = limits.CellContaining(points[i]);
    expected[i] = -1;
    if (inside(ci)) {
      const auto region = flood(ci);
      for (size_t j = 0; j < i; ++j) {
        const grid::CellIndex cj = limits.CellContaining(points[j]);
        if (region.count({cj.x, cj.y})) {
          expected[i] = expected[j];
          break;
        }
      }
    }
    if (expected[i] < 0) expected[i] = next++;
  }
  RC_ASSERT(label == expected);
}

TEST(NavigationPointsTest, OptionsAreValidatedByName) {
  NavigationPointOptions o;
  o.mean_shift.bandwidth_m = 0.0;
  try {
    Validate(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bandwidth_m"), std::string::npos);
  }
  o = {};
  o.info_radius_m = -1;
  EXPECT_THROW(Validate(o), std::invalid_argument);
  for (const double range_m : {-1.0, 21.0, std::nan("")}) {
    o = {};
    o.info_visible_range_m = range_m;
    EXPECT_THROW(Validate(o), std::invalid_argument) << range_m;
  }
}

// Random rooms: every navigation point is an input frontier point with a path
// from the robot, and the hash-grid mean-shift matches a brute-force one.
// A walled 40 x 30 cell room with up to 7 random blocks of wall or unknown.
MapBuilder RandomRoom() {
  MapBuilder b(40, 30);
  b.Wall(0, 0, 39, 29).Free(1, 1, 38, 28);
  const int blocks = *rc::gen::inRange(0, 8);
  for (int i = 0; i < blocks; ++i) {
    const int x = *rc::gen::inRange(1, 36), y = *rc::gen::inRange(1, 26);
    const int w = *rc::gen::inRange(1, 10), h = *rc::gen::inRange(1, 10);
    const bool wall = *rc::gen::arbitrary<bool>();
    b.Fill(x, y, x + w, y + h, wall ? grid::CellState::kOccupied : grid::CellState::kUnknown);
  }
  return b;
}

// A robot on a random traversable cell of 'map' (built from 'b').
Eigen::Vector2d RandomRobot(const MapBuilder& b, const PlanningMap& map) {
  const Eigen::Vector2d robot = b.At(*rc::gen::inRange(1, 39), *rc::gen::inRange(1, 29));
  RC_PRE(map.Traversable(map.limits().CellContaining(robot)));
  return robot;
}

// A RandomRoom, its planning map, a robot in it, the path distances from the
// robot and the room's frontier.
struct RandomScene {
  MapBuilder builder = RandomRoom();
  PlanningMap map{builder.map(), testing::SmallRobot()};
  Eigen::Vector2d robot = RandomRobot(builder, map);
  PathDistanceField field{map, robot};
  std::vector<Eigen::Vector2d> frontier = builder.FrontierPoints();
};

RC_GTEST_PROP(NavigationPointsProperty, PointsAreReachableFrontierPoints, ()) {
  const RandomScene s;
  const auto points = ComputeNavigationPoints(s.map, s.field, s.frontier, s.robot, {}, {});
  std::set<std::pair<int, int>> seen;
  for (const NavigationPoint& p : points) {
    RC_ASSERT(Contains(s.frontier, p.position));
    const auto reached = s.field.NearestReached(p.position, s.map.options().goal_snap_radius_m);
    RC_ASSERT(reached.has_value());
    RC_ASSERT(std::abs(reached->distance_m - p.cost_m) < 1e-4);
    const grid::CellIndex c = s.map.limits().CellContaining(p.position);
    RC_ASSERT(seen.insert({c.x, c.y}).second);
    // The planner agrees: a path exists and is no shorter than the cost.
    const auto path = PathPlanner({}).Plan(s.map, s.robot, p.position);
    RC_ASSERT(path.has_value());
    RC_ASSERT(std::abs(path->cell_path_length_m -
                       (p.cost_m -
                        (s.robot - s.map.limits().CellCenter(*s.field.start())).norm())) < 1e-3);
  }
}

// The goal manager clusters the frontier (Prepare) on another thread while it
// computes the path distances; the ranking must be the one Rank computes
// on its own, and so must ComputeNavigationPoints on a ready partition.
RC_GTEST_PROP(NavigationPointsProperty, PreparedPartitionRanksAsRankAlone, ()) {
  const RandomScene s;
  std::vector<Eigen::Vector2d> avoid;
  if (!s.frontier.empty()) avoid.push_back(s.frontier[s.frontier.size() / 2]);

  const auto direct = ComputeNavigationPoints(s.map, s.field, s.frontier, s.robot, {}, {});
  const auto split = ComputeNavigationPoints(
      s.map, s.field, PartitionFrontier(s.map, s.frontier, {}), s.robot, {}, {});
  RC_ASSERT(direct.size() == split.size());
  for (size_t i = 0; i < direct.size(); ++i) {
    RC_ASSERT(direct[i].position == split[i].position);
    RC_ASSERT(direct[i].revenue == split[i].revenue);
    RC_ASSERT(direct[i].component_size == split[i].component_size);
  }

  const std::unique_ptr<GoalPolicy> policy = MakeGoalPolicy("scout", {});
  PolicyInput in;
  in.map = &s.map;
  in.frontier = &s.frontier;
  in.robot = s.robot;
  in.avoid = &avoid;
  in.avoid_radius_m = 0.3;
  const std::any prepared = policy->Prepare(in);
  in.distances = &s.field;
  const std::vector<GoalCandidate> alone = policy->Rank(in);
  in.prepared = &prepared;
  const std::vector<GoalCandidate> with_prepared = policy->Rank(in);
  RC_ASSERT(alone.size() == with_prepared.size());
  for (size_t i = 0; i < alone.size(); ++i) {
    RC_ASSERT(alone[i].position == with_prepared[i].position);
    RC_ASSERT(alone[i].score == with_prepared[i].score);
  }
}

}  // namespace
}  // namespace scout::explore
