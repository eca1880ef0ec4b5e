#include "scout/io/slam_summary.h"

#include <gtest/gtest.h>

namespace scout::io {
namespace {

TEST(SlamSummaryTest, EachCounterLandsUnderItsOwnKey) {
  slam::SlamStats stats;  // distinct values, so a swapped key shows
  stats.num_nodes = 1;
  stats.num_submaps = 2;
  stats.num_optimizations = 3;
  stats.num_loop_closures = 4;
  stats.num_rejected_loop_closures = 5;
  stats.num_gated_loop_closures = 6;
  stats.num_loop_closure_searches = 7;
  stats.total_solve_time_s = 8.5;
  stats.num_scans = 9;
  stats.num_searches_without_match = 10;
  stats.num_wide_ambiguous_matches = 11;
  stats.num_matches_seeing_through = 12;
  stats.num_pairs_without_overlap = 13;
  stats.num_ambiguous_matches = 14;
  stats.num_near_matches = 15;
  const nlohmann::json s = SlamSummary(stats, true);
  EXPECT_EQ(s["nodes"], 1);
  EXPECT_EQ(s["submaps"], 2);
  EXPECT_EQ(s["optimizations"], 3);
  EXPECT_EQ(s["loop_closures"], 4);
  EXPECT_EQ(s["rejected_loop_closures"], 5);
  EXPECT_EQ(s["gated_loop_closures"], 6);
  EXPECT_EQ(s["loop_closure_searches"], 7);
  EXPECT_DOUBLE_EQ(s["solve_time_s"].get<double>(), 8.5);
  EXPECT_EQ(s["searches_without_match"], 10);
  EXPECT_EQ(s["wide_ambiguous_matches"], 11);
  EXPECT_EQ(s["matches_seeing_through"], 12);
  EXPECT_EQ(s["pairs_without_overlap"], 13);
  EXPECT_EQ(s["ambiguous_matches"], 14);
  EXPECT_EQ(s["near_matches"], 15);
  EXPECT_EQ(s["synchronous"], true);
  // The commands add what is theirs (explore: scans; replay: submap events).
  EXPECT_EQ(s.size(), 15u);
  EXPECT_EQ(SlamSummary(stats, false)["synchronous"], false);
}

}  // namespace
}  // namespace scout::io
