// End-to-end tests of the scout command line: exit codes, error messages and
// outputs, on a small hand-made building map.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "apps/scout/cli_test_util.h"
#include "scout/common/atomic_file.h"
#include "scout/grid/map_io.h"

namespace {

namespace fs = std::filesystem;

using Result = scout::testing::CliResult;
using scout::testing::RunScout;

// The summary.json an output directory holds.
nlohmann::json ReadSummary(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

class ScoutCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("scout_cli_test_" + std::to_string(rd()));
    fs::create_directories(dir_);
    // A 10 m x 8 m two-room building: outer walls, a dividing wall with a door.
    scout::grid::OccupancyMap map;
    map.limits = scout::grid::MapLimits(0.05, {0, 0}, 200, 160);
    map.cells.assign(map.limits.num_cells(), scout::grid::CellState::kFree);
    for (int y = 0; y < 160; ++y) {
      for (int x = 0; x < 200; ++x) {
        const bool outer = x < 3 || y < 3 || x >= 197 || y >= 157;
        const bool divider = x >= 99 && x < 102 && !(y >= 60 && y < 90);
        if (outer || divider) map.set({x, y}, scout::grid::CellState::kOccupied);
      }
    }
    scout::grid::WriteMapServerMap(map, dir_ / "rooms.yaml");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

TEST_F(ScoutCli, HelpAndVersionSucceed) {
  EXPECT_EQ(RunScout("--help").exit_code, 0);
  EXPECT_EQ(RunScout("frontier-bench --help").exit_code, 0);
}

TEST_F(ScoutCli, BadCommandLineExitsWithTwo) {
  EXPECT_EQ(RunScout("").exit_code, 2);
  EXPECT_EQ(RunScout("no-such-command").exit_code, 2);
  EXPECT_EQ(RunScout("frontier-bench --seed notanumber").exit_code, 2);
}

TEST_F(ScoutCli, NegativeOrTooLargeSeedIsAnErrorNotAWrappedNumber) {
  const std::string o = " --out " + (dir_ / "out").string();
  for (const std::string command : {"frontier-bench", "explore", "replay no-such.log"}) {
    // 2^64 + 1 would be clamped to 2^64 - 1 without the check.
    for (const std::string seed : {"-3", "18446744073709551617"}) {
      const Result r = RunScout(command + " --seed " + seed + o);
      EXPECT_EQ(r.exit_code, 2) << command;
      EXPECT_NE(r.output.find("--seed"), std::string::npos) << command << ": " << r.output;
      EXPECT_NE(r.output.find("expected a non-negative integer (at most 18446744073709551615), "
                              "got '" +
                              seed + "'"),
                std::string::npos)
          << command << ": " << r.output;
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(ScoutCli, BadInputsNameWhatIsWrongAndLeaveNoOutputs) {
  const fs::path out = dir_ / "out";
  const std::string o = " --out " + out.string();
  Result r = RunScout("frontier-bench --world atlantis" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("unknown world 'atlantis'"), std::string::npos) << r.output;
  r = RunScout("frontier-bench --world " + (dir_ / "missing.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("missing.yaml"), std::string::npos) << r.output;
  r = RunScout("frontier-bench --strategies dfd,magic --world office" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("'magic'"), std::string::npos) << r.output;
  for (const std::string list : {"exact,", ",exact", "full,,exact", ","}) {
    r = RunScout("frontier-bench --strategies " + list + " --world office" + o);
    EXPECT_EQ(r.exit_code, 2) << list;
    EXPECT_NE(r.output.find("--strategies '" + list + "': expected comma-separated names"),
              std::string::npos)
        << r.output;
  }
  r = RunScout("frontier-bench --strategies bfs --picture-strategy exact --world office" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(
      r.output.find("--picture-strategy 'exact': not among the strategies that run (full,bfs)"),
      std::string::npos)
      << r.output;
  for (const std::string bad : {"-1", "0", "abc", "nan"}) {
    r = RunScout("frontier-bench --epsilon " + bad + " --world office" + o);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(
        r.output.find("--epsilon: expected a positive finite number of metres, got '" + bad + "'"),
        std::string::npos)
        << r.output;
  }
  scout::WriteTextFileAtomically(dir_ / "bad.yaml", "frontier:\n  inflation_radius: 0.3\n");
  r = RunScout("frontier-bench --config " + (dir_ / "bad.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("frontier.inflation_radius"), std::string::npos) << r.output;
  scout::WriteTextFileAtomically(dir_ / "file", "x");
  r = RunScout("frontier-bench --world " + (dir_ / "rooms.yaml").string() + " --out " +
               (dir_ / "file" / "sub").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("file/sub"), std::string::npos) << r.output;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out));
}

TEST_F(ScoutCli, FrontierBenchWritesConsistentOutputs) {
  const fs::path out = dir_ / "out";
  const Result r = RunScout("frontier-bench --quiet --world " + (dir_ / "rooms.yaml").string() +
                            " --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".scout-outputs", "figures", "frontier.csv",
                                             "frontiers.png", "report.html", "summary.json"}));
  EXPECT_TRUE(fs::exists(out / "figures" / "queried_points.svg"));
  const nlohmann::json summary = ReadSummary(out);
  EXPECT_GT(summary["submaps"].get<int>(), 1);
  EXPECT_GT(summary["optimizations"].get<int>(), 0);
  const nlohmann::json& s = summary["frontier"]["strategies"];
  for (const std::string name : {"full", "dfd", "bfs", "direct", "exact"}) {
    ASSERT_TRUE(s.contains(name)) << name;
    for (const std::string key :
         {"queried_points", "queried_submaps", "time_ms", "accuracy", "precision", "recall", "P"}) {
      EXPECT_TRUE(s[name].contains(key)) << name << "." << key;
    }
  }
  EXPECT_DOUBLE_EQ(s["exact"]["accuracy"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["dfd"]["accuracy"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["dfd"]["P"].get<double>(), 0.0);
  EXPECT_LE(s["direct"]["queried_points"].get<int64_t>(),
            s["dfd"]["queried_points"].get<int64_t>());
  std::ifstream csv(out / "frontier.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 5 * summary["optimizations"].get<int>());
}

TEST_F(ScoutCli, AnInterruptedBenchLeavesNothingBehind) {
  // The office bench takes about a minute; a bench cut short would score the
  // strategies on part of the stream, so nothing is written.
  const fs::path out = dir_ / "interrupted";
  const Result r = scout::testing::RunScoutAndInterrupt(
      "frontier-bench --world office --quiet --out " + out.string(), out.string());
  EXPECT_EQ(r.exit_code, 130) << r.output;
  EXPECT_NE(r.output.find("scout: interrupted by SIGINT; nothing written"), std::string::npos)
      << r.output;
  // The directory the run created goes with its staging directory.
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ScoutCli, WithoutExactThePictureShowsTheFirstNamedStrategy) {
  // The default picture strategy is exact; a run without it used to stop
  // with "frontier strategy 'exact' is not running in this engine".
  const fs::path out = dir_ / "out";
  const Result r =
      RunScout("frontier-bench --quiet --no-reference --strategies bfs,direct --world " +
               (dir_ / "rooms.yaml").string() + " --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "frontiers.png"));
  // Without dfd there is no P, without "full" no scores: dashes, not "nan"
  // or an unscored 1.0000.
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("1.0000"), std::string::npos) << r.output;
  const nlohmann::json summary = ReadSummary(out);
  EXPECT_TRUE(summary["frontier"]["strategies"].contains("bfs"));
  EXPECT_FALSE(summary["frontier"]["strategies"].contains("exact"));
}

TEST_F(ScoutCli, FrontierBenchWithoutReferenceRunsOnlyTheNamedStrategies) {
  const fs::path out = dir_ / "out";
  const Result r =
      RunScout("frontier-bench --quiet --no-reference --strategies dfd,exact --world " +
               (dir_ / "rooms.yaml").string() + " --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json summary = ReadSummary(out);
  EXPECT_FALSE(summary["reference"].get<bool>());
  const nlohmann::json& s = summary["frontier"]["strategies"];
  EXPECT_FALSE(s.contains("full"));
  ASSERT_TRUE(s.contains("exact") && s.contains("dfd"));
  EXPECT_GT(s["dfd"]["queried_points"].get<int64_t>(), 0);
  EXPECT_FALSE(s["exact"].contains("accuracy"));  // nothing to score against
  EXPECT_TRUE(summary["global_frontier_points"].is_number_integer());
}

TEST_F(ScoutCli, ReportAndCompareRedrawFromTheOutputFiles) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(RunScout("frontier-bench --quiet --world " + (dir_ / "rooms.yaml").string() +
                     " --seed 3 --out " + a.string())
                .exit_code,
            0);
  fs::create_directories(b);
  fs::copy_file(a / "frontier.csv", b / "frontier.csv");
  fs::copy_file(a / "summary.json", b / "summary.json");
  Result r = RunScout("report " + b.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream page(b / "report.html");
  const std::string html{std::istreambuf_iterator<char>(page), std::istreambuf_iterator<char>()};
  EXPECT_NE(html.find("Frontier update strategies"), std::string::npos);
  EXPECT_TRUE(fs::exists(b / "figures" / "accuracy.svg"));
  r = RunScout("compare " + a.string() + " " + b.string() + " --out " + (dir_ / "cmp").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "cmp" / "compare.html"));
  EXPECT_TRUE(fs::exists(dir_ / "cmp" / "figures" / "compare_p.svg"));
  // A comparison written over one of its runs, or over another command's run,
  // would remove that run: refused, the run kept.
  r = RunScout("compare " + a.string() + " " + b.string() + " --out " + b.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("holds the input"), std::string::npos) << r.output;
  r = RunScout("compare " + b.string() + " --out " + a.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("holds the outputs of `scout frontier-bench`"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(a / "summary.json"));
  EXPECT_TRUE(fs::exists(b / "summary.json"));
  // Bad input: exit code 2, the message names the file and line; nothing written.
  std::ofstream(b / "frontier.csv", std::ios::app) << "7,dfd,x\n";
  r = RunScout("report " + b.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("frontier.csv:"), std::string::npos) << r.output;
  r = RunScout("compare " + (dir_ / "missing").string() + " --out " + (dir_ / "cmp2").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("missing"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "cmp2"));
}

TEST_F(ScoutCli, ResultsTablePrintsMarkdownAndRejectsMissingSummary) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(RunScout("frontier-bench --quiet --world " + (dir_ / "rooms.yaml").string() +
                     " --seed 3 --strategies full,dfd,exact --out " + run.string())
                .exit_code,
            0);
  std::ofstream(run / "command.txt") << "scout frontier-bench --seed 3\n";
  Result r = RunScout("results-table --kind bench " + run.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("```sh\nscout frontier-bench --seed 3\n```"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("| run | 0.05 | exact |"), std::string::npos) << r.output;
  fs::remove(run / "summary.json");
  r = RunScout("results-table --kind bench " + run.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no summary.json"), std::string::npos) << r.output;
  r = RunScout("results-table --kind tables " + run.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

TEST_F(ScoutCli, WorldSizeIsValidated) {
  // A recorded map cannot be resized; malformed and too small sizes name the problem.
  Result r = RunScout("frontier-bench --world " + (dir_ / "rooms.yaml").string() +
                      " --world-size 50 --out " + (dir_ / "a").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("only the generated office and museum"), std::string::npos) << r.output;
  r = RunScout("frontier-bench --world museum --world-size 50y50 --out " + (dir_ / "b").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("50y50"), std::string::npos) << r.output;
  r = RunScout("explore --world office --world-size 10 --out " + (dir_ / "c").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--world-size 10: office world: width_m = 10: expected >= 19.9"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "a") || fs::exists(dir_ / "b") || fs::exists(dir_ / "c"));
  // CLI11 takes an empty value as not given: the default world, or 3600 s.
  r = RunScout("explore --world-size '' --out " + (dir_ / "d").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--world-size: expected a value, got an empty string"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "d"));
}

}  // namespace
