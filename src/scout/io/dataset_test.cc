#include "scout/io/dataset.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"
#include "scout/io/carmen_log_reader.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;
using grid::TestTempDirectory;

const fs::path kDataDir = SCOUT_SHARED_DATA_DIR;

std::string ThrownDatasetMessage(const fs::path& path) {
  try {
    LoadDataset(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(Dataset, NameDropsDatasetSuffixes) {
  EXPECT_EQ(DatasetName("/data/intel-corrected.log.gz"), "intel-corrected");
  EXPECT_EQ(DatasetName("fr079-original-uncorrected.bag.gz"), "fr079-original-uncorrected");
  EXPECT_EQ(DatasetName("run.clf"), "run");
  EXPECT_EQ(DatasetName("notes.txt"), "notes.txt");
}

TEST(Dataset, ScansWithoutASingleReturnAreAnErrorAndABagNameIsExplained) {
  const TestTempDirectory dir;
  const std::string blind =
      "FLASER 3 nan nan 0 0 0 0 0 0 0 1.0 h 1.0\n"
      "FLASER 3 0 inf nan 0 0 0 0 0 0 2.0 h 2.0\n";
  try {
    LoadDataset(dir.Write("blind.log", blind));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("blind.log: none of the 2 scans has a single return"),
              std::string::npos)
        << e.what();
  }
  try {
    LoadDataset(dir.Write("broken.bag", "not a bag at all\n"));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("named like a ROS bag but does not start with"),
              std::string::npos)
        << e.what();
  }
}

TEST(Dataset, DetectsCarmenLogsByContentAndRejectsOtherFiles) {
  const TestTempDirectory dir;
  const std::string log = "FLASER 2 1 1 0 0 0 0 0 0 1.0 h 1.0\n";
  EXPECT_EQ(LoadDataset(dir.Write("log.bag", log)).format, "carmen");
  gzFile gz = gzopen((dir.path() / "log.dat").c_str(), "wb");
  ASSERT_NE(gz, nullptr);
  gzputs(gz, log.c_str());
  gzclose(gz);
  DatasetOptions bag_options;
  bag_options.scan_topic = "/scan";
  const Dataset from_gzip = LoadDataset(dir.path() / "log.dat", bag_options);
  EXPECT_EQ(from_gzip.format, "carmen");
  EXPECT_EQ(from_gzip.scans.size(), 1u);
  ASSERT_EQ(from_gzip.warnings.size(), 1u);
  EXPECT_NE(from_gzip.warnings[0].find("options for ROS bags; ignored"), std::string::npos);

  const fs::path old_bag = dir.Write("old.bag", "#ROSBAG V1.2\n...");
  EXPECT_NE(
      ThrownDatasetMessage(old_bag).find(old_bag.string() + ": ROS bag of format 'ROSBAG V1.2'"),
      std::string::npos);
  EXPECT_NE(ThrownDatasetMessage(dir.path()).find(": is a directory"), std::string::npos);
  const fs::path empty = dir.Write("empty.log", "");
  EXPECT_NE(ThrownDatasetMessage(empty).find(empty.string() + ": no usable laser scan"),
            std::string::npos);
}

// The CARMEN logs of /work/shared/data/README.md, with its counts.
struct ReadmeLog {
  const char* name;
  std::size_t flaser;
  std::size_t odom;
  std::size_t beams;
  double bbox_x_m;
  double bbox_y_m;
};

constexpr ReadmeLog kReadmeLogs[] = {
    {"intel-corrected", 910, 14541, 180, 26, 26},
    {"aces-corrected", 440, 7814, 180, 45, 40},
    {"csail-corrected", 406, 2394, 361, 43, 58},
    {"freiburg-079-corrected", 4791, 9725, 360, 36, 15},
    {"freiburg-101-corrected", 292, 4569, 360, 49, 15},
    {"seattle-corrected", 241, 19311, 361, 50, 12},
    {"orebro-corrected", 237, 255, 181, 48, 54},
    {"fhw-corrected", 488, 13935, 180, 20, 57},
};

TEST(Dataset, ReadsTheRadishCarmenLogsWithTheReadmeCounts) {
  const fs::path dir = kDataDir / "radish-carmen-corrected";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "shared data not present: " << dir;
  for (const ReadmeLog& expected : kReadmeLogs) {
    SCOPED_TRACE(expected.name);
    const fs::path path = dir / (std::string(expected.name) + ".log.gz");
    CarmenLogCounts counts;
    const auto start = std::chrono::steady_clock::now();
    const Dataset dataset = ReadCarmenLog(path, &counts);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << expected.name << ": " << dataset.scans.size() << " scans, "
              << dataset.odometry.size() << " odometry, range_max "
              << dataset.scans.front().range_max_m << " m, " << dataset.warnings.size()
              << " warnings, " << seconds << " s\n";
    // Every FLASER and ODOM line is accounted for: read, or dropped because
    // its time went back (the corrected logs echo each scan's pose as ODOM
    // with time 0; intel has 4 scans out of order).
    EXPECT_EQ(counts.flaser + counts.backwards_scans, expected.flaser);
    EXPECT_EQ(counts.odom + counts.backwards_odometry, expected.odom);
    EXPECT_EQ(counts.malformed_lines, 0u);
    EXPECT_EQ(counts.zero_beam_scans, 0u);
    EXPECT_LE(counts.backwards_scans, 4u);
    EXPECT_EQ(dataset.scans.size(), counts.flaser);
    ASSERT_EQ(dataset.scan_poses.size(), dataset.scans.size());
    const double step =
        std::numbers::pi / (expected.beams % 2 == 1 ? expected.beams - 1 : expected.beams);
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (std::size_t i = 0; i < dataset.scans.size(); ++i) {
      ASSERT_EQ(dataset.scans[i].ranges.size(), expected.beams);
      ASSERT_FLOAT_EQ(dataset.scans[i].angle_increment_rad, static_cast<float>(step));
      if (i > 0) {
        ASSERT_GE(dataset.scans[i].time_s, dataset.scans[i - 1].time_s);
      }
      min_x = std::min(min_x, dataset.scan_poses[i].x());
      max_x = std::max(max_x, dataset.scan_poses[i].x());
      min_y = std::min(min_y, dataset.scan_poses[i].y());
      max_y = std::max(max_y, dataset.scan_poses[i].y());
    }
    EXPECT_NEAR(max_x - min_x, expected.bbox_x_m, 1.0);
    EXPECT_NEAR(max_y - min_y, expected.bbox_y_m, 1.0);
    // Saturation readings (50 .. 81.91 m) must count as "no return".
    EXPECT_GT(dataset.scans.front().range_max_m, 30.f);
    EXPECT_LT(dataset.scans.front().range_max_m, 81.83f);
  }
}

TEST(Dataset, ReadsTheFr079BagWithTheReadmeCounts) {
  const fs::path path = kDataDir / "fr079-rosbag" / "fr079-original-uncorrected.bag.gz";
  if (!fs::exists(path)) GTEST_SKIP() << "shared data not present: " << path;
  const auto start = std::chrono::steady_clock::now();
  const Dataset dataset = LoadDataset(path);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "fr079 bag: " << dataset.scans.size() << " scans, " << dataset.odometry.size()
            << " odometry, " << dataset.warnings.size() << " warnings, " << seconds << " s\n";
  EXPECT_EQ(dataset.format, "rosbag");
  EXPECT_EQ(dataset.name, "fr079-original-uncorrected");
  EXPECT_TRUE(dataset.warnings.empty()) << dataset.warnings.front();
  ASSERT_EQ(dataset.scans.size(), 4934u);
  EXPECT_EQ(dataset.odometry.size(), 8951u);
  const sensor::LaserScan& scan = dataset.scans.front();
  EXPECT_EQ(scan.ranges.size(), 360u);
  EXPECT_NEAR(scan.angle_min_rad, -std::numbers::pi / 2, 1e-4);
  EXPECT_NEAR(scan.angle_increment_rad, std::numbers::pi / 360, 1e-6);
  EXPECT_NEAR(scan.range_max_m, 80.99, 1e-4);
  EXPECT_NEAR(scan.time_s, 1211.52, 0.01);
  // The README's bag time span ends with odometry; the last scan is 0.25 s earlier.
  EXPECT_NEAR(dataset.odometry.back().time_s, 2273.22, 0.01);
  EXPECT_NEAR(dataset.scans.back().time_s, 2272.97, 0.01);
  // Raw odometry moves: the robot covers tens of metres.
  double path_m = 0.0;
  for (std::size_t i = 1; i < dataset.odometry.size(); ++i) {
    path_m += (dataset.odometry[i].pose.translation() - dataset.odometry[i - 1].pose.translation())
                  .norm();
  }
  EXPECT_GT(path_m, 50.0);
}

}  // namespace
}  // namespace scout::io
