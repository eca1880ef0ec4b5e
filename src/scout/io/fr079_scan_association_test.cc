// Scan association on real data: the raw Freiburg 079 ROS bag and the
// corrected CARMEN log of the same run, whose time bases differ.

#include <gtest/gtest.h>

#include <filesystem>

#include "scout/io/dataset.h"
#include "scout/io/trajectory_association.h"

namespace scout::io {
namespace {

std::vector<std::vector<float>> Ranges(const Dataset& dataset) {
  std::vector<std::vector<float>> ranges;
  for (const sensor::LaserScan& scan : dataset.scans) ranges.push_back(scan.ranges);
  return ranges;
}

TEST(Fr079ScanAssociation, EveryCorrectedLogScanIsFoundInTheBag) {
  const std::filesystem::path data = SCOUT_SHARED_DATA_DIR;
  const auto bag_path = data / "fr079-rosbag/fr079-original-uncorrected.bag.gz";
  const auto log_path = data / "radish-carmen-corrected/freiburg-079-corrected.log.gz";
  if (!std::filesystem::exists(bag_path) || !std::filesystem::exists(log_path)) {
    GTEST_SKIP() << "fr079 data not staged under " << data;
  }
  const Dataset bag = LoadDataset(bag_path);
  const Dataset log = LoadDataset(log_path);
  ASSERT_EQ(bag.scans.size(), 4934u);
  ASSERT_EQ(log.scans.size(), 4791u);
  const std::vector<std::pair<int, int>> matches =
      MatchScansByRanges(Ranges(log), Ranges(bag), 0.01);
  // Measured: all 4791 log scans appear in the bag (the log dropped 143).
  ASSERT_EQ(matches.size(), 4791u);
  for (size_t k = 1; k < matches.size(); ++k) {
    ASSERT_GT(matches[k].first, matches[k - 1].first);
    ASSERT_GT(matches[k].second, matches[k - 1].second);
  }
  // The two clocks differ by about 1211 s and drift apart by under a second:
  // a wrong match would jump.
  for (const auto& [i, j] : matches) {
    const double offset = bag.scans[j].time_s - log.scans[i].time_s;
    EXPECT_GT(offset, 1210.5) << "log scan " << i << ", bag scan " << j;
    EXPECT_LT(offset, 1212.0) << "log scan " << i << ", bag scan " << j;
  }
}

}  // namespace
}  // namespace scout::io
