#ifndef SCOUT_IO_CARMEN_LOG_WRITER_H_
#define SCOUT_IO_CARMEN_LOG_WRITER_H_

// Writes laser scans as a CARMEN log that `scout replay` (and other CARMEN
// tools) can read: `scout explore --record-log` records the simulated robot's
// sensor stream with it, so SLAM can be re-run on exactly the data a closed-loop
// run saw, against the simulator's true poses.

#include <cstdio>
#include <filesystem>
#include <string>

#include "scout/geometry/rigid_transform.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sensor/odometry.h"

namespace scout::io {

// Throws InputError unless scans with this geometry fit a FLASER line, whose
// beams by convention start at -90 degrees and span 180 degrees: n - 1 steps
// for an odd count n (both ends included), n steps for an even count ('what'
// names the scan source in the message).
void CheckFlaserGeometry(double angle_min_rad, double angle_increment_rad, int num_beams,
                         const std::string& what);

class CarmenLogWriter {
 public:
  // Opens 'path' for writing (truncating it). Throws InputError naming the file
  // if it cannot be opened.
  explicit CarmenLogWriter(const std::filesystem::path& path);
  ~CarmenLogWriter();
  CarmenLogWriter(const CarmenLogWriter&) = delete;
  CarmenLogWriter& operator=(const CarmenLogWriter&) = delete;

  // Appends one FLASER line: the ranges (beams without a return as "inf", NaN
  // as "nan"; CARMEN has no marker of its own and Scout's reader takes both),
  // 'pose' as the laser pose (a reference trajectory for `scout replay
  // --reference`), 'odometry' as the odometry pose, and the scan's time as
  // ipc and logger timestamps. Throws InputError if the scan's geometry does
  // not fit FLASER (CheckFlaserGeometry) or the write fails.
  void AddScan(const sensor::LaserScan& scan, const geometry::Rigid2d& pose,
               const geometry::Rigid2d& odometry);
  // Appends one ODOM line: the odometry pose at its time (velocities 0, not
  // recorded). Throws InputError if the write fails.
  void AddOdometry(const sensor::Odometry& odometry);

  // Flushes and closes the file. Throws InputError naming the file if the data
  // could not be written completely.
  void Close();

  int num_scans() const { return num_scans_; }
  int num_odometry() const { return num_odometry_; }

 private:
  // Ends 'line' with the timestamps and host name every message carries and
  // writes it. Throws InputError if the write fails.
  void WriteLine(std::string* line, double time_s);

  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  int num_scans_ = 0;
  int num_odometry_ = 0;
};

}  // namespace scout::io

#endif  // SCOUT_IO_CARMEN_LOG_WRITER_H_
