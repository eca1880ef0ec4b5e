#include "scout/explore/goal_policies.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// Open space below (robot), unknown above y = 30, a wall at x = 30 rising from
// y = 15 into the unknown, and frontier pieces x 24..29 and 31..36 at y = 30.
struct SplitScene {
  MapBuilder b{60, 50};
  std::vector<Eigen::Vector2d> frontier;
  SplitScene() {
    b.Wall(0, 0, 59, 49).Free(1, 1, 58, 30).Fill(1, 31, 58, 48, grid::CellState::kUnknown);
    b.Wall(30, 15, 30, 48);
    for (int x = 24; x <= 36; ++x) {
      if (x != 30) frontier.push_back(b.At(x, 30));
    }
  }
};

std::vector<GoalCandidate> RankWith(std::string_view name, const MapBuilder& b,
                                    const std::vector<Eigen::Vector2d>& frontier,
                                    const Eigen::Vector2d& robot,
                                    const GoalPolicyOptions& options = {}) {
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const PathDistanceField field(map, robot);
  const auto policy = MakeGoalPolicy(name, options);
  PolicyInput in;
  in.map = &map;
  in.distances = &field;
  in.frontier = &frontier;
  in.robot = robot;
  return policy->Rank(in);
}

TEST(GoalPoliciesTest, NearestIsTheStraightLineNearestFrontierPoint) {
  SplitScene s;
  const auto goals = RankWith("nearest", s.b, s.frontier, s.b.At(10, 7));
  ASSERT_EQ(goals.size(), s.frontier.size());
  // From (10, 7): (24, 30) is at sqrt(14² + 23²) cells, the least.
  EXPECT_EQ(goals.front().position, s.b.At(24, 30));
  for (size_t i = 1; i < goals.size(); ++i) EXPECT_GE(goals[i - 1].score, goals[i].score);
}

TEST(GoalPoliciesTest, MeanShiftCentreLiesInTheWallScoutsPointsDoNot) {
  SplitScene s;
  const auto centres = RankWith("meanshift-centres", s.b, s.frontier, s.b.At(10, 7));
  ASSERT_EQ(centres.size(), 1u);
  EXPECT_EQ(s.b.map().at(s.b.map().limits.CellContaining(centres[0].position)),
            grid::CellState::kOccupied);
  const auto scout = RankWith("scout", s.b, s.frontier, s.b.At(10, 7));
  ASSERT_EQ(scout.size(), 2u);
  for (const GoalCandidate& g : scout) {
    EXPECT_EQ(s.b.map().at(s.b.map().limits.CellContaining(g.position)), grid::CellState::kFree);
  }
}

// meanshift-centres ranks its centres with Scout's information gain, the
// visible one included: score = gain - straight-line distance.
TEST(GoalPoliciesTest, MeanShiftCentresScoreTheVisibleGainWhenAsked) {
  SplitScene s;
  const Eigen::Vector2d robot = s.b.At(10, 7);
  GoalPolicyOptions visible;
  visible.navigation.info_visible_range_m = 3.0;
  const auto disc = RankWith("meanshift-centres", s.b, s.frontier, robot);
  const auto seen = RankWith("meanshift-centres", s.b, s.frontier, robot, visible);
  ASSERT_EQ(disc.size(), 1u);
  ASSERT_EQ(seen.size(), 1u);
  const PlanningMap map(s.b.map(), TraversabilityOptions{});
  const Eigen::Vector2d c = seen[0].position;
  EXPECT_NEAR(seen[0].score, UnknownAreaVisible(map, c, 3.0, true) - (c - robot).norm(), 1e-9);
  EXPECT_NEAR(disc[0].score, UnknownAreaWithin(map, c, 1.0, true) - (c - robot).norm(), 1e-9);
  // The centre lies in the wall (above): a lidar there sees nothing.
  EXPECT_EQ(UnknownAreaVisible(map, c, 3.0, true), 0.0);
  EXPECT_LT(seen[0].score, disc[0].score);
}

TEST(GoalPoliciesTest, ExploreLiteGoesToTheCentroidOfTheLargestSegmentEvenInAWall) {
  // A U of frontier cells around a pillar (x 11..13, y 11..16): its centroid
  // lies inside the pillar. A 3-cell segment elsewhere is below the 0.5 m
  // minimum size and ignored.
  MapBuilder b(40, 30, 0.1, grid::CellState::kFree);
  b.Wall(11, 11, 13, 16);
  std::vector<Eigen::Vector2d> u;
  for (int y = 10; y <= 16; ++y) u.push_back(b.At(10, y)), u.push_back(b.At(14, y));
  for (int x = 11; x <= 13; ++x) u.push_back(b.At(x, 10));
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const auto& p : u) centroid += p;
  centroid /= u.size();
  std::vector<Eigen::Vector2d> frontier = u;
  for (int x = 30; x <= 32; ++x) frontier.push_back(b.At(x, 25));

  const auto goals = RankWith("explore-lite", b, frontier, b.At(35, 5));
  ASSERT_EQ(goals.size(), 1u);
  EXPECT_NEAR((goals[0].position - centroid).norm(), 0.0, 1e-9);
  EXPECT_EQ(b.map().at(b.map().limits.CellContaining(goals[0].position)),
            grid::CellState::kOccupied);
  // cost = 1e-3 · distance − 1.0 · 17 cells · 0.1 m.
  const auto segments = FrontierSegments(b.map().limits, frontier, b.At(35, 5));
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].cells, 17);
  EXPECT_NEAR(goals[0].score, -(1e-3 * segments[0].min_distance_m - 1.7), 1e-9);
}

// The goal manager re-ranks while driving from a field settled only so far
// (GoalManager::ReachAndRank): every candidate missing from that ranking must
// lie farther and score at most ScoreAbovePathCost − settled_m(), and the
// candidates it has must be the complete ranking's, with the same scores and
// in the same order. Random rooms of free, unknown and occupied cells.
RC_GTEST_PROP(GoalPoliciesProperty, RankingFromAPartialFieldMissesOnlyCandidatesThatScoreLess, ()) {
  const int w = *rc::gen::inRange(6, 30), h = *rc::gen::inRange(6, 30);
  MapBuilder b(w, h, 0.1, grid::CellState::kFree);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int draw = *rc::gen::inRange(0, 100);
      if (draw < 15) b.Wall(x, y, x, y);
      if (draw >= 85) b.Fill(x, y, x, y, grid::CellState::kUnknown);
    }
  }
  const grid::CellIndex r{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
  b.Free(r.x, r.y, r.x, r.y);
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  RC_PRE(!frontier.empty());
  GoalPolicyOptions o;
  o.navigation.info_radius_m = *rc::gen::inRange(0, 8) * 0.1;
  o.navigation.info_visible_range_m = *rc::gen::element(0.0, 0.5);
  o.navigation.info_multiplier = *rc::gen::inRange(0, 30) * 0.1;
  o.navigation.hysteresis_gain = *rc::gen::inRange(0, 30) * 0.1;
  o.navigation.hysteresis_radius_m = *rc::gen::inRange(0, 20) * 0.1;
  TraversabilityOptions t;
  t.robot_radius_m = 0.0;
  t.safety_margin_m = 0.0;
  const PlanningMap map(b.map(), t);
  const StartRegion start(map, b.At(r.x, r.y));
  const PathDistanceField complete(map, start);
  const PathDistanceField part(map, start, *rc::gen::inRange(0, 40) * 0.1);
  const auto policy = MakeGoalPolicy("scout", o);
  PolicyInput in;
  in.map = &map;
  in.frontier = &frontier;
  in.robot = b.At(r.x, r.y);
  in.current_goal = frontier[*rc::gen::inRange<size_t>(0, frontier.size())];
  in.distances = &complete;
  const std::vector<GoalCandidate> all = policy->Rank(in);
  in.distances = &part;
  const std::vector<GoalCandidate> some = policy->Rank(in);
  const double above_cost = *policy->ScoreAbovePathCost(map);
  size_t j = 0;
  for (const GoalCandidate& c : all) {
    if (j < some.size() && c.position == some[j].position) {
      RC_ASSERT(c.score == some[j].score);
      ++j;
    } else {
      RC_ASSERT(c.score <= above_cost - part.settled_m() + 1e-9);
    }
  }
  RC_ASSERT(j == some.size());
}

// MaxInfoGainM2 bounds the information gain of any point, near the map's edge
// (outside counts as unknown) and in mostly unknown maps, for both gains.
RC_GTEST_PROP(GoalPoliciesProperty, InfoGainStaysWithinItsBound, ()) {
  const int w = *rc::gen::inRange(1, 30), h = *rc::gen::inRange(1, 30);
  MapBuilder b(w, h, 0.1, grid::CellState::kUnknown);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int draw = *rc::gen::inRange(0, 100);
      if (draw < 10) b.Wall(x, y, x, y);
      if (draw >= 10 && draw < 30) b.Free(x, y, x, y);
    }
  }
  NavigationPointOptions o;
  o.info_radius_m = *rc::gen::inRange(0, 15) * 0.1;
  o.info_visible_range_m = *rc::gen::element(0.0, 0.3, 1.2);
  o.outside_map_is_unknown = *rc::gen::arbitrary<bool>();
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const Eigen::Vector2d p(*rc::gen::inRange(-10, w * 10 + 10) * 0.01 * 1.0,
                          *rc::gen::inRange(-10, h * 10 + 10) * 0.01 * 1.0);
  const double bound = MaxInfoGainM2(0.1, o);
  RC_ASSERT(InfoGain(map, p, o) <= bound);
}

TEST(GoalPoliciesTest, UnknownNameIsRejectedWithTheChoices) {
  try {
    MakeGoalPolicy("frontier-magic", {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("explore-lite"), std::string::npos);
  }
  for (const std::string& name : GoalPolicyNames())
    EXPECT_EQ(MakeGoalPolicy(name, {})->name(), name);
}

}  // namespace
}  // namespace scout::explore
