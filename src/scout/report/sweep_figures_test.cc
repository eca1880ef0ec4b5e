#include "scout/report/sweep_figures.h"

#include <gtest/gtest.h>

namespace scout::report {
namespace {

RunData BenchRun(double epsilon, double width, double direct_points, double direct_accuracy) {
  RunData run;
  run.name = "run";
  run.summary = nlohmann::json::parse(R"({"optimizations": 4, "frontier": {"strategies": {
      "dfd": {"queried_points": 1000, "time_ms": 8.0, "accuracy": 1.0},
      "bfs": {"queried_points": 600, "time_ms": 4.0, "accuracy": 0.9999}}}})");
  run.summary["epsilon_m"] = epsilon;
  run.summary["world_size_m"] = {width, width};
  run.summary["frontier"]["strategies"]["direct"] = {
      {"queried_points", direct_points}, {"time_ms", 2.0}, {"accuracy", direct_accuracy}};
  return run;
}

std::vector<std::string> Names(const std::vector<Figure>& figures) {
  std::vector<std::string> names;
  for (const Figure& f : figures) names.push_back(f.name);
  return names;
}

TEST(SweepFigures, EpsilonSweepHasBfsAndDirectOnly) {
  const std::vector<Figure> figures =
      SweepFigures({BenchRun(0.2, 50, 300, 0.999), BenchRun(0.05, 50, 700, 0.99999)});
  ASSERT_EQ(Names(figures), (std::vector<std::string>{"epsilon_points", "epsilon_accuracy"}));
  EXPECT_NE(figures[0].svg.find("direct"), std::string::npos);
  EXPECT_NE(figures[0].svg.find("bfs"), std::string::npos);
  EXPECT_EQ(figures[0].svg.find("dfd"), std::string::npos);
  EXPECT_NE(figures[1].svg.find("ε (m)"), std::string::npos);
}

TEST(SweepFigures, SizeSweepHasEveryStrategy) {
  const std::vector<Figure> figures =
      SweepFigures({BenchRun(0.05, 100, 300, 1.0), BenchRun(0.05, 50, 100, 1.0)});
  ASSERT_EQ(Names(figures), (std::vector<std::string>{"size_points", "size_time"}));
  for (const char* name : {"dfd", "bfs", "direct"}) {
    EXPECT_NE(figures[0].svg.find(name), std::string::npos) << name;
  }
  EXPECT_NE(figures[1].svg.find("ms per round"), std::string::npos);
}

TEST(SweepFigures, OneValueDrawsNothing) {
  EXPECT_TRUE(SweepFigures({BenchRun(0.05, 50, 100, 1.0)}).empty());
  EXPECT_TRUE(SweepFigures({}).empty());
}

}  // namespace
}  // namespace scout::report
