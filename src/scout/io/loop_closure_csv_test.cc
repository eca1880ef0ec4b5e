#include "scout/io/loop_closure_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace scout::io {
namespace {

using geometry::Rigid2d;

std::vector<std::string> Lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

class LoopClosureCsvTest : public ::testing::Test {
 protected:
  std::filesystem::path dir_ = std::filesystem::path(::testing::TempDir()) / "loop_closure_csv";
  void SetUp() override {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
};

TEST(MatchErrorTest, IsZeroWhenThePosesAgreeWithTheMatch) {
  const Rigid2d submap(3.0, -1.0, 0.7);
  const Rigid2d match(1.5, 2.0, -0.4);
  const MatchDisagreement e = MatchError(match, submap, submap * match);
  EXPECT_NEAR(e.translation_m, 0.0, 1e-12);
  EXPECT_NEAR(e.rotation_deg, 0.0, 1e-12);
}

TEST(MatchErrorTest, MeasuresTheNodeOffsetInTheMatchedNodeFrame) {
  // The node lies 0.3 m to the left of and 2 degrees turned from where the
  // match puts it (left in the matched node's own frame).
  const Rigid2d submap(10.0, 5.0, M_PI / 2);
  const Rigid2d match(2.0, 0.0, M_PI / 2);
  const Rigid2d node = submap * match * Rigid2d(0.0, 0.3, 2.0 * M_PI / 180.0);
  const MatchDisagreement e = MatchError(match, submap, node);
  EXPECT_NEAR(e.translation_m, 0.3, 1e-12);
  EXPECT_NEAR(e.rotation_deg, 2.0, 1e-9);
}

TEST(ReferenceSubmapPoseTest, PlacesTheSubmapFrameByItsFirstNode) {
  slam::LoopClosureRecord r;
  r.first_node_in_submap = Rigid2d(0.5, 0.0, 0.1);
  const Rigid2d first_reference(4.0, 4.0, 1.0);
  const Rigid2d submap = ReferenceSubmapPose(r, first_reference);
  const Rigid2d back = submap * r.first_node_in_submap;
  EXPECT_NEAR(back.x(), 4.0, 1e-12);
  EXPECT_NEAR(back.y(), 4.0, 1e-12);
  EXPECT_NEAR(back.theta(), 1.0, 1e-12);
}

TEST_F(LoopClosureCsvTest, WritesEachRecordWithItsOutcomeAndErrors) {
  // Reference world: node 0 (the submap's first node) at the origin, node 5
  // at (4, 1) turned 90 degrees. The submap frame sits 1 m behind node 0.
  std::vector<std::optional<Rigid2d>> reference(6);
  reference[0] = Rigid2d(0.0, 0.0, 0.0);
  reference[5] = Rigid2d(4.0, 1.0, M_PI / 2);
  slam::LoopClosureRecord right;
  right.node_id = 5;
  right.submap_id = 1;
  right.outcome = slam::LoopClosureOutcome::kAccepted;
  right.first_node_in_submap = Rigid2d(1.0, 0.0, 0.0);
  right.match = Rigid2d(5.0, 1.0, M_PI / 2);  // node 5 in that submap frame, exactly
  right.estimate = Rigid2d(5.0, 1.5, M_PI / 2);
  right.gate_window_m = 2.0;
  right.submap_first_node_id = 0;
  slam::LoopClosureRecord copy = right;  // the same place 6 m on: a copy
  copy.outcome = slam::LoopClosureOutcome::kGated;
  copy.match = Rigid2d(11.0, 1.0, M_PI / 2);
  right.score = 0.62;
  right.min_score = 0.55;
  right.search_window_m = 3.0;
  slam::LoopClosureRecord unknown = right;  // no reference for node 3
  unknown.node_id = 3;
  unknown.outcome = slam::LoopClosureOutcome::kDropped;
  unknown.gate_window_m = std::numeric_limits<double>::infinity();
  unknown.near_match = true;
  unknown.score = 0.5;
  slam::LoopClosureRecord none = right;  // a search that found no match
  none.outcome = slam::LoopClosureOutcome::kNoMatch;
  none.has_match = false;
  none.score = std::numeric_limits<double>::quiet_NaN();

  // Final graph: submap 1 at (-1, 0), node 5 where the match says, node 3
  // 0.2 m off its match.
  const GlobalSubmaps submaps = {{Rigid2d(), nullptr}, {Rigid2d(-1.0, 0.0, 0.0), nullptr}};
  std::vector<StampedPose> nodes(6);
  for (int i = 0; i < 6; ++i) nodes[i].time_s = 0.1 * i;
  nodes[5].pose = Rigid2d(4.0, 1.0, M_PI / 2);
  nodes[3].pose = Rigid2d(4.0, 1.2, M_PI / 2);
  const auto path = dir_ / "loop_closures.csv";
  WriteLoopClosureCsv({right, copy, unknown, none}, nodes, submaps, reference, path);

  const std::vector<std::string> lines = Lines(path);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0],
            "node,node_time_s,submap,outcome,near_match,score,min_score,search_window_m,match_x_m,"
            "match_y_m,match_theta_rad,innovation_m,gate_window_m,final_error_m,final_error_deg,"
            "reference_error_m,reference_error_deg,estimate_reference_error_m");
  const auto a = Fields(lines[1]);
  ASSERT_EQ(a.size(), 18u);
  EXPECT_EQ(a[0], "5");
  EXPECT_EQ(a[1], "0.500000");  // the node's stamp
  EXPECT_EQ(a[3], "accepted");
  EXPECT_EQ(a[4], "0");
  EXPECT_EQ(a[5], "0.6200");
  EXPECT_EQ(a[6], "0.5500");
  EXPECT_EQ(a[7], "3.000");
  EXPECT_NEAR(std::stod(a[11]), 0.5, 1e-9);  // innovation
  EXPECT_EQ(a[12], "2.0000");
  EXPECT_NEAR(std::stod(a[13]), 0.0, 1e-4);
  EXPECT_NEAR(std::stod(a[15]), 0.0, 1e-4);  // the reference agrees
  EXPECT_NEAR(std::stod(a[17]), 0.5, 1e-4);  // the estimate was 0.5 m off it
  const auto g = Fields(lines[2]);
  EXPECT_EQ(g[3], "gated");
  EXPECT_NEAR(std::stod(g[11]), std::hypot(6.0, 0.5), 1e-4);
  EXPECT_NEAR(std::stod(g[15]), 6.0, 1e-4);  // 6 m from the reference: a copy
  const auto d = Fields(lines[3]);
  EXPECT_EQ(d[3], "dropped");
  EXPECT_EQ(d[4], "1");  // taken as a near match
  EXPECT_EQ(d[12], "");  // no gate
  EXPECT_NEAR(std::stod(d[13]), 0.2, 1e-4);
  EXPECT_EQ(d[15], "");  // the reference lacks node 3
  EXPECT_EQ(d[16], "");
  EXPECT_EQ(d[17], "");
  const auto m = Fields(lines[4]);
  ASSERT_EQ(m.size(), 18u);
  EXPECT_EQ(m[3], "no_match");
  for (int k : {5, 8, 9, 10, 11, 13, 14, 15, 16}) EXPECT_EQ(m[k], "") << k;
  EXPECT_EQ(m[6], "0.5500");                 // what the submap asked for
  EXPECT_NEAR(std::stod(m[17]), 0.5, 1e-4);  // the estimate is still graded
}

TEST_F(LoopClosureCsvTest, RejectsARecordBeyondThePoses) {
  slam::LoopClosureRecord r;
  r.node_id = 7;
  const std::vector<StampedPose> one_node(1);
  const GlobalSubmaps one_submap = {{Rigid2d(), nullptr}};
  EXPECT_THROW(WriteLoopClosureCsv({r}, one_node, one_submap, {}, dir_ / "x.csv"),
               std::out_of_range);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.csv"));
}

}  // namespace
}  // namespace scout::io
