#include "scout/sim/simulated_robot.h"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "scout/common/error.h"
#include "scout/sim/random.h"

namespace scout::sim {
namespace {

// Independent random streams of one seed.
constexpr uint64_t kLidarStream = 0;
constexpr uint64_t kOdometryStream = 1;

// A due time counts as reached within this slack, so 10 steps of 0.01 s reach
// 0.1 s despite round-off in the summed sim time.
constexpr double kClockSlackS = 1e-9;

void RequireRate(double rate_hz, const std::string& key) {
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz)) {
    std::ostringstream message;
    message << "sim." << key << " = " << rate_hz << ": expected a finite value > 0";
    throw InputError(message.str());
  }
}

// Returns the first period index whose due time lies after 'time_s'.
int64_t NextIndexAfter(double time_s, double rate_hz) {
  return static_cast<int64_t>(std::floor((time_s + kClockSlackS) * rate_hz)) + 1;
}

}  // namespace

void CheckSimulatedRobotOptions(const SimulatedRobotOptions& o) {
  CheckDiffDriveOptions(o.robot);
  CheckOdometryNoiseOptions(o.odometry);
  Lidar{o.lidar};  // validates the lidar options
  RequireRate(o.scan_rate_hz, "scan_rate_hz");
  RequireRate(o.odometry_rate_hz, "odometry_rate_hz");
  if (!std::isfinite(o.start_heading_rad)) {
    throw InputError("sim.start_heading_rad: expected a finite value");
  }
}

SimulatedRobot::SimulatedRobot(const World& world, const SimulatedRobotOptions& options,
                               uint64_t seed)
    : world_(world),
      options_((CheckSimulatedRobotOptions(options), options)),
      robot_(world.map, options.robot, geometry::Rigid2d(world.start, options.start_heading_rad)),
      lidar_(options.lidar),
      lidar_rng_(DeriveSeed(seed, kLidarStream)),
      odometry_model_(options.odometry, DeriveSeed(seed, kOdometryStream), robot_.pose(),
                      robot_.pose()) {
  SampleDueSensors();
}

DiffDriveStepResult SimulatedRobot::Step(double v_cmd_mps, double omega_cmd_radps, double dt_s) {
  const DiffDriveStepResult result = robot_.Step(v_cmd_mps, omega_cmd_radps, dt_s);
  sim_time_s_ += dt_s;
  SampleDueSensors();
  return result;
}

void SimulatedRobot::SampleDueSensors() {
  const auto due = [this](int64_t index, double rate_hz) {
    return static_cast<double>(index) / rate_hz <= sim_time_s_ + kClockSlackS;
  };
  if (due(next_odometry_index_, options_.odometry_rate_hz)) {
    odometry_.time_s = sim_time_s_;
    odometry_.pose = odometry_model_.Update(robot_.pose());
    odometry_unread_ = true;
    next_odometry_index_ = NextIndexAfter(sim_time_s_, options_.odometry_rate_hz);
  }
  if (due(next_scan_index_, options_.scan_rate_hz)) {
    pending_scan_ = lidar_.Scan(world_, robot_.pose(), sim_time_s_, lidar_rng_);
    next_scan_index_ = NextIndexAfter(sim_time_s_, options_.scan_rate_hz);
  }
}

std::optional<sensor::LaserScan> SimulatedRobot::MaybeScan() {
  std::optional<sensor::LaserScan> scan = std::move(pending_scan_);
  pending_scan_.reset();
  return scan;
}

std::optional<sensor::Odometry> SimulatedRobot::MaybeOdometry() {
  if (!odometry_unread_) return std::nullopt;
  odometry_unread_ = false;
  return odometry_;
}

}  // namespace scout::sim
