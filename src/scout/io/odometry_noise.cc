#include "scout/io/odometry_noise.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"

namespace scout::io {
namespace {

// Standard normal samples by Box-Muller from 53-bit uniforms: unlike
// std::normal_distribution, the sequence is the same on every standard library.
class GaussianSampler {
 public:
  explicit GaussianSampler(uint64_t seed) : engine_(seed) {}

  double Sample(double standard_deviation) {
    if (has_spare_) {
      has_spare_ = false;
      return standard_deviation * spare_;
    }
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;          // [0, 1)
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return standard_deviation * radius * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

void CheckCoefficient(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("odometry noise: ") + name +
                                " must be finite and >= 0, got " + FormatNumber(value));
  }
}

// Returns 'increment' (a motion in the frame of the previous pose) with noise.
geometry::Rigid2d NoisyIncrement(const geometry::Rigid2d& increment, double scale,
                                 const OdometryNoiseModel& model, GaussianSampler& gaussian) {
  double trans = increment.translation().norm();
  // Below a micrometre the direction of travel is numerical noise.
  double rot1 = trans > 1e-6 ? std::atan2(increment.y(), increment.x()) : 0.0;
  // Driving backwards is a short turn and a negative move, not a half turn.
  if (std::abs(rot1) > std::numbers::pi / 2) {
    rot1 = geometry::NormalizeAngle(rot1 + std::numbers::pi);
    trans = -trans;
  }
  const double rot2 = geometry::NormalizeAngle(increment.theta() - rot1);
  const double a_rr = model.rotation_per_rotation * model.rotation_per_rotation;
  const double a_rt = model.rotation_per_translation * model.rotation_per_translation;
  const double a_tt = model.translation_per_translation * model.translation_per_translation;
  const double a_tr = model.translation_per_rotation * model.translation_per_rotation;
  const double abs_trans = std::abs(trans);
  const double noisy_rot1 =
      rot1 + gaussian.Sample(scale * std::sqrt(a_rr * std::abs(rot1) + a_rt * abs_trans / 2));
  const double noisy_trans =
      trans + gaussian.Sample(
                  scale * std::sqrt(a_tt * abs_trans + a_tr * (std::abs(rot1) + std::abs(rot2))));
  const double noisy_rot2 =
      rot2 + gaussian.Sample(scale * std::sqrt(a_rr * std::abs(rot2) + a_rt * abs_trans / 2));
  return geometry::Rigid2d(noisy_trans * std::cos(noisy_rot1), noisy_trans * std::sin(noisy_rot1),
                           noisy_rot1 + noisy_rot2);
}

}  // namespace

std::vector<sensor::Odometry> AddOdometryNoise(const std::vector<sensor::Odometry>& odometry,
                                               double scale, uint64_t seed,
                                               const OdometryNoiseModel& model) {
  CheckCoefficient(scale, "scale");
  CheckCoefficient(model.rotation_per_rotation, "rotation_per_rotation");
  CheckCoefficient(model.rotation_per_translation, "rotation_per_translation");
  CheckCoefficient(model.translation_per_translation, "translation_per_translation");
  CheckCoefficient(model.translation_per_rotation, "translation_per_rotation");
  // Re-integrating without noise would still change the last bits.
  if (scale == 0.0 || odometry.empty()) return odometry;
  GaussianSampler gaussian(seed);
  std::vector<sensor::Odometry> noisy;
  noisy.reserve(odometry.size());
  noisy.push_back(odometry.front());
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    const geometry::Rigid2d increment = odometry[i - 1].pose.inverse() * odometry[i].pose;
    noisy.push_back({odometry[i].time_s,
                     noisy.back().pose * NoisyIncrement(increment, scale, model, gaussian)});
  }
  return noisy;
}

}  // namespace scout::io
