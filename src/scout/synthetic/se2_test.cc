#include "scout/synthetic/se2.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <numbers>

namespace scout::synthetic {
namespace {

using geometry::Rigid2d;

void ExpectNear(const Rigid2d& a, const Rigid2d& b, double tolerance) {
  EXPECT_NEAR(a.x(), b.x(), tolerance);
  EXPECT_NEAR(a.y(), b.y(), tolerance);
  EXPECT_NEAR(geometry::NormalizeAngle(a.theta() - b.theta()), 0.0, tolerance);
}

TEST(ScaleMotion, EndpointsAreIdentityAndTheMotion) {
  const Rigid2d motion(1.0, -2.0, 0.7);
  ExpectNear(ScaleMotion(motion, 0.0), Rigid2d(), 1e-12);
  ExpectNear(ScaleMotion(motion, 1.0), motion, 1e-12);
}

TEST(ScaleMotion, ScalesPureTranslationLinearly) {
  ExpectNear(ScaleMotion(Rigid2d(2.0, 4.0, 0.0), 0.25), Rigid2d(0.5, 1.0, 0.0), 1e-12);
}

TEST(ScaleMotion, RotatesAboutTheFixedPoint) {
  // A quarter turn about (1, 0): half of it is an eighth turn about (1, 0).
  const Rigid2d about(1.0, 0.0, 0.0);
  const Rigid2d quarter = about * Rigid2d(0.0, 0.0, std::numbers::pi / 2) * about.inverse();
  const Rigid2d eighth = about * Rigid2d(0.0, 0.0, std::numbers::pi / 4) * about.inverse();
  ExpectNear(ScaleMotion(quarter, 0.5), eighth, 1e-12);
}

RC_GTEST_PROP(ScaleMotion, TwoHalvesMakeTheWhole, ()) {
  const auto gen = [] { return *rc::gen::inRange(-3000, 3000) / 1000.0; };
  const Rigid2d motion(gen(), gen(), gen());
  const Rigid2d half = ScaleMotion(motion, 0.5);
  const Rigid2d whole = half * half;
  RC_ASSERT((whole.translation() - motion.translation()).norm() < 1e-9);
  RC_ASSERT(std::abs(geometry::NormalizeAngle(whole.theta() - motion.theta())) < 1e-9);
}

}  // namespace
}  // namespace scout::synthetic
