#include "scout/slam/submap_chain.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::slam {
namespace {

// Five submaps started 10 m of trajectory apart: a corridor out and back.
const std::vector<double> kStarts = {0.0, 10.0, 20.0, 30.0, 40.0};

TEST(SubmapChainTest, WithoutLoopClosuresTheChainIsTheTrajectory) {
  const std::vector<double> travel = ShortestChainTravel(kStarts, {}, {{0, 0.0}});
  EXPECT_EQ(travel, (std::vector<double>{0.0, 10.0, 20.0, 30.0, 40.0}));
  // From the middle, both ways along the sequence.
  EXPECT_EQ(ShortestChainTravel(kStarts, {}, {{2, 1.5}}),
            (std::vector<double>{21.5, 11.5, 1.5, 11.5, 21.5}));
}

TEST(SubmapChainTest, ALoopClosureShortensTheChainFromBothEnds) {
  // A closure of submap 4 (the way back) in submap 0, standing for 2 m.
  std::vector<std::vector<SubmapLink>> links(5);
  links[4].push_back({0, 2.0});
  links[0].push_back({4, 2.0});
  EXPECT_EQ(ShortestChainTravel(kStarts, links, {{0, 0.0}}),
            (std::vector<double>{0.0, 10.0, 20.0, 12.0, 2.0}));
  EXPECT_EQ(ShortestChainTravel(kStarts, links, {{4, 0.0}}),
            (std::vector<double>{2.0, 12.0, 20.0, 10.0, 0.0}));
}

TEST(SubmapChainTest, SeveralSourcesTakeTheNearest) {
  // A node inserted into submaps 1 and 2, 3 m past 2's start (13 m past 1's).
  EXPECT_EQ(ShortestChainTravel(kStarts, {}, {{1, 13.0}, {2, 3.0}}),
            (std::vector<double>{23.0, 13.0, 3.0, 13.0, 23.0}));
}

TEST(SubmapChainTest, IgnoresLinksAndSourcesOutsideTheSequence) {
  std::vector<std::vector<SubmapLink>> links(5);
  links[1].push_back({7, 0.0});
  const std::vector<double> travel = ShortestChainTravel(kStarts, links, {{9, 0.0}, {1, 0.0}});
  EXPECT_EQ(travel, (std::vector<double>{10.0, 0.0, 10.0, 20.0, 30.0}));
  const std::vector<double> none = ShortestChainTravel(kStarts, links, {{9, 0.0}});
  for (double t : none) EXPECT_TRUE(std::isinf(t));
}

}  // namespace
}  // namespace scout::slam
