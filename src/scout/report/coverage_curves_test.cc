#include "scout/report/coverage_curves.h"

#include <gtest/gtest.h>

namespace scout::report {
namespace {

RunData MakeRun(const std::string& name, const std::string& world, const std::string& policy,
                std::vector<CoverageSample> coverage) {
  RunData r;
  r.name = name;
  r.summary = {{"world", world}, {"goals_policy", policy}};
  r.coverage = std::move(coverage);
  return r;
}

TEST(CoverageCurvesTest, SeedsOfOnePolicyBecomeTheirMean) {
  // Two seeds: one reaches 100 % after 10 m, the other 50 % and stops at 5 m.
  const std::vector<RunData> runs = {MakeRun("a", "office", "scout", {{0, 0, 0.0}, {10, 10, 1.0}}),
                                     MakeRun("b", "office", "scout", {{0, 0, 0.0}, {5, 5, 0.5}}),
                                     MakeRun("c", "office", "nearest", {{0, 0, 0.2}, {8, 8, 0.9}})};
  const CoverageLines lines = CoverageLinesOf(runs);
  EXPECT_TRUE(lines.grouped);
  ASSERT_EQ(lines.over_path.size(), 2u);
  EXPECT_EQ(lines.over_path[0].name, "office · scout (mean of 2 runs)");
  EXPECT_EQ(lines.over_path[1].name, "c");  // alone: its own line, its own samples
  EXPECT_EQ(lines.over_path[1].x, (std::vector<double>{0, 8}));
  const Series& mean = lines.over_path[0];
  ASSERT_FALSE(mean.x.empty());
  EXPECT_DOUBLE_EQ(mean.x.front(), 0.0);
  EXPECT_DOUBLE_EQ(mean.x.back(), 10.0);
  EXPECT_DOUBLE_EQ(mean.y.front(), 0.0);
  // At 10 m: run a at 100 %, run b kept its final 50 %.
  EXPECT_DOUBLE_EQ(mean.y.back(), 75.0);
  // Between 5 and 10 m only b's step to 50 % has happened.
  for (size_t i = 0; i < mean.x.size(); ++i) {
    if (mean.x[i] >= 5.0 && mean.x[i] < 10.0) {
      EXPECT_DOUBLE_EQ(mean.y[i], 25.0) << mean.x[i];
    }
  }
}

TEST(CoverageCurvesTest, DifferentRunsKeepOneLineEach) {
  const std::vector<RunData> runs = {MakeRun("a", "office", "scout", {{0, 0, 0.1}, {2, 1, 0.4}}),
                                     MakeRun("b", "museum", "scout", {{0, 0, 0.1}})};
  const CoverageLines lines = CoverageLinesOf(runs);
  EXPECT_FALSE(lines.grouped);
  ASSERT_EQ(lines.over_time.size(), 2u);
  EXPECT_EQ(lines.over_time[0].x, (std::vector<double>{0, 2}));
  EXPECT_EQ(lines.over_path[0].x, (std::vector<double>{0, 1}));
  EXPECT_DOUBLE_EQ(lines.over_path[0].y[1], 40.0);
}

}  // namespace
}  // namespace scout::report
