#include "scout/report/results_tables.h"

#include <gtest/gtest.h>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/report/test_runs.h"

namespace scout::report {
namespace {

using testing::FreshDir;
using testing::WriteFrontierRun;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ResultsTables, BenchShowsCommandValuesAndPerRoundCost) {
  const std::filesystem::path dir = WriteFrontierRun("tables_bench");
  WriteTextFileAtomically(dir / "command.txt",
                          "scout frontier-bench --world office --seed 7 --epsilon 0.1\n");
  const std::string md = ResultsTables(TableKind::kBench, {dir});
  EXPECT_TRUE(Contains(md, "```sh\nscout frontier-bench --world office --seed 7 --epsilon 0.1\n"))
      << md;
  // The run table: world, seed, epsilon, local frontier points.
  EXPECT_TRUE(Contains(md, "| tables_bench | office | — | 7 | 0.10 |")) << md;
  // direct: 40 points over 3 rounds (13 per round), P 88.9 %, one wrong answer,
  // 0.405 ms / 3 rounds = 0.135 ms per round.
  EXPECT_TRUE(Contains(md,
                       "| tables_bench | 0.10 | direct | 3 | 40 | 13 | 88.9 % | 99.7220 % | "
                       "— | 100.000 % | 99.167 % | 0.135 |"))
      << md;
  // Strategies in the README's order, not the summary's alphabetical one.
  EXPECT_LT(md.find("| full |"), md.find("| dfd |"));
  EXPECT_LT(md.find("| dfd |"), md.find("| direct |"));
}

TEST(ResultsTables, ReplayShowsSlamAccuracyAndCost) {
  const std::filesystem::path dir = FreshDir("tables_replay");
  WriteTextFileAtomically(dir / "summary.json", R"({
    "dataset": "intel-corrected", "odom_noise": 1.0, "scans": 910, "data_duration_s": 1200.4,
    "wall_time_s": 60.2, "realtime_factor": 19.94, "peak_rss_mb": 312.6,
    "slam": {"submaps": 14, "loop_closures": 52, "optimizations": 9},
    "reference": {"matched_scans": 905, "ate_rmse_m": 0.0812, "rpe_1s_trans_m": 0.0123,
                  "rpe_1s_rot_deg": 0.41, "rpe_10s_trans_m": 0.0734, "rpe_10s_rot_deg": 1.27,
                  "rpe_1s_trans_mean_m": 0.0101, "rpe_1s_rot_mean_deg": 0.33,
                  "rpe_10s_trans_mean_m": 0.0612, "rpe_10s_rot_mean_deg": 0.98},
    "consistency": {"estimate_mean_distance_m": 0.01224, "reference_mean_distance_m": 0.01629,
                    "revisits": {"scans": 40, "estimate_mean_distance_m": 0.02987,
                                 "reference_mean_distance_m": 0.02861}},
    "frontier": {"strategies": {"exact": {"queried_points": 12345, "time_ms": 90.0,
      "accuracy": 1.0, "precision": 1.0, "recall": 1.0, "P": 0.8766, "fp": 0, "fn": 0}}}})");
  WriteTextFileAtomically(dir / "command.txt", "scout replay intel.log.gz --odom-noise 1\n");
  const std::string md = ResultsTables(TableKind::kReplay, {dir});
  EXPECT_TRUE(Contains(md, "scout replay intel.log.gz --odom-noise 1\n")) << md;
  EXPECT_TRUE(Contains(md,
                       "| tables_replay | intel-corrected | 1.0 | 910 | 1200 | 60 | 19.94 | "
                       "313 | 14 | 52 | 905 | 0.081 | 0.012 / 0.41 (0.010 / 0.33) | "
                       "0.073 / 1.27 (0.061 / 0.98) | 12.2 (16.3) | 29.9 (28.6) |"))
      << md;
  // No frontier.csv: the rounds come from the SLAM optimisations.
  EXPECT_TRUE(Contains(md,
                       "| tables_replay | exact | 9 | 12,345 | 1,372 | 87.7 % | 100.0000 % | "
                       "0 | 100.000 % | 100.000 % | 10.000 |"))
      << md;
}

TEST(ResultsTables, ExploreRowsAndMeansPerWorldAndPolicy) {
  std::vector<std::filesystem::path> dirs;
  for (int seed : {1, 2}) {
    const std::filesystem::path dir = FreshDir("tables_explore_" + std::to_string(seed));
    const bool done = seed == 1;
    WriteTextFileAtomically(
        dir / "summary.json",
        std::string(R"({"world": "office", "goals_policy": "scout", "seed": )") +
            std::to_string(seed) + R"(, "terminated": ")" + (done ? "complete" : "max_sim_time") +
            R"(", "coverage": )" + (done ? "0.995" : "0.80") +
            R"(, "path_length_m": 250.4, "sim_time_s": 600, "wall_time_s": 42,
               "time_to_coverage_s": {"0.99": )" +
            (done ? "500.0" : "null") +
            R"(}, "goals": {"issued": 20, "reached": 18, "unreachable": 1},
               "collisions": 0, "ate_rmse_m": )" +
            (done ? "0.04" : "0.1") + "}");
    // Seed 1 passes 95 % (at 220 m) before 99 % (240 m); seed 2 reaches neither.
    WriteTextFileAtomically(dir / "coverage.csv",
                            "sim_time_s,path_length_m,coverage\n0,0,0\n400,200,0.8\n450,220," +
                                std::string(done ? "0.96" : "0.8") + "\n500,240," +
                                std::string(done ? "0.995" : "0.8") + "\n");
    WriteTextFileAtomically(dir / "command.txt", "scout explore --world office --seed " +
                                                     std::to_string(seed) + " --goals scout\n");
    dirs.push_back(dir);
  }
  const std::string md = ResultsTables(TableKind::kExplore, dirs);
  EXPECT_TRUE(Contains(md,
                       "scout explore --world office --seed 1 --goals scout\n"
                       "scout explore --world office --seed 2 --goals scout\n"))
      << md;
  EXPECT_TRUE(Contains(md,
                       "| tables_explore_1 | office | scout | 1 | complete | 99.5 % | 250 | "
                       "240 | 600 | 500 | 20 | 18 | 1 | 0 | 0.040 | 42 | 14.3 |"))
      << md;
  EXPECT_TRUE(Contains(md,
                       "| tables_explore_2 | office | scout | 2 | max_sim_time | 80.0 % | 250 "
                       "| — | 600 | — |"))
      << md;
  EXPECT_TRUE(Contains(
      md,
      "| office | scout | 2 | 89.8 % | 80.0 % | 1 of 2 | 240 | 500 | 1 of 2 | 220 | 2 | 0 | "
      "0.070 | 0.100 |"))
      << md;
}

// An explore run of 'policy' on the office whose coverage passes 95 % at
// 'path_95' m and 99 % at 'path_99' m of path (0: never).
std::filesystem::path ExploreRun(const std::string& policy, int seed, int path_95, int path_99) {
  const std::filesystem::path dir =
      FreshDir("tables_paired_" + policy + "_" + std::to_string(seed));
  WriteTextFileAtomically(dir / "summary.json", R"({"world": "office", "goals_policy": ")" +
                                                    policy + R"(", "seed": )" +
                                                    std::to_string(seed) + "}");
  std::string csv = "sim_time_s,path_length_m,coverage\n0,0,0\n";
  if (path_95 > 0) csv += "10," + std::to_string(path_95) + ",0.96\n";
  if (path_99 > 0) csv += "20," + std::to_string(path_99) + ",0.995\n";
  WriteTextFileAtomically(dir / "coverage.csv", csv);
  return dir;
}

TEST(ResultsTables, ScoutAgainstEachBaselineOnTheSeedsBothReached) {
  // 99 %: only seed 1 is reached by both (Scout misses it on seed 2, where
  // nearest's short path must not count). 95 %: both seeds.
  const std::vector<std::filesystem::path> dirs = {
      ExploreRun("scout", 1, 200, 240), ExploreRun("scout", 2, 150, 0),
      ExploreRun("nearest", 1, 250, 300), ExploreRun("nearest", 2, 150, 160)};
  const std::string md = ResultsTables(TableKind::kExplore, dirs);
  EXPECT_TRUE(Contains(md, "| office | nearest | 1 | 240 | 300 | 0.80 | 2 | 175 | 200 | 0.88 |"))
      << md;
  // Without Scout's policy in the world there is nothing to compare.
  EXPECT_FALSE(Contains(ResultsTables(TableKind::kExplore, {dirs[2], dirs[3]}),
                        "Scout's goal policy against"));
}

TEST(ResultsTables, PWithoutDfdIsAgainstEveryLocalPointOfEveryRound) {
  // frontier-bench --strategies direct: the summary's P is null, but dfd would
  // have queried the 100 + 120 + 140 local points of the three rounds.
  const std::filesystem::path dir = FreshDir("tables_no_dfd");
  WriteTextFileAtomically(dir / "frontier.csv",
                          "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,"
                          "local_points\n"
                          "0,direct,10,1,100,0,0,0,0,100\n"
                          "1,direct,0,0,5,0,0,0,0,120\n"
                          "2,direct,30,2,300,0,0,0,0,140\n");
  WriteTextFileAtomically(dir / "summary.json",
                          R"({"world": "museum", "optimizations": 3, "frontier": {"strategies":
                              {"direct": {"queried_points": 40, "time_ms": 0.405, "P": null}}}})");
  const std::string md = ResultsTables(TableKind::kBench, {dir});
  EXPECT_TRUE(Contains(md, "| tables_no_dfd | — | direct | 3 | 40 | 13 | 88.9 % |")) << md;
  // Without local points nothing says what dfd would have queried.
  WriteTextFileAtomically(dir / "frontier.csv",
                          "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn\n"
                          "0,direct,10,1,100,0,0,0,0\n");
  EXPECT_TRUE(Contains(ResultsTables(TableKind::kBench, {dir}), "| direct | 1 | 40 | 40 | — |"))
      << ResultsTables(TableKind::kBench, {dir});
}

TEST(ResultsTables, RunWithoutCommandIsMarked) {
  const std::filesystem::path dir = WriteFrontierRun("tables_no_command");
  const std::string md = ResultsTables(TableKind::kBench, {dir});
  EXPECT_TRUE(Contains(md, "(command not recorded)")) << md;
}

TEST(ResultsTables, MissingSummaryNamesTheDirectory) {
  const std::filesystem::path dir = FreshDir("tables_empty");
  WriteTextFileAtomically(dir / "frontier.csv", testing::kFrontierCsv);
  try {
    ResultsTables(TableKind::kBench, {dir});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), dir.string())) << e.what();
    EXPECT_TRUE(Contains(e.what(), "no summary.json")) << e.what();
  }
  EXPECT_THROW(ResultsTables(TableKind::kBench, {}), InputError);
}

TEST(ResultsTables, SummaryValueOfTheWrongTypeNamesTheFileAndKey) {
  struct Case {
    std::string summary;
    std::string message;
  };
  const std::vector<Case> cases = {
      {R"({"coverage": "abc"})", "key 'coverage' is \"abc\", expected a number"},
      {R"({"goals": 5})", "key 'goals' is 5, expected an object"},
      {R"({"frontier": {"strategies": {"exact": {"P": "x"}}}})",
       "key 'frontier/strategies/exact/P' is \"x\", expected a number"},
      {R"({"reference": {"ate_rmse_m": [1]}})", "key 'reference/ate_rmse_m' is [1]"},
      {R"({"consistency": {"revisits": {"scans": "many"}}})",
       "key 'consistency/revisits/scans' is \"many\", expected a number"},
      {R"({"scans": -5})", "key 'scans' is -5, expected a number >= 0"},
      {R"({"scans": 1e999})", "not valid JSON"},
      {R"({"dataset": "intel", "scans": 3})",
       "a run of `scout replay`; expected runs of `scout explore`"},
  };
  const std::filesystem::path dir = FreshDir("tables_wrong_type");
  for (const Case& c : cases) {
    WriteTextFileAtomically(dir / "summary.json", c.summary);
    try {
      ResultsTables(TableKind::kExplore, {dir});
      ADD_FAILURE() << "expected InputError for " << c.summary;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), (dir / "summary.json").string())) << e.what();
      EXPECT_TRUE(Contains(e.what(), c.message)) << e.what();
    }
  }
  // Nested 100,000 deep, printing the value overflowed the stack (SIGSEGV).
  std::string deep = R"({"world": )";
  for (int i = 0; i < 100000; ++i) deep += "[";
  for (int i = 0; i < 100000; ++i) deep += "]";
  WriteTextFileAtomically(dir / "summary.json", deep + "}");
  try {
    ResultsTables(TableKind::kExplore, {dir});
    ADD_FAILURE() << "expected InputError for a deep summary";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "nested more than 32 levels deep")) << e.what();
  }
  // Not measured: null, and frontier-bench's "reference": false.
  WriteTextFileAtomically(dir / "summary.json",
                          R"({"reference": false, "coverage": null, "goals_policy": "scout",
                              "slam": {"synchronous": true, "nodes": 3}})");
  EXPECT_NO_THROW(ResultsTables(TableKind::kExplore, {dir}));
}

TEST(ResultsTables, KindIsParsedOrNamed) {
  EXPECT_EQ(ParseTableKind("replay"), TableKind::kReplay);
  EXPECT_EQ(ParseTableKind("bench"), TableKind::kBench);
  EXPECT_EQ(ParseTableKind("explore"), TableKind::kExplore);
  try {
    ParseTableKind("benchmark");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "'benchmark'")) << e.what();
  }
}

}  // namespace
}  // namespace scout::report
