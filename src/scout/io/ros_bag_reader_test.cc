// C++17 translation unit: writes bags with the ROS 1 message headers.
#include "scout/io/ros_bag_reader.h"

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <stdlib.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;
using grid::TestTempDirectory;

sensor_msgs::LaserScan Scan(double stamp_s, int beams) {
  sensor_msgs::LaserScan scan;
  scan.header.stamp = ros::Time(stamp_s);
  scan.header.frame_id = "laser";
  scan.angle_min = -1.0f;
  scan.angle_max = 1.0f;
  scan.angle_increment = 0.25f;
  scan.range_min = 0.1f;
  scan.range_max = 20.f;
  for (int k = 0; k < beams; ++k) scan.ranges.push_back(1.0f + k);
  return scan;
}

nav_msgs::Odometry Odom(double stamp_s, double x, double y, double yaw) {
  nav_msgs::Odometry odometry;
  odometry.header.stamp = ros::Time(stamp_s);
  odometry.pose.pose.position.x = x;
  odometry.pose.pose.position.y = y;
  odometry.pose.pose.orientation.z = std::sin(yaw / 2);
  odometry.pose.pose.orientation.w = std::cos(yaw / 2);
  return odometry;
}

// A bag with scans on /front_scan (3) and /rear_scan (1), odometry on
// /wheel_odom and a PoseStamped distractor.
fs::path WriteTestBag(const fs::path& path) {
  rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
  for (int i = 0; i < 3; ++i) {
    bag.write("/front_scan", ros::Time(10.0 + i), Scan(i == 1 ? 0.0 : 10.0 + i, 4));
    bag.write("/wheel_odom", ros::Time(10.5 + i), Odom(10.5 + i, i, 2.0 * i, 0.5 * i));
  }
  bag.write("/rear_scan", ros::Time(11.0), Scan(11.0, 2));
  geometry_msgs::PoseStamped pose;
  pose.header.stamp = ros::Time(11.0);
  bag.write("/goal", ros::Time(11.0), pose);
  bag.close();
  return path;
}

void GzipFile(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  gzFile out = gzopen(to.c_str(), "wb");
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size())),
            static_cast<int>(bytes.size()));
  ASSERT_EQ(gzclose(out), Z_OK);
}

bool AnyWarningContains(const Dataset& dataset, const std::string& text) {
  for (const std::string& warning : dataset.warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string ThrownBagMessage(const fs::path& path, const DatasetOptions& options = {}) {
  try {
    ReadRosBag(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

// Points TMPDIR at an empty directory for the lifetime of this object, so a
// test can check that the reader leaves no temporary file behind.
class ScopedTmpDir {
 public:
  explicit ScopedTmpDir(const fs::path& dir) : dir_(dir) {
    fs::create_directories(dir);
    if (const char* old = getenv("TMPDIR")) old_ = old;
    setenv("TMPDIR", dir.c_str(), 1);
  }
  ~ScopedTmpDir() {
    if (old_) {
      setenv("TMPDIR", old_->c_str(), 1);
    } else {
      unsetenv("TMPDIR");
    }
  }
  bool IsEmpty() const { return fs::is_empty(dir_); }

 private:
  fs::path dir_;
  std::optional<std::string> old_;
};

TEST(RosBagReader, AutoDetectsTopicsByTypeAndMessageCount) {
  const TestTempDirectory dir;
  const fs::path path = WriteTestBag(dir.path() / "robot.bag");
  const Dataset dataset = ReadRosBag(path);
  EXPECT_EQ(dataset.name, "robot");
  EXPECT_EQ(dataset.format, "rosbag");
  ASSERT_EQ(dataset.scans.size(), 3u);
  const sensor::LaserScan& scan = dataset.scans[0];
  EXPECT_DOUBLE_EQ(scan.time_s, 10.0);
  EXPECT_FLOAT_EQ(scan.angle_min_rad, -1.0f);
  EXPECT_FLOAT_EQ(scan.angle_increment_rad, 0.25f);
  EXPECT_FLOAT_EQ(scan.range_min_m, 0.1f);
  EXPECT_FLOAT_EQ(scan.range_max_m, 20.f);
  EXPECT_EQ(scan.ranges, (std::vector<float>{1.f, 2.f, 3.f, 4.f}));
  // A zero header stamp falls back to the bag's receive time.
  EXPECT_DOUBLE_EQ(dataset.scans[1].time_s, 11.0);
  ASSERT_EQ(dataset.odometry.size(), 3u);
  EXPECT_DOUBLE_EQ(dataset.odometry[2].time_s, 12.5);
  EXPECT_NEAR(dataset.odometry[2].pose.x(), 2.0, 1e-12);
  EXPECT_NEAR(dataset.odometry[2].pose.y(), 4.0, 1e-12);
  EXPECT_NEAR(dataset.odometry[2].pose.theta(), 1.0, 1e-12);
  EXPECT_TRUE(dataset.scan_poses.empty());
  EXPECT_TRUE(AnyWarningContains(dataset, "several sensor_msgs/LaserScan topics"));
  EXPECT_TRUE(AnyWarningContains(dataset, "reading /front_scan"));
}

TEST(RosBagReader, OptionsChooseTheTopics) {
  const TestTempDirectory dir;
  const fs::path path = WriteTestBag(dir.path() / "robot.bag");
  DatasetOptions options;
  options.scan_topic = "/rear_scan";
  options.odometry_topic = "/wheel_odom";
  const Dataset dataset = ReadRosBag(path, options);
  ASSERT_EQ(dataset.scans.size(), 1u);
  EXPECT_EQ(dataset.scans[0].ranges.size(), 2u);
  EXPECT_EQ(dataset.odometry.size(), 3u);
  EXPECT_TRUE(dataset.warnings.empty());
}

TEST(RosBagReader, UnknownTopicIsAnErrorListingTheTopicsOfThatType) {
  const TestTempDirectory dir;
  const fs::path path = WriteTestBag(dir.path() / "robot.bag");
  DatasetOptions options;
  options.scan_topic = "/goal";  // exists, but is not a LaserScan
  const std::string message = ThrownBagMessage(path, options);
  EXPECT_NE(message.find(path.string() + ": topic '/goal' is not a sensor_msgs/LaserScan"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("/front_scan (3 messages), /rear_scan (1 messages)"), std::string::npos)
      << message;
  options = {};
  options.odometry_topic = "/odom";
  EXPECT_NE(ThrownBagMessage(path, options).find("expected one of: /wheel_odom"),
            std::string::npos);
}

TEST(RosBagReader, BagWithoutScansIsAnErrorAndWithoutOdometryAWarning) {
  const TestTempDirectory dir;
  const fs::path no_scans = dir.path() / "no_scans.bag";
  {
    rosbag::Bag bag(no_scans.string(), rosbag::bagmode::Write);
    bag.write("/odom", ros::Time(1.0), Odom(1.0, 0, 0, 0));
  }
  const std::string message = ThrownBagMessage(no_scans);
  EXPECT_NE(message.find(no_scans.string() + ": no sensor_msgs/LaserScan topic"), std::string::npos)
      << message;
  EXPECT_NE(message.find("/odom (nav_msgs/Odometry, 1 messages)"), std::string::npos) << message;

  const fs::path no_odometry = dir.path() / "no_odometry.bag";
  {
    rosbag::Bag bag(no_odometry.string(), rosbag::bagmode::Write);
    bag.write("/scan", ros::Time(1.0), Scan(1.0, 3));
  }
  const Dataset dataset = ReadRosBag(no_odometry);
  EXPECT_EQ(dataset.scans.size(), 1u);
  EXPECT_TRUE(dataset.odometry.empty());
  EXPECT_TRUE(AnyWarningContains(dataset, "no nav_msgs/Odometry topic"));
}

TEST(RosBagReader, StampsGoingBackAndEmptyScansAreDroppedWithWarnings) {
  const TestTempDirectory dir;
  const fs::path path = dir.path() / "stamps.bag";
  {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    bag.write("/scan", ros::Time(1.0), Scan(1.0, 3));
    bag.write("/scan", ros::Time(2.0), Scan(0.5, 3));
    bag.write("/scan", ros::Time(3.0), Scan(3.0, 0));
    bag.write("/scan", ros::Time(4.0), Scan(4.0, 3));
  }
  const Dataset dataset = ReadRosBag(path);
  ASSERT_EQ(dataset.scans.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.scans[1].time_s, 4.0);
  EXPECT_TRUE(AnyWarningContains(dataset, "LaserScan at t=0.5"));
  EXPECT_TRUE(AnyWarningContains(dataset, "has 0 beams"));
}

TEST(RosBagReader, OneStampFarAheadLosesOnlyItselfAndInvalidStampsAndPosesAreNamed) {
  const TestTempDirectory dir;
  const fs::path path = dir.path() / "stamps.bag";
  {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    for (int i = 0; i < 6; ++i) {
      bag.write("/scan", ros::Time(1.0 + i), Scan(i == 2 ? 4294967295.0 : 1.0 + i, 3));
      bag.write("/odom", ros::Time(1.0 + i), Odom(i == 3 ? 1e5 : 1.0 + i, i, 0, 0));
    }
    sensor_msgs::LaserScan bad_nsec = Scan(7.0, 3);
    bad_nsec.header.stamp.nsec = 4294967295u;
    bag.write("/scan", ros::Time(7.0), bad_nsec);
    sensor_msgs::LaserScan inverted_limits = Scan(8.0, 3);
    inverted_limits.range_min = 30.f;
    bag.write("/scan", ros::Time(8.0), inverted_limits);
    nav_msgs::Odometry zero_quaternion = Odom(7.0, 6, 0, 0);
    zero_quaternion.pose.pose.orientation.w = 0.0;
    bag.write("/odom", ros::Time(7.0), zero_quaternion);
  }
  const Dataset dataset = ReadRosBag(path);
  ASSERT_EQ(dataset.scans.size(), 5u);
  EXPECT_DOUBLE_EQ(dataset.scans[2].time_s, 4.0);
  ASSERT_EQ(dataset.odometry.size(), 5u);
  EXPECT_DOUBLE_EQ(dataset.odometry[3].time_s, 5.0);
  EXPECT_TRUE(AnyWarningContains(dataset, "LaserScan at t=4294967295 s is out of time order"));
  EXPECT_TRUE(AnyWarningContains(dataset, "Odometry at t=100000 s is out of time order"));
  EXPECT_TRUE(AnyWarningContains(dataset, "has header.stamp.nsec 4294967295; skipped"));
  EXPECT_TRUE(AnyWarningContains(dataset, "has range_min 30 and range_max 20; skipped"));
  EXPECT_TRUE(AnyWarningContains(dataset, "with an orientation quaternion of norm 0; dropped"));
}

TEST(RosBagReader, ScansMostlyOutOfTimeOrderAreAnError) {
  const TestTempDirectory dir;
  const fs::path path = dir.path() / "reversed.bag";
  {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    for (int i = 0; i < 5; ++i) bag.write("/scan", ros::Time(1.0 + i), Scan(10.0 - i, 3));
  }
  EXPECT_NE(ThrownBagMessage(path).find("reversed.bag: only 1 of 5 scans are in time order"),
            std::string::npos)
      << ThrownBagMessage(path);
}

TEST(RosBagReader, UnusableAnglesOdometryAndCorruptMessagesAreSkippedWithWarnings) {
  const TestTempDirectory dir;
  const fs::path path = dir.path() / "odd.bag";
  {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    bag.write("/scan", ros::Time(1.0), Scan(1.0, 3));
    sensor_msgs::LaserScan no_increment = Scan(2.0, 3);
    no_increment.angle_increment = 0.f;
    bag.write("/scan", ros::Time(2.0), no_increment);
    sensor_msgs::LaserScan nan_angle = Scan(3.0, 3);
    nan_angle.angle_min = std::numeric_limits<float>::quiet_NaN();
    bag.write("/scan", ros::Time(3.0), nan_angle);
    // Its ranges (7 beams of 1..7 m) get a corrupt length below.
    bag.write("/scan", ros::Time(4.0), Scan(4.0, 7));
    bag.write("/scan", ros::Time(5.0), Scan(5.0, 3));
    bag.write("/odom", ros::Time(1.0), Odom(1.0, 0, 0, 0));
    bag.write("/odom", ros::Time(2.0), Odom(2.0, 1e12, 0, 0));
    bag.write("/odom", ros::Time(3.0), Odom(3.0, 1, 0, 0));
  }
  // The ranges array is its length (uint32 7) followed by the floats 1..7:
  // a length far beyond the message makes deserialisation overrun.
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string pattern(4, '\0');
  pattern[0] = 7;
  const float first = 1.0f;
  pattern.append(reinterpret_cast<const char*>(&first), sizeof(first));
  const size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos);
  // 0x3fffffff beams: deserialising would first allocate 4 GiB.
  bytes[at] = '\xff';
  bytes[at + 1] = '\xff';
  bytes[at + 2] = '\xff';
  bytes[at + 3] = '\x3f';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;

  const Dataset dataset = ReadRosBag(path);
  ASSERT_EQ(dataset.scans.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.scans[1].time_s, 5.0);
  ASSERT_EQ(dataset.odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.odometry[1].time_s, 3.0);
  EXPECT_TRUE(AnyWarningContains(dataset, "LaserScan at t=2 s has angle_min"));
  EXPECT_TRUE(AnyWarningContains(dataset, "LaserScan at t=3 s has angle_min nan"));
  EXPECT_TRUE(AnyWarningContains(dataset,
                                 "message on /scan at bag time 4 s is corrupt (ranges "
                                 "length 1073741823 runs past the"));
  EXPECT_TRUE(AnyWarningContains(
      dataset,
      "Odometry at t=2 s at (1000000000000, 0) with an orientation quaternion of norm 1; dropped"));
}

TEST(RosBagReader, ARecordDataLengthBeyondItsChunkDoesNotReadPastIt) {
  const TestTempDirectory dir;
  const fs::path path = dir.path() / "length.bag";
  {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    for (int i = 0; i < 3; ++i) bag.write("/scan", ros::Time(1.0 + i), Scan(1.0 + i, 3));
  }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // A message record ends in its data length, then the data: seq (4 bytes),
  // stamp (8), then frame_id "laser" with its length (5). The second
  // message's data length becomes 2^31 - 1.
  const std::string frame("\x05\x00\x00\x00laser", 9);
  const size_t first = bytes.find(frame);
  ASSERT_NE(first, std::string::npos);
  const size_t second = bytes.find(frame, first + 1);
  ASSERT_NE(second, std::string::npos);
  // 69 bytes: 4 + 8 + (4 + 5) + 7 * 4 + (4 + 3 * 4) + 4.
  ASSERT_EQ(bytes.substr(second - 16, 4), std::string("\x45\x00\x00\x00", 4));
  const std::string huge("\xff\xff\xff\x7f", 4);
  bytes.replace(second - 16, 4, huge);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  // Deserialising reads only the message's own fields: all three scans.
  const Dataset dataset = ReadRosBag(path);
  EXPECT_EQ(dataset.scans.size(), 3u);
}

TEST(RosBagReader, TruncatedOrCorruptBagIsAnErrorNamingTheFile) {
  const TestTempDirectory dir;
  const fs::path whole = WriteTestBag(dir.path() / "whole.bag");
  const fs::path cut = dir.path() / "cut.bag";
  fs::copy_file(whole, cut);
  fs::resize_file(cut, fs::file_size(whole) / 2);
  std::string message = ThrownBagMessage(cut);
  EXPECT_NE(message.find(cut.string() + ": not a readable ROS 1 bag"), std::string::npos)
      << message;
  const fs::path garbage = dir.Write("garbage.bag", "#ROSBAG V2.0\nthis is not a bag");
  message = ThrownBagMessage(garbage);
  EXPECT_NE(message.find(garbage.string() + ": not a readable ROS 1 bag"), std::string::npos)
      << message;
}

TEST(RosBagReader, GzipBagReadsLikeThePlainOneAndLeavesNoTemporaryFile) {
  const TestTempDirectory dir;
  const fs::path plain = WriteTestBag(dir.path() / "robot.bag");
  const fs::path gz = dir.path() / "robot.bag.gz";
  GzipFile(plain, gz);
  const ScopedTmpDir tmp(dir.path() / "tmp");
  const Dataset dataset = ReadRosBag(gz);
  EXPECT_EQ(dataset.name, "robot");
  EXPECT_EQ(dataset.scans.size(), 3u);
  EXPECT_EQ(dataset.odometry.size(), 3u);
  EXPECT_TRUE(tmp.IsEmpty());

  // Also after errors: a truncated gzip, and a complete gzip of a cut bag.
  const fs::path cut_gz = dir.path() / "cut.bag.gz";
  fs::copy_file(gz, cut_gz);
  fs::resize_file(cut_gz, fs::file_size(gz) / 2);
  EXPECT_NE(ThrownBagMessage(cut_gz).find(cut_gz.string() + ": corrupt or truncated gzip"),
            std::string::npos);
  EXPECT_TRUE(tmp.IsEmpty());
  const fs::path cut_bag = dir.path() / "cut.bag";
  fs::copy_file(plain, cut_bag);
  fs::resize_file(cut_bag, fs::file_size(plain) / 2);
  const fs::path gz_of_cut = dir.path() / "gz_of_cut.bag.gz";
  GzipFile(cut_bag, gz_of_cut);
  EXPECT_NE(ThrownBagMessage(gz_of_cut).find(gz_of_cut.string() + ": not a readable ROS 1 bag"),
            std::string::npos);
  EXPECT_TRUE(tmp.IsEmpty());
}

TEST(RosBagReader, LoadDatasetDetectsBagsByContent) {
  const TestTempDirectory dir;
  const fs::path plain = WriteTestBag(dir.path() / "recording.dat");
  const fs::path gz = dir.path() / "recording.gz";
  GzipFile(plain, gz);
  EXPECT_EQ(LoadDataset(plain).format, "rosbag");
  const Dataset dataset = LoadDataset(gz);
  EXPECT_EQ(dataset.format, "rosbag");
  EXPECT_EQ(dataset.scans.size(), 3u);
  const std::vector<BagTopic> topics = ListBagTopics(plain);
  ASSERT_EQ(topics.size(), 4u);
  EXPECT_EQ(topics[0].name, "/front_scan");
  EXPECT_EQ(topics[0].type, "sensor_msgs/LaserScan");
  EXPECT_EQ(topics[0].message_count, 3u);
}

}  // namespace
}  // namespace scout::io
