#include "scout/io/carmen_log_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>
#include <string>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;
using grid::TestTempDirectory;

// "FLASER n r.. x y th x y th t host t" with 'n' beams of 'range' metres.
std::string Flaser(int n, double range, double x, double y, double theta, double time) {
  std::ostringstream line;
  line << "FLASER " << n;
  for (int k = 0; k < n; ++k) line << ' ' << range;
  line << ' ' << x << ' ' << y << ' ' << theta << ' ' << x << ' ' << y << ' ' << theta << ' '
       << time << " pippo " << time << '\n';
  return line.str();
}

std::string Odom(double x, double y, double theta, double time) {
  std::ostringstream line;
  line << "ODOM " << x << ' ' << y << ' ' << theta << " 0 0 0 " << time << " pippo " << time
       << '\n';
  return line.str();
}

// Writes 'content' gzip-compressed to 'path'.
void WriteGzip(const fs::path& path, const std::string& content) {
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(gzwrite(file, content.data(), static_cast<unsigned>(content.size())),
            static_cast<int>(content.size()));
  ASSERT_EQ(gzclose(file), Z_OK);
}

bool AnyWarningContains(const Dataset& dataset, const std::string& text) {
  for (const std::string& warning : dataset.warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string ThrownLogMessage(const fs::path& path) {
  try {
    ReadCarmenLog(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(CarmenLogReader, ReadsFlaserRobotLaserAndOdom) {
  const TestTempDirectory dir;
  const std::string log =
      "# message formats defined: PARAM FLASER ODOM ROBOTLASER1\n"
      "PARAM robot_use_laser on nohost 0\n" +
      Odom(0, 0, 0, 0.5) + Flaser(4, 2.5, 1.0, 2.0, 0.5, 1.0) +
      "ROBOTLASER1 0 -1.5 1.0 0.5 30.0 0.01 0 3 1.0 nan inf 2 7 8 "
      "9 9 9 3.0 4.0 -0.25 0 0 0 0 0 2.0 host 2.0\n" +
      Odom(1.0, 0.5, 0.25, 2.5) + Flaser(5, 3.0, 2.0, 2.0, 0.0, 3.0);
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(dir.Write("lab.log", log), &counts);

  EXPECT_EQ(dataset.name, "lab");
  EXPECT_EQ(dataset.format, "carmen");
  EXPECT_TRUE(dataset.warnings.empty()) << dataset.warnings.front();
  EXPECT_EQ(counts.flaser, 2u);
  EXPECT_EQ(counts.robotlaser1, 1u);
  EXPECT_EQ(counts.odom, 2u);
  EXPECT_EQ(counts.comment_lines, 1u);
  EXPECT_EQ(counts.other_messages.at("PARAM"), 1u);
  ASSERT_EQ(dataset.scans.size(), 3u);
  ASSERT_EQ(dataset.scan_poses.size(), 3u);

  // Even beam count: [-90, 90) deg in steps of 180/n.
  const sensor::LaserScan& even = dataset.scans[0];
  EXPECT_DOUBLE_EQ(even.time_s, 1.0);
  EXPECT_FLOAT_EQ(even.angle_min_rad, static_cast<float>(-std::numbers::pi / 2));
  EXPECT_FLOAT_EQ(even.angle_increment_rad, static_cast<float>(std::numbers::pi / 4));
  EXPECT_EQ(even.ranges, std::vector<float>(4, 2.5f));
  EXPECT_DOUBLE_EQ(dataset.scan_poses[0].x(), 1.0);
  EXPECT_DOUBLE_EQ(dataset.scan_poses[0].theta(), 0.5);
  // Odd beam count: [-90, 90] deg, both ends included.
  EXPECT_FLOAT_EQ(dataset.scans[2].angle_increment_rad, static_cast<float>(std::numbers::pi / 4));

  // ROBOTLASER1: its own angles and range limit; NaN and inf kept; robot pose.
  const sensor::LaserScan& robot = dataset.scans[1];
  EXPECT_DOUBLE_EQ(robot.time_s, 2.0);
  EXPECT_FLOAT_EQ(robot.angle_min_rad, -1.5f);
  EXPECT_FLOAT_EQ(robot.angle_increment_rad, 0.5f);
  EXPECT_FLOAT_EQ(robot.range_max_m, 30.f);
  ASSERT_EQ(robot.ranges.size(), 3u);
  EXPECT_FLOAT_EQ(robot.ranges[0], 1.f);
  EXPECT_TRUE(std::isnan(robot.ranges[1]));
  EXPECT_TRUE(std::isinf(robot.ranges[2]));
  EXPECT_DOUBLE_EQ(dataset.scan_poses[1].x(), 3.0);
  EXPECT_DOUBLE_EQ(dataset.scan_poses[1].y(), 4.0);
  EXPECT_DOUBLE_EQ(dataset.scan_poses[1].theta(), -0.25);

  // Each laser line's own odometry pose, stamped with its scan's time.
  ASSERT_EQ(dataset.scan_odometry.size(), dataset.scans.size());
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[1].time_s, 2.0);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[1].pose.x(), 3.0);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[1].pose.theta(), -0.25);

  ASSERT_EQ(dataset.odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.odometry[1].time_s, 2.5);
  EXPECT_DOUBLE_EQ(dataset.odometry[1].pose.y(), 0.5);
  EXPECT_DOUBLE_EQ(dataset.odometry[1].pose.theta(), 0.25);
}

TEST(CarmenLogReader, FlaserOdometryFieldsAreKeptApartFromThePose) {
  const TestTempDirectory dir;
  const fs::path path = dir.Write(
      "odom.log", "FLASER 2 1.0 1.5 10 20 0.5 1 2 0.25 7.0 host 7.0\n" + Odom(9, 9, 0, 7.5));
  const Dataset dataset = ReadCarmenLog(path);
  ASSERT_EQ(dataset.scans.size(), 1u);
  EXPECT_DOUBLE_EQ(dataset.scan_poses[0].x(), 10.0);
  ASSERT_EQ(dataset.scan_odometry.size(), 1u);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[0].time_s, 7.0);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[0].pose.x(), 1.0);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[0].pose.y(), 2.0);
  EXPECT_DOUBLE_EQ(dataset.scan_odometry[0].pose.theta(), 0.25);
  ASSERT_EQ(dataset.odometry.size(), 1u);  // the ODOM message, unchanged
  EXPECT_DOUBLE_EQ(dataset.odometry[0].pose.x(), 9.0);
}

TEST(CarmenLogReader, MalformedLineIsSkippedWithAWarningNamingFileAndLine) {
  const TestTempDirectory dir;
  const fs::path path = dir.Write(
      "bad.log", Flaser(3, 1.0, 0, 0, 0, 1.0) + "FLASER 3 1.0 2.0 0 0 0 0 0 0 2.0 h 2.0\n" +
                     "ODOM 1 2 x 0 0 0 2.5 h 2.5\n" + Flaser(3, 1.0, 0, 0, 0, 3.0));
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  EXPECT_EQ(dataset.scans.size(), 2u);
  EXPECT_TRUE(dataset.odometry.empty());
  EXPECT_EQ(counts.malformed_lines, 2u);
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":2: malformed FLASER"));
  EXPECT_TRUE(AnyWarningContains(dataset, "expected 14 fields for 3 beams"));
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":3: malformed ODOM"));
  EXPECT_TRUE(AnyWarningContains(dataset, "found 'x'"));
}

TEST(CarmenLogReader, MessagesGoingBackInTimeAreDroppedPerStream) {
  const TestTempDirectory dir;
  const fs::path path =
      dir.Write("back.log", Flaser(2, 1.0, 0, 0, 0, 1.0) + Odom(0, 0, 0, 5.0) +
                                Flaser(2, 1.0, 0, 0, 0, 3.0) + Flaser(2, 1.0, 0, 0, 0, 2.0) +
                                Odom(0, 0, 0, 0.0) + Flaser(2, 1.0, 0, 0, 0, 3.0));
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  ASSERT_EQ(dataset.scans.size(), 3u);  // equal times are kept
  EXPECT_DOUBLE_EQ(dataset.scans[1].time_s, 3.0);
  EXPECT_DOUBLE_EQ(dataset.scans[2].time_s, 3.0);
  EXPECT_EQ(dataset.odometry.size(), 1u);
  EXPECT_EQ(counts.backwards_scans, 1u);
  EXPECT_EQ(counts.backwards_odometry, 1u);
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":4: FLASER at t=2"));
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":5: ODOM at t=0"));
}

TEST(CarmenLogReader, OneTimeFarAheadLosesOnlyItsOwnLine) {
  const TestTempDirectory dir;
  std::string log;
  for (int i = 0; i < 6; ++i) log += Flaser(2, 1.0, 0, 0, 0, i == 2 ? 1e9 : 1.0 + i);
  const fs::path path = dir.Write("jump.log", log);
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  ASSERT_EQ(dataset.scans.size(), 5u);
  EXPECT_DOUBLE_EQ(dataset.scans[2].time_s, 4.0);
  EXPECT_EQ(dataset.scan_poses.size(), 5u);
  EXPECT_EQ(counts.flaser, 5u);
  EXPECT_EQ(counts.backwards_scans, 1u);
  EXPECT_TRUE(AnyWarningContains(
      dataset, path.string() + ":3: FLASER at t=1000000000 s is out of time order"));
}

TEST(CarmenLogReader, ReversedTimesAreAnErrorNotASingleScan) {
  const TestTempDirectory dir;
  std::string log;
  for (int i = 0; i < 6; ++i) log += Flaser(2, 1.0, 0, 0, 0, 10.0 - i);
  const fs::path path = dir.Write("reversed.log", log);
  EXPECT_NE(ThrownLogMessage(path).find("reversed.log: only 1 of 6 scans are in time order"),
            std::string::npos)
      << ThrownLogMessage(path);
}

TEST(CarmenLogReader, RobotLaserWithoutAResolutionIsMalformedAndAFieldOfViewMismatchIsNamed) {
  const TestTempDirectory dir;
  const std::string tail = " 0 0 0 1 2 0.5 0 0 0 0 0 ";
  const fs::path path = dir.Write(
      "robotlaser.log", "ROBOTLASER1 0 -1 1.0 0 30 0.01 0 3 1 2 3 0" + tail + "1.0 h 1.0\n" +
                            "ROBOTLASER1 0 -1 1.0 0.5 0 0.01 0 3 1 2 3 0" + tail + "2.0 h 2.0\n" +
                            "ROBOTLASER1 0 -1 1.0 0.5 30 0.01 0 3 1 2 3 0" + tail + "3.0 h 3.0\n" +
                            "ROBOTLASER1 0 -1 3.0 0.5 30 0.01 0 3 1 2 3 0" + tail + "4.0 h 4.0\n");
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  EXPECT_EQ(dataset.scans.size(), 2u);
  EXPECT_EQ(counts.malformed_lines, 2u);
  EXPECT_TRUE(AnyWarningContains(dataset,
                                 ":1: malformed ROBOTLASER1 message skipped: expected a "
                                 "nonzero angular_resolution"));
  EXPECT_TRUE(AnyWarningContains(dataset,
                                 ":2: malformed ROBOTLASER1 message skipped: expected a "
                                 "positive maximum_range"));
  EXPECT_TRUE(AnyWarningContains(dataset,
                                 ":4: ROBOTLASER1 field_of_view 3 rad is not 3 (or 2) "
                                 "steps of angular_resolution 0.5 rad"));
}

TEST(CarmenLogReader, AbsurdBeamCountsAreMalformedLines) {
  const TestTempDirectory dir;
  // Line 1: n + 11 wraps around to 5, the field count, with unchecked sums.
  const fs::path path =
      dir.Write("huge.log", "FLASER 18446744073709551610 1 2 3\n" +
                                std::string("FLASER 18446744073709551615 1 2 3 4 5 6 7 8 9\n") +
                                "ROBOTLASER1 0 0 3 0.5 30 0 0 18446744073709551615 1 2\n" +
                                "ROBOTLASER1 0 0 3 0.5 30 0 0 1 1 18446744073709551600 9\n" +
                                Flaser(2, 1.0, 0, 0, 0, 1.0));
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  EXPECT_EQ(counts.malformed_lines, 4u);
  EXPECT_EQ(dataset.scans.size(), 1u);
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":4: malformed ROBOTLASER1"));
}

TEST(CarmenLogReader, CorruptCoordinatesAndTimesAreMalformedLines) {
  const TestTempDirectory dir;
  // A pose 1e12 m out would make a submap grow without bound; a time of
  // 1e300 s would make every later scan go back in time.
  const fs::path path =
      dir.Write("far.log", Flaser(2, 1.0, 0, 0, 0, 1.0) + Flaser(2, 1.0, 1e12, 0, 0, 2.0) +
                               Flaser(2, 1.0, 0, 0, 0, 1e300) + Odom(0, -1e12, 0, 2.5) +
                               Flaser(2, 1.0, 0, 0, 0, 3.0));
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  EXPECT_EQ(counts.malformed_lines, 3u);
  ASSERT_EQ(dataset.scans.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.scans[1].time_s, 3.0);
  EXPECT_TRUE(dataset.odometry.empty());
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":2: malformed FLASER"));
  EXPECT_TRUE(AnyWarningContains(dataset, "expected a number within +-1000000 as field 5"));
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":3: malformed FLASER"));
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":4: malformed ODOM"));
}

TEST(CarmenLogReader, APipeOrDirectoryIsRefusedByName) {
  const TestTempDirectory dir;
  const fs::path fifo = dir.path() / "stream.log";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Reading a pipe would lose the bytes the format detection reads.
  std::string message = ThrownLogMessage(fifo);
  EXPECT_NE(message.find(fifo.string() + ": is not a regular file"), std::string::npos) << message;
  message = ThrownLogMessage(dir.path());
  EXPECT_NE(message.find(": is a directory"), std::string::npos) << message;
}

TEST(CarmenLogReader, ZeroBeamScansAreSkippedWithAWarning) {
  const TestTempDirectory dir;
  const fs::path path =
      dir.Write("zero.log", Flaser(0, 1.0, 0, 0, 0, 1.0) + Flaser(2, 1.0, 0, 0, 0, 2.0));
  CarmenLogCounts counts;
  const Dataset dataset = ReadCarmenLog(path, &counts);
  EXPECT_EQ(dataset.scans.size(), 1u);
  EXPECT_EQ(counts.zero_beam_scans, 1u);
  EXPECT_TRUE(AnyWarningContains(dataset, path.string() + ":1: FLASER with 0 beams"));
}

TEST(CarmenLogReader, ManyWarningsOfOneKindAreSummarised) {
  const TestTempDirectory dir;
  std::string log = Flaser(2, 1.0, 0, 0, 0, 1.0);
  for (int i = 0; i < 25; ++i) log += "ODOM 1 2\n";
  const Dataset dataset = ReadCarmenLog(dir.Write("noisy.log", log));
  EXPECT_EQ(dataset.warnings.size(), 11u);
  EXPECT_TRUE(AnyWarningContains(dataset, "15 more malformed lines not listed (25 in total)"));
}

TEST(CarmenLogReader, FlaserRangeMaxIsInferredFromTheSaturationValue) {
  const TestTempDirectory dir;
  std::string saturated;
  for (int i = 0; i < 12; ++i) saturated += Flaser(2, 50.0, 0, 0, 0, i);
  EXPECT_FLOAT_EQ(ReadCarmenLog(dir.Write("a.log", saturated)).scans[0].range_max_m, 49.5f);
  // A largest reading seen once is a return, not a saturation value.
  const Dataset plain = ReadCarmenLog(
      dir.Write("b.log", Flaser(2, 5.0, 0, 0, 0, 1.0) + Flaser(1, 7.0, 0, 0, 0, 2.0)));
  EXPECT_FLOAT_EQ(plain.scans[0].range_max_m, 81.9f);
}

TEST(CarmenLogReader, CoarseTimestampsGiveAWarning) {
  const TestTempDirectory dir;
  std::string log;
  for (int i = 0; i < 4; ++i) log += Flaser(2, 1.0, i, 0, 0, 0.0);
  const Dataset dataset = ReadCarmenLog(dir.Write("zero_times.log", log));
  EXPECT_EQ(dataset.scans.size(), 4u);
  EXPECT_TRUE(AnyWarningContains(dataset, "3 of 4 scans have the same ipc_timestamp"));
}

TEST(CarmenLogReader, GzipLogReadsLikeThePlainOne) {
  const TestTempDirectory dir;
  const std::string log = Odom(0, 0, 0, 0.5) + Flaser(3, 1.5, 1, 2, 0.1, 1.0) +
                          Odom(0.5, 0, 0, 1.5) + Flaser(3, 2.5, 1, 3, 0.2, 2.0);
  const Dataset plain = ReadCarmenLog(dir.Write("same.log", log));
  const fs::path gz = dir.path() / "same.log.gz";
  WriteGzip(gz, log);
  const Dataset compressed = ReadCarmenLog(gz);
  EXPECT_EQ(compressed.name, "same");
  ASSERT_EQ(compressed.scans.size(), plain.scans.size());
  for (std::size_t i = 0; i < plain.scans.size(); ++i) {
    EXPECT_EQ(compressed.scans[i].ranges, plain.scans[i].ranges);
    EXPECT_EQ(compressed.scans[i].time_s, plain.scans[i].time_s);
  }
  EXPECT_EQ(compressed.odometry.size(), 2u);
  EXPECT_TRUE(compressed.warnings.empty());
}

TEST(CarmenLogReader, TruncatedGzipKeepsTheCompleteLinesWithAWarning) {
  const TestTempDirectory dir;
  // Varied ranges so the compressed stream is long enough to cut in the middle.
  // Fifteen bad lines first: their warnings must not hide the one that says
  // the log was cut.
  std::string log;
  for (int i = 0; i < 15; ++i) log += "FLASER 6 bad\n";
  for (int i = 0; i < 2000; ++i) log += Flaser(6, 1.0 + (i * 7919 % 1000) * 0.001, i, 0, 0, i);
  const fs::path whole = dir.path() / "whole.log.gz";
  WriteGzip(whole, log);
  const fs::path cut = dir.path() / "cut.log.gz";
  fs::copy_file(whole, cut);
  fs::resize_file(cut, fs::file_size(whole) / 2);
  const Dataset dataset = ReadCarmenLog(cut);
  EXPECT_GT(dataset.scans.size(), 100u);
  EXPECT_LT(dataset.scans.size(), 2000u);
  // Every kept scan is complete: 6 beams with the ranges written.
  for (std::size_t i = 0; i < dataset.scans.size(); ++i) {
    ASSERT_EQ(dataset.scans[i].ranges.size(), 6u);
    EXPECT_FLOAT_EQ(dataset.scans[i].ranges[5], 1.0f + (i * 7919 % 1000) * 0.001f);
  }
  ASSERT_FALSE(dataset.warnings.empty());
  EXPECT_EQ(dataset.warnings.front().find(cut.string() + ": gzip data ends early"), 0u)
      << dataset.warnings.front();
  EXPECT_TRUE(AnyWarningContains(dataset, "5 more malformed"));
}

TEST(CarmenLogReader, GzipChecksumMismatchTrailingBytesAndSeveralMembersLoseNoLine) {
  const TestTempDirectory dir;
  std::string log;
  for (int i = 0; i < 2000; ++i) log += Flaser(6, 1.0 + (i * 7919 % 1000) * 0.001, i, 0, 0, i);
  const fs::path whole = dir.path() / "whole.log.gz";
  WriteGzip(whole, log);
  std::string bytes;
  {
    std::ifstream in(whole, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The CRC-32 is the trailer's first four bytes: every line is still there.
  std::string bad_crc = bytes;
  bad_crc[bad_crc.size() - 8] ^= 0x55;
  const fs::path crc = dir.Write("crc.log.gz", bad_crc);
  const Dataset checked = ReadCarmenLog(crc);
  EXPECT_EQ(checked.scans.size(), 2000u);
  ASSERT_FALSE(checked.warnings.empty());
  EXPECT_EQ(checked.warnings.front().find(crc.string() + ": gzip incorrect data check"), 0u)
      << checked.warnings.front();
  // Bytes after the stream are named; a second gzip member is read.
  const fs::path trailing = dir.Write("trailing.log.gz", bytes + "junk after the stream");
  const Dataset trailed = ReadCarmenLog(trailing);
  EXPECT_EQ(trailed.scans.size(), 2000u);
  EXPECT_TRUE(AnyWarningContains(trailed, "21 bytes after the end of the gzip stream ignored"));
  const fs::path later = dir.path() / "later.log.gz";
  WriteGzip(later, Flaser(6, 1.0, 0, 0, 0, 5000.0));
  std::string second;
  {
    std::ifstream in(later, std::ios::binary);
    second.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const Dataset both = ReadCarmenLog(dir.Write("members.log.gz", bytes + second));
  ASSERT_EQ(both.scans.size(), 2001u);
  EXPECT_DOUBLE_EQ(both.scans.back().time_s, 5000.0);
  EXPECT_TRUE(both.warnings.empty()) << both.warnings.front();
}

TEST(CarmenLogReader, GzipCutInItsHeaderIsAnErrorNamingTheFile) {
  const TestTempDirectory dir;
  const fs::path whole = dir.path() / "whole.log.gz";
  WriteGzip(whole, Flaser(3, 1.0, 0, 0, 0, 1.0));
  const fs::path cut = dir.path() / "header_only.log.gz";
  fs::copy_file(whole, cut);
  fs::resize_file(cut, 6);
  const std::string message = ThrownLogMessage(cut);
  EXPECT_NE(message.find(cut.string()), std::string::npos) << message;
  EXPECT_NE(message.find("gzip"), std::string::npos) << message;
}

TEST(CarmenLogReader, CorruptGzipDataIsAnErrorNamingTheFile) {
  const TestTempDirectory dir;
  const fs::path path =
      dir.Write("corrupt.log.gz", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", 10) +
                                      std::string(200, '\xff'));
  const std::string message = ThrownLogMessage(path);
  EXPECT_NE(message.find(path.string() + ": corrupt or truncated gzip"), std::string::npos)
      << message;
}

TEST(CarmenLogReader, LogWithoutScansIsAnError) {
  const TestTempDirectory dir;
  const fs::path path = dir.Write("odom_only.log", Odom(0, 0, 0, 1.0) + Odom(1, 0, 0, 2.0));
  const std::string message = ThrownLogMessage(path);
  EXPECT_NE(message.find(path.string() + ": no usable laser scan"), std::string::npos) << message;
  EXPECT_NE(message.find("expected FLASER or ROBOTLASER1"), std::string::npos) << message;
  EXPECT_NE(ThrownLogMessage(dir.path() / "missing.log").find("missing.log: cannot open"),
            std::string::npos);
}

}  // namespace
}  // namespace scout::io
