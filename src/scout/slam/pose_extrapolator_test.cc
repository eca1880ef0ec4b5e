#include "scout/slam/pose_extrapolator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::slam {
namespace {

using geometry::Rigid2d;

void ExpectPoseNear(const Rigid2d& actual, const Rigid2d& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance) << actual;
  EXPECT_NEAR(actual.y(), expected.y(), tolerance) << actual;
  EXPECT_NEAR(geometry::NormalizeAngle(actual.theta() - expected.theta()), 0.0, tolerance)
      << actual;
}

TEST(PoseExtrapolatorTest, IdentityBeforeAnyPoseThenHoldsASinglePose) {
  PoseExtrapolator extrapolator;
  ExpectPoseNear(extrapolator.ExtrapolatePose(3.0), Rigid2d(), 0.0);
  extrapolator.AddPose(1.0, Rigid2d(1.0, 2.0, 0.5));
  ExpectPoseNear(extrapolator.ExtrapolatePose(2.0), Rigid2d(1.0, 2.0, 0.5), 1e-12);
}

TEST(PoseExtrapolatorTest, ConstantVelocityWithoutOdometry) {
  PoseExtrapolator extrapolator;
  // Moving 1 m/s along +y (robot heading +90 degrees), turning 0.1 rad/s.
  extrapolator.AddPose(0.0, Rigid2d(0.0, 0.0, M_PI / 2));
  extrapolator.AddPose(0.1, Rigid2d(0.0, 0.1, M_PI / 2));
  ExpectPoseNear(extrapolator.ExtrapolatePose(0.3), Rigid2d(0.0, 0.3, M_PI / 2), 1e-9);
  extrapolator.AddPose(0.2, Rigid2d(0.0, 0.2, M_PI / 2 + 0.01));
  // Linear (x, y, theta) interpolation in the frame of the pose at 0.1 s.
  const Rigid2d predicted = extrapolator.ExtrapolatePose(0.3);
  EXPECT_NEAR(predicted.theta(), M_PI / 2 + 0.02, 1e-9);
  EXPECT_NEAR(predicted.y(), 0.3, 1e-3);
  // An older pose does not rewind the model.
  extrapolator.AddPose(0.05, Rigid2d(5.0, 5.0, 0.0));
  EXPECT_EQ(*extrapolator.last_pose_time(), 0.2);
}

TEST(PoseExtrapolatorTest, ConstantVelocityStopsAfterTwoSecondsOrTwoIntervals) {
  PoseExtrapolator extrapolator;
  extrapolator.AddPose(0.0, Rigid2d(0.0, 0.0, 0.0));
  extrapolator.AddPose(0.1, Rigid2d(0.1, 0.0, 0.0));  // 1 m/s along +x
  ExpectPoseNear(extrapolator.ExtrapolatePose(2.0), Rigid2d(2.0, 0.0, 0.0), 1e-9);
  // A scan stamped a million seconds later is predicted where 2 s take the robot.
  ExpectPoseNear(extrapolator.ExtrapolatePose(1e6), Rigid2d(2.1, 0.0, 0.0), 1e-9);
  // Sparse poses (5 s apart) are extended by twice their interval.
  extrapolator.AddPose(5.1, Rigid2d(5.1, 0.0, 0.0));
  ExpectPoseNear(extrapolator.ExtrapolatePose(12.1), Rigid2d(12.1, 0.0, 0.0), 1e-9);
  ExpectPoseNear(extrapolator.ExtrapolatePose(100.0), Rigid2d(15.1, 0.0, 0.0), 1e-9);
}

TEST(PoseExtrapolatorTest, OdometryDeltaAppliedToLastMatchedPose) {
  PoseExtrapolator extrapolator;
  // Odometry frame rotated and shifted against the local frame: only deltas matter.
  for (int i = 0; i <= 10; ++i) {
    // Driving forward at 1 m/s along the odometry frame's -x axis.
    extrapolator.AddOdometry({0.1 * i, Rigid2d(10.0 - 0.1 * i, 3.0, M_PI)});
  }
  extrapolator.AddPose(0.25, Rigid2d(1.0, 1.0, 0.0));  // robot heading +x in the local frame
  // Between readings: interpolated, 0.5 s later -> 0.5 m further along +x.
  ExpectPoseNear(extrapolator.ExtrapolatePose(0.75), Rigid2d(1.5, 1.0, 0.0), 1e-9);
  // Beyond the newest reading (1.0 s): the last velocity is extended briefly.
  ExpectPoseNear(extrapolator.ExtrapolatePose(1.2), Rigid2d(1.95, 1.0, 0.0), 1e-9);
  // Far beyond it, odometry is stale: fall back to the matched poses (one pose: hold it).
  ExpectPoseNear(extrapolator.ExtrapolatePose(3.0), Rigid2d(1.0, 1.0, 0.0), 1e-9);
}

TEST(PoseExtrapolatorTest, OdometryTurnIsExpressedInTheRobotFrame) {
  PoseExtrapolator extrapolator;
  extrapolator.AddOdometry({0.0, Rigid2d(0.0, 0.0, 0.0)});
  extrapolator.AddOdometry({1.0, Rigid2d(1.0, 0.0, 0.2)});  // 1 m forward, 0.2 rad left
  extrapolator.AddPose(0.0, Rigid2d(2.0, 0.0, M_PI / 2));   // heading +y in the local frame
  ExpectPoseNear(extrapolator.ExtrapolatePose(1.0), Rigid2d(2.0, 1.0, M_PI / 2 + 0.2), 1e-9);
  // Non-finite and out-of-order readings are ignored.
  extrapolator.AddOdometry({2.0, Rigid2d(std::nan(""), 0.0, 0.0)});
  extrapolator.AddOdometry({0.5, Rigid2d(100.0, 0.0, 0.0)});
  ExpectPoseNear(extrapolator.ExtrapolatePose(1.0), Rigid2d(2.0, 1.0, M_PI / 2 + 0.2), 1e-9);
}

}  // namespace
}  // namespace scout::slam
