// Known answers on hand-built submaps (ALGORITHMS §3).

#include "scout/frontier/stabbing_query.h"

#include <gtest/gtest.h>

#include "scout/frontier/frontier_engine.h"
#include "scout/frontier/test_grids.h"

namespace scout::frontier {
namespace {

using testing::DrawGrid;

// Two submaps over the same 2 m x 1 m corridor (0.1 m cells). A has seen the
// left three quarters, B the right three quarters; both leave the top row
// unknown. B's frame is offset: its grid origin is (-1, -1) and its pose
// (1, 1, 0), so both grids cover global [0, 2] x [0, 1].
class TwoRooms : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::vector<std::string> a = {
        "????????????????????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "...............?????",  //
        "####################",  //
    };
    const std::vector<std::string> b = {
        "????????????????????",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "?????...............",  //
        "####################",  //
    };
    FrontierOptions options;
    options.inflation_radius_m = 0.0;
    engine_ =
        std::make_unique<FrontierEngine>(options, std::vector<std::string>{"full", "dfd"}, false);
    events::SubmapChanged ea{0, DrawGrid(a, 0.1), geometry::Rigid2d(), {{0.55, 0.45}}, true};
    events::SubmapChanged eb{
        1, DrawGrid(b, 0.1, {-1.0, -1.0}), geometry::Rigid2d(1, 1, 0), {{0.55, -0.55}}, true};
    engine_->Apply(ea);
    engine_->Apply(eb);
    engine_->Apply(events::Optimized{{geometry::Rigid2d(), geometry::Rigid2d(1, 1, 0)}});
  }

  // Returns the answer of the local frontier point of 'submap' at global 'g'.
  bool AnswerAt(const std::string& strategy, int submap, const Eigen::Vector2d& g) {
    const SubmapRecord& r = engine_->catalog().submap(submap);
    for (size_t k = 0; k < r.frontier.points_m.size(); ++k) {
      if ((r.global_pose * r.frontier.points_m[k] - g).norm() < 1e-6) {
        return engine_->strategy(strategy).IsGlobalFrontier(submap, static_cast<int>(k));
      }
    }
    ADD_FAILURE() << "no local frontier point of submap " << submap << " at " << g.transpose();
    return false;
  }

  std::unique_ptr<FrontierEngine> engine_;
};

TEST_F(TwoRooms, PointSeenBeyondByTheOtherSubmapIsNotGlobal) {
  // A's frontier at column 14 faces its unknown; B has seen past it.
  EXPECT_FALSE(AnswerAt("full", 0, {1.45, 0.45}));
  // B's frontier at column 5 faces its unknown; A has seen past it.
  EXPECT_FALSE(AnswerAt("full", 1, {0.55, 0.45}));
}

TEST_F(TwoRooms, PointThatIsAFrontierInBothSubmapsIsGlobal) {
  // Row 8 borders the unknown top row in both submaps.
  EXPECT_TRUE(AnswerAt("full", 0, {0.75, 0.85}));
  EXPECT_TRUE(AnswerAt("full", 1, {0.75, 0.85}));
}

TEST_F(TwoRooms, PointWhereTheOtherSubmapKnowsNothingIsGlobal) {
  EXPECT_TRUE(AnswerAt("full", 0, {0.05, 0.45}));  // left end: B unknown there
  EXPECT_TRUE(AnswerAt("full", 1, {1.95, 0.45}));  // right end: A unknown there
}

TEST_F(TwoRooms, DfdWithHintsAgreesWithFull) {
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(engine_->strategy("dfd").answers(i), engine_->strategy("full").answers(i));
  }
  EXPECT_EQ(engine_->GlobalFrontier("full").size(), engine_->GlobalFrontier("dfd").size());
}

TEST_F(TwoRooms, MovingBAwayMakesAsPointsGlobalAgain) {
  engine_->Apply(events::Optimized{{geometry::Rigid2d(), geometry::Rigid2d(30, 30, 0)}});
  EXPECT_TRUE(AnswerAt("full", 0, {1.45, 0.45}));
  EXPECT_TRUE(AnswerAt("dfd", 0, {1.45, 0.45}));
}

TEST(StabbingQuery, HintIsUpdatedToTheObjectingSubmap) {
  FrontierOptions options;
  options.inflation_radius_m = 0.0;
  SubmapCatalog catalog(options);
  // Submap 1 knows a larger area, so the point is interior (not a frontier cell) there.
  const auto known = DrawGrid(std::vector<std::string>(6, "......"), 0.1, {-0.1, -0.1});
  const auto edge = DrawGrid({"....", "....", "....", "...?"}, 0.1);
  catalog.Apply(events::SubmapChanged{0, edge, geometry::Rigid2d(), {{0.15, 0.25}}, true});
  catalog.Apply(events::SubmapChanged{1, known, geometry::Rigid2d(), {{0.15, 0.25}}, true});
  std::vector<int> scratch;
  int hint = -1;
  // (0.25, 0.05) is a frontier cell of submap 0 and plain free space in 1.
  EXPECT_FALSE(StabbingQuery(catalog, 0, {0.25, 0.05}, &hint, &scratch));
  EXPECT_EQ(hint, 1);
  // The hint is asked first and stays while it objects.
  EXPECT_FALSE(StabbingQuery(catalog, 0, {0.25, 0.05}, &hint, &scratch));
  EXPECT_EQ(hint, 1);
  EXPECT_FALSE(StabbingQuery(catalog, 0, {0.25, 0.05}, nullptr, &scratch));
}

}  // namespace
}  // namespace scout::frontier
