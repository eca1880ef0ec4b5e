#ifndef SCOUT_GRID_FUSION_TEST_POSES_H_
#define SCOUT_GRID_FUSION_TEST_POSES_H_

#include <rapidcheck.h>

#include <numbers>

#include "scout/geometry/rigid_transform.h"

namespace scout::grid::testing {

// A random submap pose for the fusion properties. Axis-aligned angles are
// drawn often: SLAM's first submap sits at the identity, where submap and
// global cell edges coincide.
inline geometry::Rigid2d RandomSubmapPose() {
  const double theta =
      *rc::gen::oneOf(rc::gen::just(0.0), rc::gen::just(std::numbers::pi / 2),
                      rc::gen::map(rc::gen::inRange(-314, 315), [](int a) { return a / 100.0; }));
  return geometry::Rigid2d(*rc::gen::inRange(-300, 300) / 97.0, *rc::gen::inRange(-300, 300) / 89.0,
                           theta);
}

}  // namespace scout::grid::testing

#endif  // SCOUT_GRID_FUSION_TEST_POSES_H_
