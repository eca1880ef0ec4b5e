#ifndef SCOUT_IO_ODOMETRY_NOISE_H_
#define SCOUT_IO_ODOMETRY_NOISE_H_

// Synthetic wheel-odometry drift for datasets whose odometry is too good
// (the "-corrected" CARMEN logs hold the corrected trajectory as ODOM).

#include <cstdint>
#include <vector>

#include "scout/sensor/odometry.h"

namespace scout::io {

// The odometry motion model of Thrun, Burgard & Fox (Probabilistic Robotics,
// 5.4): every increment is split into a turn 'rot1' towards the direction of
// travel, a straight move 'trans' and a final turn 'rot2', and each part gets
// zero-mean Gaussian noise. Unlike the book's per-step standard deviations,
// the VARIANCES grow linearly with the motion (a random walk), so the drift
// over a path does not depend on how often odometry was sampled. Each
// coefficient is the standard deviation after one unit of motion:
//   var(rot1), var(rot2): rotation_per_rotation^2 * |rot| [rad]
//                         + rotation_per_translation^2 * |trans| / 2 [m]
//   var(trans):           translation_per_translation^2 * |trans| [m]
//                         + translation_per_rotation^2 * (|rot1| + |rot2|) [rad]
// The defaults are a typical differential-drive robot. Measured over 10 m
// straight at 10 cm steps (io_dataset_test, OdometryNoise.*): heading
// error sd ~0.032 rad (1.8 deg), along-track sd ~0.16 m, cross-track sd
// ~0.18 m, i.e. ~2.5 % of the distance travelled; a full turn in place
// accumulates a heading sd of ~0.125 rad (7 deg).
struct OdometryNoiseModel {
  double rotation_per_rotation = 0.05;        // rad per sqrt(rad) turned
  double rotation_per_translation = 0.01;     // rad per sqrt(m) travelled
  double translation_per_translation = 0.05;  // m per sqrt(m) travelled
  double translation_per_rotation = 0.01;     // m per sqrt(rad) turned
};

// Returns 'odometry' re-integrated from its consecutive increments with the
// noise of 'model', every standard deviation multiplied by 'scale'. The first
// pose and all times are kept; scale 0 returns the input unchanged. The same
// inputs and 'seed' give the same output with any standard library: draws come
// from std::mt19937_64 (fully specified) through an own Box-Muller transform,
// not the implementation-defined std::normal_distribution. Throws
// std::invalid_argument if 'scale' or a model coefficient is negative or not
// finite.
//
// Compared with sim::OdometryModel (per-sample standard deviations, tuned for
// 50 Hz simulation): recorded odometry comes at 5 to 50 Hz, so here the drift
// must not depend on the sample rate.
std::vector<sensor::Odometry> AddOdometryNoise(const std::vector<sensor::Odometry>& odometry,
                                               double scale, uint64_t seed,
                                               const OdometryNoiseModel& model = {});

}  // namespace scout::io

#endif  // SCOUT_IO_ODOMETRY_NOISE_H_
