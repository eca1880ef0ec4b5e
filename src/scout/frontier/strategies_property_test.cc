// Properties of the update strategies on random layouts and pose sequences:
// exact and dfd always equal full; bfs and direct never query more than dfd.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "scout/frontier/exact_strategy.h"
#include "scout/frontier/frontier_engine.h"
#include "scout/frontier/random_scenario.h"

namespace scout::frontier {
namespace {

using testing::Perturb;
using testing::RandomScenario;

const StrategyRound& LastRound(const FrontierEngine& engine, const std::string& name) {
  for (auto it = engine.rounds().rbegin(); it != engine.rounds().rend(); ++it) {
    if (it->strategy == name) return *it;
  }
  throw std::logic_error("no round for " + name);
}

struct Outcome {
  int64_t positives = 0, negatives = 0;
  int64_t inexact_errors = 0;  // bfs + direct wrong answers, summed over rounds
};

// Runs one random scenario and checks every round; returns what was seen.
// With 'defer', grid changes are coalesced and applied at random flushes (and
// at every round), so batches of several changes per submap are checked too.
Outcome RunScenario(uint64_t seed, double exact_slack_m, int aligned_one_in, bool defer) {
  testing::RandomScenarioOptions o;
  RandomScenario s(seed, o);
  FrontierOptions options;
  options.inflation_radius_m = 0.1;
  options.exact_slack_m = exact_slack_m;
  options.defer_grid_changes = defer;
  FrontierEngine engine(options, {"full", "dfd", "bfs", "direct", "exact"}, true);
  std::vector<geometry::Rigid2d> truth, estimate;
  Outcome out;
  // Between optimisations too (after grid changes), the exact strategies must
  // agree with full point by point: exploration reads answers at any time.
  const auto check_answers = [&] {
    if (defer && s.Int(3) == 0) engine.Flush();
    if (engine.has_pending_changes()) return;
    for (int i = 0; i < engine.catalog().size(); ++i) {
      RC_ASSERT(engine.strategy("exact").answers(i) == engine.strategy("full").answers(i));
      RC_ASSERT(engine.strategy("dfd").answers(i) == engine.strategy("full").answers(i));
    }
  };
  const auto check_round = [&] {
    check_answers();
    for (const std::string name : {"dfd", "exact"}) {
      const Confusion& c = LastRound(engine, name).confusion;
      RC_ASSERT(c.fp == 0);
      RC_ASSERT(c.fn == 0);
    }
    const int64_t dfd = LastRound(engine, "dfd").cost.queried_points;
    RC_ASSERT(LastRound(engine, "bfs").cost.queried_points <= dfd);
    RC_ASSERT(LastRound(engine, "direct").cost.queried_points <= dfd);
    const Confusion& truth_c = LastRound(engine, "full").confusion;
    out.positives += truth_c.tp;
    out.negatives += truth_c.tn;
    for (const std::string name : {"bfs", "direct"}) {
      const Confusion& c = LastRound(engine, name).confusion;
      out.inexact_errors += c.fp + c.fn;
    }
  };
  std::vector<int> grown(o.num_submaps, 0);
  // A grid change: one of the first 'n' submaps sees farther and its grid grows.
  const auto grow_one = [&](int n) {
    const int k = s.Int(n);
    grown[k] += s.Int(6);
    engine.Apply(s.MakeSubmap(k, truth[k], s.Uniform(1.5, 2.9 + 0.1 * grown[k]), grown[k]));
    check_answers();
  };
  for (int id = 0; id < o.num_submaps; ++id) {
    const bool aligned = s.Int(aligned_one_in) == 0;
    truth.push_back(s.TruePose(aligned));
    engine.Apply(s.MakeSubmap(id, truth.back(), s.Uniform(1.0, 2.9)));
    check_answers();
    estimate.push_back(aligned ? truth.back() : Perturb(s, truth.back(), 0.03, 0.01));
    if (id % 2 == 1) {
      engine.Apply(events::Optimized{estimate});
      check_round();
    }
    if (s.Int(2) == 0) grow_one(id + 1);
  }
  for (int round = 0; round < 12; ++round) {
    // Kind 5 is a loop closure moving submaps by metres: pairs stop (or start)
    // overlapping and exact's witnesses are lost and found again.
    const int kind = s.Int(6);
    const double t = kind == 0 ? 2e-4 : kind == 1 ? 4e-3 : kind == 2 ? 0.03 : kind == 5 ? 1.5 : 0.4;
    for (size_t k = 0; k < estimate.size(); ++k) {
      if (s.Int(2) != 0) continue;
      if (kind == 4) {
        // Whole half-cell shifts keep lattice-aligned submaps aligned.
        const double half = o.resolution_m / 2;
        estimate[k] =
            geometry::Rigid2d(estimate[k].x() + half * (s.Int(5) - 2),
                              estimate[k].y() + half * (s.Int(5) - 2), estimate[k].theta());
      } else {
        estimate[k] = Perturb(s, estimate[k], t, t / 4);
      }
    }
    engine.Apply(events::Optimized{estimate});
    check_round();
    if (s.Int(2) == 0) grow_one(o.num_submaps);
  }
  return out;
}

RC_GTEST_PROP(Strategies, ExactAndDfdEqualFullEveryRound, ()) {
  const uint64_t seed = *rc::gen::arbitrary<uint64_t>();
  const double slack = *rc::gen::element(0.05, 0.2, 0.5, 2.0);
  // All, a third, or none of the submaps on one lattice (answers on cell borders).
  const int aligned_one_in = *rc::gen::element(1, 3, 1000000);
  const bool defer = *rc::gen::arbitrary<bool>();
  const Outcome out = RunScenario(seed, slack, aligned_one_in, defer);
  // The scenario must exercise both answers, or the check above is empty.
  RC_TAG(out.positives > 0 && out.negatives > 0 ? "both answers" : "one-sided");
}

TEST(Strategies, ScenariosExerciseBothAnswersAndInexactStrategiesErr) {
  int64_t positives = 0, negatives = 0, inexact_errors = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const Outcome out = RunScenario(seed, 0.5, 3, seed % 2 == 0);
    positives += out.positives;
    negatives += out.negatives;
    inexact_errors += out.inexact_errors;
  }
  EXPECT_GT(positives, 0);
  EXPECT_GT(negatives, 0);
  // Small pose changes below epsilon flip answers that bfs/direct keep stale:
  // this is what exact fixes, so the scenarios must show it.
  EXPECT_GT(inexact_errors, 0);
}

// Submap 0 and submap 1, which sees farther around the same place and covers
// 0's frontier ring while it is there; 'away' is a pose of 1 far from 0.
class CoverMovesAway : public ::testing::Test {
 protected:
  static FrontierOptions Options() {
    FrontierOptions options;
    options.inflation_radius_m = 0.1;
    return options;
  }
  CoverMovesAway() {
    engine.Apply(s.MakeSubmap(0, pose, 1.0));
    engine.Apply(s.MakeSubmap(1, pose, 2.5));
  }
  RandomScenario s{11, {}};
  FrontierEngine engine{Options(), {"full", "exact"}, true};
  const geometry::Rigid2d pose = s.TruePose();
  const geometry::Rigid2d away{pose.x() + 40.0, pose.y(), pose.theta()};
};

// Exact updates only the submaps an optimisation can affect. A submap that
// does not move must still be updated when the one submap that covered its
// frontier moves away, and again when it moves back over it.
TEST_F(CoverMovesAway, ExactUpdatesASubmapThatStaysWhenItsCoverMovesAwayAndBack) {
  const auto frontier_points_of_0 = [&] {
    const std::vector<uint8_t>& full = engine.strategy("full").answers(0);
    EXPECT_EQ(engine.strategy("exact").answers(0), full);
    return std::count(full.begin(), full.end(), 1);
  };
  engine.Apply(events::Optimized{{pose, pose}});
  const auto covered = frontier_points_of_0();
  engine.Apply(events::Optimized{{pose, away}});
  const auto uncovered = frontier_points_of_0();
  engine.Apply(events::Optimized{{pose, pose}});
  EXPECT_EQ(frontier_points_of_0(), covered);
  // Submap 0's frontier is hidden while 1 covers it, and its own once 1 left.
  EXPECT_GT(uncovered, covered);
  EXPECT_EQ(uncovered, static_cast<int64_t>(engine.catalog().submap(0).frontier.points_m.size()));
}

// A point whose witness comes and goes is added again to the watches that do
// not object; a watch that held it already must not hold it twice, or a long
// run's passes grow with every loop closure that uncovers it.
TEST_F(CoverMovesAway, ExactKeepsOneEntryPerPointWhileItsWitnessComesAndGoes) {
  // 2 sees as far as 0 around the same place: neither objects at the other's
  // frontier ring, and 1 covers both rings while it is there.
  engine.Apply(s.MakeSubmap(2, pose, 1.0));
  const auto& exact = dynamic_cast<const ExactStrategy&>(engine.strategy("exact"));
  std::vector<int64_t> entries;
  for (int cycle = 0; cycle < 6; ++cycle) {
    engine.Apply(events::Optimized{{pose, pose, pose}});
    engine.Apply(events::Optimized{{pose, away, pose}});
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(exact.answers(i), engine.strategy("full").answers(i)) << "cycle " << cycle;
    }
    entries.push_back(exact.num_entries());
  }
  // The uncovered rings are stored (their margins are small), the same ones every cycle.
  EXPECT_GT(entries.front(), 0);
  for (const int64_t n : entries) EXPECT_EQ(n, entries.front());
}

// Most points of a pair whose boxes meet lie outside the other submap's grid,
// where it objects nowhere. Here the corner of submap 1's box reaches into the
// box of submap 0's frontier ring, the ring itself does not: when 1 moves by
// more than the slack, exact proves from the box distance alone that 1 still
// objects at none of the ring's points, and looks none of them up.
TEST(ExactStrategy, ProvesPointsOutsideTheOtherGridWithoutLookUps) {
  testing::RandomScenarioOptions o;
  o.wall_density = 0.0;  // a whole ring
  RandomScenario s(5, o);
  FrontierOptions options;
  options.inflation_radius_m = 0.1;
  FrontierEngine engine(options, {"full", "exact"}, true);
  const geometry::Rigid2d pose(6.0, 6.0, 0.0);
  engine.Apply(s.MakeSubmap(0, pose, 1.8));
  engine.Apply(s.MakeSubmap(1, pose, 1.0));
  engine.Flush();  // grid changes wait for the next round by default
  const SubmapCatalog& catalog = engine.catalog();
  std::vector<Eigen::Vector2d> ring;
  for (const Eigen::Vector2d& p : catalog.submap(0).frontier.points_m) ring.push_back(pose * p);
  ASSERT_FALSE(ring.empty());
  // How far into the north-east corner the ring reaches (global frame).
  double ring_corner = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& g : ring) ring_corner = std::max(ring_corner, std::min(g.x(), g.y()));
  const double box_corner = catalog.GlobalPointsBox(0).max.x();
  const double half_size = o.submap_size_m / 2;
  // Submap 1's south-west corner at 'corner' on the diagonal.
  const auto with_corner_at = [&](double corner) {
    return geometry::Rigid2d(corner + half_size, corner + half_size, 0.0);
  };
  const double before = ring_corner + 0.05, after = box_corner - 0.05;
  ASSERT_GT((after - before) * std::sqrt(2.0), options.exact_slack_m);  // a re-anchoring move
  for (const double corner : {before, after}) {
    engine.Apply(events::Optimized{{pose, with_corner_at(corner)}});
    ASSERT_TRUE(catalog.submap(1).global_box.Intersects(catalog.GlobalPointsBox(0)));
    for (const Eigen::Vector2d& g : ring) ASSERT_FALSE(catalog.submap(1).global_box.Contains(g));
    EXPECT_EQ(engine.strategy("exact").answers(0), engine.strategy("full").answers(0));
  }
  EXPECT_EQ(LastRound(engine, "exact").cost.queried_points, 0);
  EXPECT_GT(LastRound(engine, "full").cost.queried_points, 0);
}

}  // namespace
}  // namespace scout::frontier
