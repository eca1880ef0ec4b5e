#include "scout/io/tum_trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::io {
namespace {

TEST(TumTrajectory, RoundTripKeepsStampsPositionsAndYaw) {
  const grid::TestTempDirectory dir;
  const std::vector<StampedPose> written = {
      {1211.520329, geometry::Rigid2d(1.5, -2.25, 0.0)},
      {1211.730001, geometry::Rigid2d(-3.123456, 4.0, 3.0)},
      {1212.0, geometry::Rigid2d(0.0, 0.0, -std::numbers::pi + 1e-6)},
      {1213.5, geometry::Rigid2d(10.0, 20.0, -1.2345)}};
  const auto path = dir.path() / "trajectory.tum";
  WriteTumTrajectory(written, path);
  const std::vector<StampedPose> read = ReadTumTrajectory(path);
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_NEAR(read[i].time_s, written[i].time_s, 1e-6);
    EXPECT_NEAR(read[i].pose.x(), written[i].pose.x(), 1e-6);
    EXPECT_NEAR(read[i].pose.y(), written[i].pose.y(), 1e-6);
    EXPECT_NEAR(geometry::NormalizeAngle(read[i].pose.theta() - written[i].pose.theta()), 0.0,
                1e-8);
  }
}

TEST(TumTrajectory, WritesOneTumLinePerPoseWithZeroZ) {
  const grid::TestTempDirectory dir;
  const auto path = dir.path() / "t.tum";
  WriteTumTrajectory({{2.5, geometry::Rigid2d(1.0, 2.0, std::numbers::pi / 2)}}, path);
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header[0], '#');
  EXPECT_EQ(line,
            "2.500000 1.000000 2.000000 0.000000 0.000000000 0.000000000 0.707106781 "
            "0.707106781");
}

TEST(TumTrajectory, ReadsCommentsBlankLinesAndNormalisesQuaternions) {
  const grid::TestTempDirectory dir;
  // Second pose: a quaternion scaled by 2 (yaw 90 deg); third: 180 deg.
  const auto path =
      dir.Write("t.tum",
                "# stamp x y z qx qy qz qw\n\n  \n0 1 2 0 0 0 0 1\n1.5 3 4 0.3 0 0 1.4142135 "
                "1.4142135\n# done\n2 0 0 0 0 0 1 0\r\n");
  const std::vector<StampedPose> t = ReadTumTrajectory(path);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[1].time_s, 1.5);
  EXPECT_DOUBLE_EQ(t[1].pose.x(), 3.0);
  EXPECT_NEAR(t[1].pose.theta(), std::numbers::pi / 2, 1e-6);
  EXPECT_NEAR(std::abs(t[2].pose.theta()), std::numbers::pi, 1e-9);
}

TEST(TumTrajectory, MalformedLineNamesFileLineAndExpectation) {
  const grid::TestTempDirectory dir;
  const auto path = dir.Write("bad.tum", "# header\n0 0 0 0 0 0 0 1\n1 2 3 0 0 0 1\n");
  try {
    ReadTumTrajectory(path);
    FAIL() << "a line with 7 numbers was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.tum:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("expected 8"), std::string::npos) << message;
  }
}

TEST(TumTrajectory, RejectsTrailingTextZeroQuaternionAndMissingFile) {
  const grid::TestTempDirectory dir;
  EXPECT_THROW(ReadTumTrajectory(dir.Write("a.tum", "0 0 0 0 0 0 0 1 x\n")), InputError);
  EXPECT_THROW(ReadTumTrajectory(dir.Write("b.tum", "0 0 0 0 0 0 0 0\n")), InputError);
  EXPECT_THROW(ReadTumTrajectory(dir.Write("c.tum", "0 0 0 0 0 nan 0 1\n")), InputError);
  EXPECT_THROW(ReadTumTrajectory(dir.path() / "missing.tum"), InputError);
}

}  // namespace
}  // namespace scout::io
