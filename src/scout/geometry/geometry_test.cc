#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <numbers>
#include <stdexcept>
#include <vector>

#include "scout/geometry/box.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/geometry/segment.h"

namespace scout::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(DistanceToSegment, ProjectsOntoTheSegmentOrItsNearerEnd) {
  const Eigen::Vector2d a(0, 0), b(4, 0);
  EXPECT_DOUBLE_EQ(DistanceToSegment({2, 3}, a, b), 3.0);    // beside it
  EXPECT_DOUBLE_EQ(DistanceToSegment({7, 4}, a, b), 5.0);    // beyond b
  EXPECT_DOUBLE_EQ(DistanceToSegment({-3, -4}, a, b), 5.0);  // before a
  EXPECT_DOUBLE_EQ(DistanceToSegment({3, 4}, a, a), 5.0);    // a point
  EXPECT_DOUBLE_EQ(SquaredDistanceToSegment({2, 3}, a, b), 9.0);
}

TEST(NormalizeAngle, WrapsIntoHalfOpenRange) {
  EXPECT_NEAR(NormalizeAngle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(NormalizeAngle(-3 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(NormalizeAngle(kPi), -kPi);
  EXPECT_NEAR(NormalizeAngle(0.25 + 8 * kPi), 0.25, 1e-12);
}

TEST(Rigid2d, AppliesRotationThenTranslation) {
  const Rigid2d t(1.0, 2.0, kPi / 2);
  const Eigen::Vector2d p = t * Eigen::Vector2d(1.0, 0.0);
  EXPECT_NEAR(p.x(), 1.0, 1e-12);
  EXPECT_NEAR(p.y(), 3.0, 1e-12);
}

RC_GTEST_PROP(Rigid2d, InverseUndoesTransform, ()) {
  const auto gen = [] { return *rc::gen::inRange(-100000, 100000) / 1000.0; };
  const Rigid2d t(gen(), gen(), gen());
  const Eigen::Vector2d p(gen(), gen());
  const Eigen::Vector2d back = t.inverse() * (t * p);
  RC_ASSERT((back - p).norm() < 1e-9);
  const Rigid2d identity = t * t.inverse();
  RC_ASSERT(identity.translation().norm() < 1e-9);
  RC_ASSERT(std::abs(identity.theta()) < 1e-12);
}

RC_GTEST_PROP(Rigid2d, CompositionIsAssociativeOnPoints, ()) {
  const auto gen = [] { return *rc::gen::inRange(-10000, 10000) / 1000.0; };
  const Rigid2d a(gen(), gen(), gen()), b(gen(), gen(), gen());
  const Eigen::Vector2d p(gen(), gen());
  RC_ASSERT(((a * b) * p - a * (b * p)).norm() < 1e-9);
}

RC_GTEST_PROP(MaxDisplacementWithin, BoundsEveryPointInTheDisc, ()) {
  const auto gen = [] { return *rc::gen::inRange(-5000, 5000) / 1000.0; };
  const Rigid2d delta(gen() * 0.1, gen() * 0.1, gen() * 0.1);
  const Eigen::Vector2d center(gen(), gen());
  const double radius = std::abs(gen());
  const double bound = MaxDisplacementWithin(delta, center, radius);
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * kPi * k / 16;
    const Eigen::Vector2d q = center + radius * Eigen::Vector2d(std::cos(a), std::sin(a));
    RC_ASSERT((delta * q - q).norm() <= bound + 1e-12);
  }
}

TEST(Box2d, TransformBoxContainsTransformedCorners) {
  const Box2d box({0, 0}, {2, 1});
  const Rigid2d t(5, 5, kPi / 4);
  const Box2d out = TransformBox(t, box);
  for (const Eigen::Vector2d& c : {Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 1),
                                   Eigen::Vector2d(0, 1), Eigen::Vector2d(2, 0)}) {
    EXPECT_TRUE(out.Inflated(1e-12).Contains(t * c));
  }
  EXPECT_FALSE(out.Contains({0, 0}));
}

TEST(Box2d, EmptyBoxNeitherContainsNorIntersects) {
  const Box2d empty;
  EXPECT_TRUE(empty.empty());
  EXPECT_FALSE(empty.Contains({0, 0}));
  EXPECT_FALSE(empty.Intersects(Box2d({-1, -1}, {1, 1})));
  EXPECT_DOUBLE_EQ(Box2d({0, 0}, {1, 1}).DistanceTo({4, 5}), 5.0);
}

TEST(FitRigid2d, RecoversAKnownTransformAndRejectsUnpairedPoints) {
  const Rigid2d truth(2.0, -1.0, 0.3);
  const std::vector<Eigen::Vector2d> from = {{0, 0}, {4, 0}, {4, 3}, {1, 5}};
  std::vector<Eigen::Vector2d> to;
  for (const Eigen::Vector2d& p : from) to.push_back(truth * p);
  const Rigid2d fit = FitRigid2d(from, to);
  EXPECT_NEAR(fit.theta(), 0.3, 1e-12);
  EXPECT_NEAR((fit.translation() - truth.translation()).norm(), 0.0, 1e-12);
  EXPECT_EQ(FitRigid2d({}, {}).translation(), Eigen::Vector2d::Zero());
  EXPECT_THROW(FitRigid2d(from, {to[0]}), std::invalid_argument);
}

}  // namespace
}  // namespace scout::geometry
