#ifndef SCOUT_SYNTHETIC_SE2_H_
#define SCOUT_SYNTHETIC_SE2_H_

#include "scout/geometry/rigid_transform.h"

namespace scout::synthetic {

// Returns the fraction 'fraction' of the rigid motion 'motion' along its screw
// path, exp(fraction * log(motion)) in SE(2): a rotation by fraction * theta
// about the same fixed point (or that fraction of a pure translation). 0 gives
// the identity and 1 gives 'motion'.
geometry::Rigid2d ScaleMotion(const geometry::Rigid2d& motion, double fraction);

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_SE2_H_
