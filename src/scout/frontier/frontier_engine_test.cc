#include "scout/frontier/frontier_engine.h"

#include <gtest/gtest.h>

#include "scout/common/error.h"
#include "scout/frontier/random_scenario.h"

namespace scout::frontier {
namespace {

TEST(Confusion, RatiosFollowTheirDefinitions) {
  Confusion c;
  c.tp = 8, c.fp = 2, c.tn = 85, c.fn = 5;
  EXPECT_DOUBLE_EQ(c.accuracy(), 93.0 / 100.0);
  EXPECT_DOUBLE_EQ(c.precision(), 8.0 / 10.0);
  EXPECT_DOUBLE_EQ(c.recall(), 8.0 / 13.0);
  EXPECT_DOUBLE_EQ(Confusion{}.precision(), 1.0);
}

TEST(FrontierEngine, RejectsUnknownAndDuplicateStrategies) {
  EXPECT_THROW(FrontierEngine(FrontierOptions{}, {"dfd", "magic"}, true), InputError);
  EXPECT_THROW(FrontierEngine(FrontierOptions{}, {"dfd", "dfd"}, true), InputError);
  EXPECT_THROW(FrontierEngine(FrontierOptions{}, {}, false), InputError);
  FrontierOptions bad;
  bad.epsilon_m = -1.0;
  EXPECT_THROW(FrontierEngine(bad, {"dfd"}, false), InputError);
}

TEST(FrontierEngine, EvaluationAddsFullAndScoresEveryRound) {
  FrontierEngine engine(FrontierOptions{}, {"dfd", "direct"}, true);
  ASSERT_EQ(engine.strategy_names().front(), "full");
  testing::RandomScenario s(7, {});
  std::vector<geometry::Rigid2d> poses;
  for (int id = 0; id < 4; ++id) {
    poses.push_back(s.TruePose());
    engine.Apply(s.MakeSubmap(id, poses.back(), 1.8));
  }
  engine.Apply(events::Optimized{poses});
  engine.Apply(events::Optimized{poses});
  EXPECT_EQ(engine.optimizations(), 2);
  EXPECT_EQ(engine.rounds().size(), 6u);  // 2 rounds x 3 strategies
  const std::vector<StrategyTotals> totals = engine.Totals();
  const int64_t all_points = engine.catalog().total_points();
  ASSERT_GT(all_points, 0);
  EXPECT_EQ(totals[0].queried_points, 2 * all_points);  // full
  EXPECT_EQ(totals[1].queried_points, 2 * all_points);  // dfd
  EXPECT_DOUBLE_EQ(totals[1].performance_p, 0.0);
  // Unmoved submaps: direct queries nothing and stays exact.
  EXPECT_EQ(totals[2].queried_points, 0);
  EXPECT_DOUBLE_EQ(totals[2].performance_p, 1.0);
  EXPECT_DOUBLE_EQ(totals[2].confusion.accuracy(), 1.0);
  EXPECT_GT(totals[0].grid_change_queried_points, 0);
}

TEST(FrontierEngine, RejectsEventsForUnknownSubmaps) {
  FrontierEngine engine(FrontierOptions{}, {"exact"}, false);
  testing::RandomScenario s(3, {});
  EXPECT_THROW(engine.Apply(s.MakeSubmap(1, s.TruePose(), 1.0)), InputError);
  EXPECT_THROW(engine.Apply(events::Optimized{{geometry::Rigid2d()}}), InputError);
}

}  // namespace
}  // namespace scout::frontier
