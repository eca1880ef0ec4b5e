#ifndef SCOUT_SIM_SIMULATED_ROBOT_H_
#define SCOUT_SIM_SIMULATED_ROBOT_H_

#include <cstdint>
#include <optional>
#include <random>

#include "scout/geometry/rigid_transform.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sensor/odometry.h"
#include "scout/sim/diff_drive_robot.h"
#include "scout/sim/lidar.h"
#include "scout/sim/odometry_model.h"
#include "scout/sim/world.h"

namespace scout::sim {

struct SimulatedRobotOptions {
  DiffDriveOptions robot;
  LidarOptions lidar;
  OdometryNoiseOptions odometry;
  // Scans per second (the paper's Hokuyo class runs at 10 Hz).
  double scan_rate_hz = 10.0;
  // Odometry samples per second, at most one per Step (a faster rate samples
  // once per step). The noise is drawn per sample, so a different rate changes
  // the drift (see OdometryNoiseOptions). 20 Hz: one sample per step of
  // `scout explore` (explore.dt_s = 0.05 s), as it has always sampled.
  double odometry_rate_hz = 20.0;
  // Heading at the world's start position.
  double start_heading_rad = 0.0;
};

// Throws InputError naming the key if an option is invalid.
void CheckSimulatedRobotOptions(const SimulatedRobotOptions& options);

// A robot in a TRUE world, as the rest of Scout sees it: velocity commands in,
// lidar scans and wheel odometry out, plus ground truth for evaluation.
//
// Sensors sample on their own clocks: a reading is due every 1 / rate seconds
// from t = 0, and is taken at the end of the first Step that reaches its due
// time, stamped with the sim time of that moment (so with dt dividing the
// period, stamps are exact multiples of it). Readings for t = 0 exist before
// any Step. If one Step spans several periods only one reading is taken.
// The odometry frame coincides with the world frame at t = 0.
//
// Deterministic: the same world, options, seed and commands give identical
// readings; lidar and odometry noise use independent streams of 'seed'.
class SimulatedRobot {
 public:
  // 'world' must outlive the robot. Throws InputError if an option is invalid
  // or the disc does not fit at the world's start.
  SimulatedRobot(const World& world, const SimulatedRobotOptions& options, uint64_t seed);

  // Advances the simulation by 'dt_s' seconds with the commanded body
  // velocities (limited as DiffDriveRobot::Step) and samples due sensors.
  DiffDriveStepResult Step(double v_cmd_mps, double omega_cmd_radps, double dt_s);

  // Returns the scan taken since the last call, if any (at most one is kept:
  // an unread scan is replaced by the next, as a driver's queue of one).
  std::optional<sensor::LaserScan> MaybeScan();
  // Returns the odometry sample taken since the last call, if any.
  std::optional<sensor::Odometry> MaybeOdometry();
  // Returns the latest odometry sample (stamped with its sample time).
  const sensor::Odometry& OdometryReading() const { return odometry_; }

  // Ground truth and bookkeeping.
  const geometry::Rigid2d& true_pose() const { return robot_.pose(); }
  double sim_time_s() const { return sim_time_s_; }
  int collisions() const { return robot_.collisions(); }
  double path_length_m() const { return robot_.path_length_m(); }
  const DiffDriveRobot& robot() const { return robot_; }
  const SimulatedRobotOptions& options() const { return options_; }

 private:
  void SampleDueSensors();

  const World& world_;
  SimulatedRobotOptions options_;
  DiffDriveRobot robot_;
  Lidar lidar_;
  std::mt19937_64 lidar_rng_;
  OdometryModel odometry_model_;
  double sim_time_s_ = 0.0;
  // Sensor clocks count periods as integers so due times never drift by
  // floating-point accumulation.
  int64_t next_scan_index_ = 0;
  int64_t next_odometry_index_ = 0;
  std::optional<sensor::LaserScan> pending_scan_;
  bool odometry_unread_ = false;
  sensor::Odometry odometry_;
};

}  // namespace scout::sim

#endif  // SCOUT_SIM_SIMULATED_ROBOT_H_
