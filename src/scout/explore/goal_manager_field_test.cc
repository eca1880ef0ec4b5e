// The goal manager settles its path distance fields only as far as a goal
// selection or a re-ranking needs (GoalManager::ReachAndRank). Its decisions
// must be those it makes with complete fields, step for step.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <memory>
#include <string_view>
#include <vector>

#include "scout/explore/goal_manager.h"
#include "scout/explore/goal_manager_test_util.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// Scout's policy, claiming no bound of its scores above path cost: the goal
// manager then settles every field completely.
class CompleteFieldsScout : public GoalPolicy {
 public:
  explicit CompleteFieldsScout(const GoalPolicyOptions& o) : scout_(MakeGoalPolicy("scout", o)) {}
  std::string_view name() const override { return scout_->name(); }
  bool needs_path_distances() const override { return scout_->needs_path_distances(); }
  bool checks_paths_against_scan() const override { return scout_->checks_paths_against_scan(); }
  bool keeps_stand_off_from_unknown() const override {
    return scout_->keeps_stand_off_from_unknown();
  }
  std::any Prepare(const PolicyInput& in) const override { return scout_->Prepare(in); }
  std::vector<GoalCandidate> Rank(const PolicyInput& in) const override { return scout_->Rank(in); }

 private:
  std::unique_ptr<GoalPolicy> scout_;
};

// A building of w x h cells (0.1 m) with random walls, each with a door,
// explored by a robot that sees 2.5 or 5 m around itself (through walls: the
// map only has to change) and jumps 0.4 m along its path every half second.
RC_GTEST_PROP(GoalManagerProperty, PartialPathDistanceFieldsDecideAsCompleteOnes, ()) {
  const int w = *rc::gen::inRange(40, 120), h = *rc::gen::inRange(40, 90);
  MapBuilder truth(w, h, 0.1, grid::CellState::kFree);
  truth.Wall(0, 0, w - 1, 0).Wall(0, h - 1, w - 1, h - 1).Wall(0, 0, 0, h - 1);
  truth.Wall(w - 1, 0, w - 1, h - 1);
  for (int walls = *rc::gen::inRange(0, 5); walls > 0; --walls) {
    const int door = *rc::gen::inRange(10, 60);
    if (*rc::gen::arbitrary<bool>()) {
      const int x = *rc::gen::inRange(10, w - 10), d = *rc::gen::inRange(1, h - 13);
      truth.Wall(x, 0, x, h - 1).Free(x, d, x, std::min(h - 2, d + door / 5 + 8));
    } else {
      const int y = *rc::gen::inRange(10, h - 10), d = *rc::gen::inRange(1, w - 13);
      truth.Wall(0, y, w - 1, y).Free(d, y, std::min(w - 2, d + door / 5 + 8), y);
    }
  }
  Eigen::Vector2d robot = truth.At(*rc::gen::inRange(5, w - 5), *rc::gen::inRange(5, h - 5));
  RC_PRE(truth.map().at(truth.map().limits.CellContaining(robot)) == grid::CellState::kFree);

  GoalPolicyOptions policy;
  // A small gain bound (about 1.6 m with the hysteresis) against the map's
  // size, so that most fields stay partial.
  policy.navigation.info_radius_m = *rc::gen::element(0.3, 0.5, 1.0);
  policy.navigation.hysteresis_gain = *rc::gen::element(1.0, 2.0);
  GoalManagerOptions options = testing::NoStuckRecovery();
  // Without a margin the re-ranking switches goals often.
  options.goal_switch_margin = *rc::gen::element(0.0, 5.0);
  const int sight = *rc::gen::element(25, 50);  // cells
  GoalManager partial(options, {}, {}, {}, MakeGoalPolicy("scout", policy));
  GoalManager complete(options, {}, {}, {}, std::make_unique<CompleteFieldsScout>(policy));
  // Partial fields begin at the bound itself and grow by a cell or a few, so
  // that the goal manager extends them often on these small maps.
  partial.SetPartialFieldExtentsForTesting(
      {0.0, *rc::gen::element(0.1, 0.5), *rc::gen::element(0.0, 1.5)});
  partial.Start();
  complete.Start();

  MapBuilder known(w, h, 0.1, grid::CellState::kUnknown);
  for (int step = 0; step < 40; ++step) {
    const grid::CellIndex at = known.map().limits.CellContaining(robot);
    for (int y = at.y - sight; y <= at.y + sight; ++y) {
      for (int x = at.x - sight; x <= at.x + sight; ++x) {
        if (!truth.map().limits.Contains({x, y}) ||
            (x - at.x) * (x - at.x) + (y - at.y) * (y - at.y) > sight * sight)
          continue;
        known.Fill(x, y, x, y, truth.map().at({x, y}));
      }
    }
    const std::vector<Eigen::Vector2d> frontier = known.FrontierPoints();
    const ExploreInput in = testing::InputAt(0.5 * step, robot, known.map(), frontier, true);
    const ExploreStatus a = partial.Update(in);
    const ExploreStatus b = complete.Update(in);
    RC_ASSERT(a.state == b.state);
    RC_ASSERT(a.goal == b.goal);
    RC_ASSERT(a.target == b.target);
    RC_ASSERT(a.path == b.path);
    RC_ASSERT(a.frontier_left == b.frontier_left);
    RC_ASSERT(a.reachable_frontier_left == b.reachable_frontier_left);
    if (a.state == ExploreState::kFinished) break;
    // Along the path by 0.4 m.
    double left_m = 0.4;
    for (size_t i = 1; i < a.path.size() && left_m > 0.0; ++i) {
      const Eigen::Vector2d leg = a.path[i] - robot;
      if ((a.path[i] - a.path[i - 1]).dot(leg) <= 0.0) continue;  // behind the robot
      const double n = leg.norm();
      if (n <= left_m) {
        robot = a.path[i], left_m -= n;
      } else {
        robot += leg * (left_m / n), left_m = 0.0;
      }
    }
  }
  const ExploreCounters& ca = partial.counters();
  const ExploreCounters& cb = complete.counters();
  RC_ASSERT(ca.goals_issued == cb.goals_issued);
  RC_ASSERT(ca.goals_seen == cb.goals_seen);
  RC_ASSERT(ca.goals_superseded == cb.goals_superseded);
  RC_ASSERT(ca.goals_unreachable == cb.goals_unreachable);
  RC_ASSERT(ca.selections == cb.selections);
  RC_ASSERT(ca.escapes == cb.escapes);
}

}  // namespace
}  // namespace scout::explore
