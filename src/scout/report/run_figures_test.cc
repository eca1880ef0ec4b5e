#include "scout/report/run_figures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/report/strategy_stats.h"
#include "scout/report/test_runs.h"
#include "scout/report/xml_check.h"

namespace scout::report {
namespace {

using testing::CheckXml;

const Figure* FindFigure(const std::vector<Figure>& figures, const std::string& name) {
  for (const Figure& f : figures) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

TEST(RunFigures, FrontierRunGivesThePaperFigures) {
  const RunData run = ReadRun(testing::WriteFrontierRun("figures"));
  EXPECT_EQ(run.name, "figures");
  ASSERT_EQ(run.rounds.size(), 9u);
  EXPECT_EQ(run.rounds[5].strategy, "direct");
  EXPECT_EQ(run.rounds[5].fn, 1);
  EXPECT_EQ(*run.rounds[8].local_points, 140);
  const std::vector<Figure> figures = RunFigures(run);
  std::vector<std::string> names;
  for (const Figure& f : figures) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"local_points", "queried_points", "update_time",
                                             "accuracy"}));
  for (const Figure& f : figures) {
    const testing::XmlCheck xml = CheckXml(f.svg);
    ASSERT_EQ(xml.error, "") << f.name;
  }
  const testing::XmlCheck queried = CheckXml(FindFigure(figures, "queried_points")->svg);
  EXPECT_EQ(queried.classes.at("series"), 3);          // full, dfd, direct
  EXPECT_EQ(queried.classes.at("marker"), 3 * 3 + 3);  // 3 rounds + legend
  EXPECT_EQ(CheckXml(FindFigure(figures, "local_points")->svg).classes.at("series"), 1);
  // full is the reference: two strategies with three bars each.
  const std::string& bars = FindFigure(figures, "accuracy")->svg;
  EXPECT_EQ(CheckXml(bars).classes.at("bar"), 6);
  EXPECT_NE(bars.find(">99.72<"), std::string::npos);  // direct's accuracy from summary.json
  // Times are drawn in milliseconds: dfd's 1100 us is 1.1 ms.
  EXPECT_NE(FindFigure(figures, "update_time")->svg.find("update time (ms)"), std::string::npos);
}

TEST(RunFigures, RunsWithoutTheReferenceClaimNoAccuracy) {
  // frontier.csv of a run without "full" (explore, frontier-bench
  // --no-reference): every confusion count is zero.
  RunData run;
  run.name = "unscored";
  for (int round = 0; round < 3; ++round) {
    FrontierRound r;
    r.round = round;
    r.strategy = "exact";
    r.queried_points = 10;
    r.time_us = 100;
    run.rounds.push_back(r);
  }
  const std::vector<StrategyStats> stats = StrategyStatsOf(run);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_TRUE(std::isnan(stats[0].accuracy));
  EXPECT_TRUE(std::isnan(stats[0].precision));
  EXPECT_TRUE(std::isnan(stats[0].recall));
  for (const Figure& f : RunFigures(run)) EXPECT_NE(f.name, "accuracy");
}

TEST(RunFigures, StrategyStatsFromCsvWhenTheSummaryIsAbsent) {
  const std::filesystem::path dir = testing::WriteFrontierRun("csv_only");
  std::filesystem::remove(dir / "summary.json");
  const std::vector<StrategyStats> stats = StrategyStatsOf(ReadRun(dir));
  ASSERT_EQ(stats.size(), 3u);
  const StrategyStats& direct = stats[2];
  EXPECT_EQ(direct.strategy, "direct");
  EXPECT_EQ(direct.rounds, 3);
  EXPECT_EQ(direct.queried_points, 40);
  EXPECT_NEAR(direct.performance_p, 1.0 - 40.0 / 360.0, 1e-12);
  EXPECT_NEAR(direct.time_per_round_ms, 0.405 / 3, 1e-12);
  EXPECT_NEAR(direct.recall, 119.0 / 120.0, 1e-12);
  EXPECT_DOUBLE_EQ(direct.precision, 1.0);
  EXPECT_NEAR(direct.accuracy, 359.0 / 360.0, 1e-12);
  EXPECT_DOUBLE_EQ(stats[1].performance_p, 0.0);  // dfd against itself
}

TEST(RunFigures, OldCsvWithoutLocalPointsStillDrawsTheRest) {
  const std::filesystem::path dir = testing::FreshDir("old_csv");
  WriteTextFileAtomically(dir / "frontier.csv",
                          "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn\n"
                          "0,dfd,5,1,10,1,0,4,0\n");
  const std::vector<Figure> figures = RunFigures(ReadRun(dir));
  ASSERT_FALSE(figures.empty());
  EXPECT_EQ(figures.front().name, "queried_points");
}

TEST(RunFigures, CoverageRunGivesCoverageFigures) {
  const std::vector<Figure> figures = RunFigures(ReadRun(testing::WriteExploreRun("explore", 0.5)));
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].name, "coverage_path");
  EXPECT_EQ(figures[1].name, "coverage_time");
  const testing::XmlCheck xml = CheckXml(figures[0].svg);
  ASSERT_EQ(xml.error, "");
  EXPECT_EQ(xml.classes.at("marker"), 11 + 1);
  EXPECT_NE(figures[0].svg.find("path length (m)"), std::string::npos);
}

// Each malformed input names the file and the line that is wrong.
TEST(RunFigures, BadCsvNamesFileAndLine) {
  const std::filesystem::path dir = testing::FreshDir("bad");
  const auto expect_error = [&](const std::string& file, const std::string& content,
                                const std::string& where) {
    std::filesystem::remove(dir / "frontier.csv");
    std::filesystem::remove(dir / "coverage.csv");
    WriteTextFileAtomically(dir / file, content);
    try {
      ReadRun(dir);
      ADD_FAILURE() << "no error for " << content;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find((dir / file).string() + where), std::string::npos)
          << e.what();
    }
  };
  const std::string header =
      "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points\n";
  expect_error("frontier.csv", header + "0,dfd,5,1,10,1,0,4,0,5\n0,direct,5,1,1x0,1,0,4,0,5\n",
               ":3: column 'time_us' is '1x0'");
  expect_error("frontier.csv", header + "0,dfd,5,1,10,1,0,4\n", ":2: expected 10 fields, got 8");
  expect_error("frontier.csv", header + "0,dfd,-5,1,10,1,0,4,0,5\n", ":2: column 'queried_points'");
  expect_error("frontier.csv", "round,strategy,time_us\n", ":1: header lacks column");
  expect_error("frontier.csv", "", ":1: missing header");
  expect_error("coverage.csv", "sim_time_s,path_length_m,coverage\n1,2,0.5\n\n2,3,nan\n",
               ":4: column 'coverage'");
  expect_error("coverage.csv", "sim_time_s,path_length_m,coverage\n1,2,1.5\n", ":2: coverage");
  expect_error("coverage.csv", "sim_time_s,path_length_m,coverage\n2,2,0.5\n1,3,0.6\n",
               ":3: sim_time_s '1' falls below the row before's (2)");
  // A byte order mark before the header is not part of its first column.
  WriteTextFileAtomically(dir / "bom.csv", "\xEF\xBB\xBF" + header + "0,dfd,5,1,10,1,0,4,0,5\n");
  EXPECT_EQ(ReadFrontierCsv(dir / "bom.csv").size(), 1u);
  expect_error("frontier.csv", header + "0,dfd,5,1,-10,1,0,4,0,5\n",
               ":2: column 'time_us' is '-10', expected a time >= 0");
  expect_error("frontier.csv", header + "0,dfd,99999999999999999999999,1,10,1,0,4,0,5\n",
               ":2: column 'queried_points'");
  std::filesystem::remove(dir / "coverage.csv");
  EXPECT_THROW(ReadRun(dir), InputError);  // holds nothing
  EXPECT_THROW(ReadRun(dir / "nonexistent"), InputError);
  EXPECT_THROW(ReadFrontierCsv(dir / "frontier.csv"), InputError);  // missing file
}

}  // namespace
}  // namespace scout::report
