#include "scout/io/carmen_log_writer.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include "scout/common/error.h"

namespace scout::io {
namespace {

// Numbers are written in the shortest text that reads back to the same
// float (ranges) or double (poses, times), so a replay of the log feeds SLAM
// exactly what the closed loop fed it and repeats its trajectory bit for bit.
template <typename T>
void AppendNumber(std::string* line, T value) {
  if (std::isnan(value)) {
    *line += " nan";
  } else if (std::isinf(value)) {
    *line += value > 0 ? " inf" : " -inf";
  } else {
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
    (void)error;  // 64 characters hold any float or double
    *line += ' ';
    line->append(text, end);
  }
}

}  // namespace

void CheckFlaserGeometry(double angle_min_rad, double angle_increment_rad, int num_beams,
                         const std::string& what) {
  // The reader (carmen_log_reader.cc) spreads n beams over pi in n - 1 steps
  // for odd n and n steps for even n, starting at -pi/2.
  const int steps = num_beams % 2 == 1 ? num_beams - 1 : num_beams;
  const double expected_increment = steps > 0 ? std::numbers::pi / steps : 0.0;
  constexpr double kTolerance_rad = 1e-5;
  if (num_beams < 2 || std::abs(angle_min_rad + std::numbers::pi / 2) > kTolerance_rad ||
      std::abs(angle_increment_rad - expected_increment) * steps > kTolerance_rad) {
    throw InputError(what +
                     ": a CARMEN FLASER line needs beams from -90 degrees over 180 degrees "
                     "(an odd count n with both ends included, or an even count n spaced "
                     "180/n degrees); this scan has " +
                     std::to_string(num_beams) + " beams from " +
                     std::to_string(angle_min_rad * 180.0 / std::numbers::pi) + " degrees, " +
                     std::to_string(angle_increment_rad * 180.0 / std::numbers::pi) +
                     " degrees apart");
  }
}

CarmenLogWriter::CarmenLogWriter(const std::filesystem::path& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw InputError(path.string() + ": cannot open for writing (expected a writable path)");
  }
  std::fputs(
      "# CARMEN log written by Scout: FLASER lines hold the true pose as x y theta and\n"
      "# the odometry pose as odom_x odom_y odom_theta; beams without a return are inf.\n"
      "# ODOM lines hold every odometry sample SLAM got (`scout replay --explore-slam`\n"
      "# feeds them, and so repeats the run's SLAM exactly).\n",
      file_);
}

CarmenLogWriter::~CarmenLogWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void CarmenLogWriter::AddScan(const sensor::LaserScan& scan, const geometry::Rigid2d& pose,
                              const geometry::Rigid2d& odometry) {
  if (file_ == nullptr) throw InputError(path_.string() + ": written to after Close()");
  CheckFlaserGeometry(scan.angle_min_rad, scan.angle_increment_rad,
                      static_cast<int>(scan.ranges.size()), path_.string());
  std::string line = "FLASER " + std::to_string(scan.ranges.size());
  line.reserve(line.size() + 8 * scan.ranges.size() + 160);
  for (const float r : scan.ranges) AppendNumber(&line, r);
  for (const double v :
       {pose.x(), pose.y(), pose.theta(), odometry.x(), odometry.y(), odometry.theta()}) {
    AppendNumber(&line, v);
  }
  WriteLine(&line, scan.time_s);
  ++num_scans_;
}

void CarmenLogWriter::AddOdometry(const sensor::Odometry& odometry) {
  if (file_ == nullptr) throw InputError(path_.string() + ": written to after Close()");
  std::string line = "ODOM";
  for (const double v : {odometry.pose.x(), odometry.pose.y(), odometry.pose.theta()}) {
    AppendNumber(&line, v);
  }
  line += " 0 0 0";  // tv rv accel: not recorded
  WriteLine(&line, odometry.time_s);
  ++num_odometry_;
}

void CarmenLogWriter::WriteLine(std::string* line, double time_s) {
  AppendNumber(line, time_s);  // ipc_timestamp
  *line += " scout-sim";
  AppendNumber(line, time_s);  // logger_timestamp
  *line += '\n';
  if (std::fputs(line->c_str(), file_) == EOF) {
    throw InputError(path_.string() + ": write failed (disk full?)");
  }
}

void CarmenLogWriter::Close() {
  if (file_ == nullptr) return;
  const bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed) throw InputError(path_.string() + ": write failed (disk full?)");
}

}  // namespace scout::io
