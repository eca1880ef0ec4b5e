#include "scout/explore/path_follower.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::explore {
namespace {

// Distance from 'p' to the polyline.
double DistanceToPath(const std::vector<Eigen::Vector2d>& path, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], ab = path[i] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

struct Drive {
  bool reached = false;
  double time_s = 0.0;
  double max_deviation_m = 0.0;
  double max_v = 0.0, max_w = 0.0;
  geometry::Rigid2d final_pose;
};

// Integrates a unicycle (exact arcs) under the follower's commands.
Drive Simulate(PathFollower& follower, geometry::Rigid2d pose, double limit_s) {
  Drive d;
  const double dt = 0.05;
  for (; d.time_s < limit_s; d.time_s += dt) {
    const FollowStatus s = follower.Update(pose);
    if (s.reached) {
      d.reached = true;
      break;
    }
    const double v = s.command.linear_mps, w = s.command.angular_radps;
    d.max_v = std::max(d.max_v, std::abs(v));
    d.max_w = std::max(d.max_w, std::abs(w));
    const double th = pose.theta();
    Eigen::Vector2d step;
    if (std::abs(w) < 1e-9) {
      step = v * dt * Eigen::Vector2d(std::cos(th), std::sin(th));
    } else {
      step = (v / w) * Eigen::Vector2d(std::sin(th + w * dt) - std::sin(th),
                                       -std::cos(th + w * dt) + std::cos(th));
    }
    pose = geometry::Rigid2d(pose.translation() + step, th + w * dt);
    d.max_deviation_m =
        std::max(d.max_deviation_m, DistanceToPath(follower.path(), pose.translation()));
  }
  d.final_pose = pose;
  return d;
}

TEST(PathFollowerTest, DrivesAUnicycleAlongAnLShapedPathToTheGoal) {
  PathFollower follower({});
  const std::vector<Eigen::Vector2d> path = {{0, 0}, {3, 0}, {3, 3}};
  follower.SetPath(path);
  // Start facing away from the path: the first command turns on the spot.
  const geometry::Rigid2d start(0, 0, M_PI);
  const FollowStatus first = follower.Update(start);
  EXPECT_EQ(first.command.linear_mps, 0.0);
  EXPECT_GT(std::abs(first.command.angular_radps), 0.0);
  EXPECT_NEAR(first.remaining_m, 6.0, 1e-9);

  const Drive d = Simulate(follower, start, 60.0);
  ASSERT_TRUE(d.reached);
  EXPECT_LT((d.final_pose.translation() - Eigen::Vector2d(3, 3)).norm(), 0.25 + 1e-9);
  // 6 m at 0.5 m/s plus turning: well under 30 s.
  EXPECT_LT(d.time_s, 30.0);
  // The corner is cut by less than the lookahead allows.
  EXPECT_LT(d.max_deviation_m, 0.3);
  const PathFollowerOptions o;
  EXPECT_LE(d.max_v, o.max_linear_speed_mps + 1e-12);
  EXPECT_LE(d.max_w, o.max_angular_speed_radps + 1e-12);
}

TEST(PathFollowerTest, FollowsAPathThatDoublesBack) {
  // Out and back along a U: progress must not jump to the return leg.
  PathFollower follower({});
  const std::vector<Eigen::Vector2d> path = {{0, 0}, {4, 0}, {4, 0.8}, {0, 0.8}};
  follower.SetPath(path);
  const Drive d = Simulate(follower, geometry::Rigid2d(0, 0, 0), 60.0);
  ASSERT_TRUE(d.reached);
  EXPECT_LT((d.final_pose.translation() - Eigen::Vector2d(0, 0.8)).norm(), 0.26);
  EXPECT_GT(d.time_s, 16.0);  // drove the 8.8 m, did not hop across
}

TEST(PathFollowerTest, ReachedAndStoppedWithinTolerance) {
  PathFollower follower({});
  follower.SetPath({{1, 1}});
  const FollowStatus s = follower.Update(geometry::Rigid2d(1.1, 1.1, 0.3));
  EXPECT_TRUE(s.reached);
  EXPECT_EQ(s.command.linear_mps, 0.0);
  EXPECT_EQ(s.command.angular_radps, 0.0);
}

TEST(PathFollowerTest, OptionsAreValidatedByName) {
  PathFollowerOptions o;
  o.min_linear_speed_mps = 2.0;
  try {
    PathFollower f(o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("min_linear_speed_mps"), std::string::npos);
  }
}

}  // namespace
}  // namespace scout::explore
