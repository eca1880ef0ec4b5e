#ifndef SCOUT_IO_CARMEN_LOG_READER_H_
#define SCOUT_IO_CARMEN_LOG_READER_H_

// Reader for CARMEN text logs (the Radish / Freiburg format), plain or gzip.
//
// Messages read (all times are the ipc_timestamp field):
//   FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname
//          logger_timestamp
//     A 180 degree front laser from -90 degrees. An even n covers [-90, 90) in
//     steps of 180/n degrees, an odd n covers [-90, 90] in steps of
//     180/(n-1): 180 and 181 beams are 1 degree apart, 360 and 361 half a
//     degree, as in the Radish logs. The scan pose is (x, y, theta).
//     FLASER has no range limit field: range_max_m is inferred per file.
//     If one largest reading repeats (at least 10 times), it is the sensor's
//     "no return" value (81.91 m for a SICK LMS in cm mode, 32.767 m in mm
//     mode, or a logger's clip value such as 50 m) and range_max_m is 99 % of
//     it, so that value and the error codes just below it (81.83, 81.87 ...)
//     count as no return. Otherwise range_max_m is 81.9 m (SICK LMS).
//   ROBOTLASER1 laser_type start_angle field_of_view angular_resolution
//          maximum_range accuracy remission_mode n r1..rn m rem1..remm
//          laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv
//          forward_safety_dist side_safety_dist turn_axis ipc_timestamp
//          ipc_hostname logger_timestamp
//     angle_min = start_angle, increment = angular_resolution, range_max =
//     maximum_range. The scan pose is the robot pose.
//   ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp
//
// Everything else (PARAM, NEFF, RLASER, ... and '#' comments) is skipped
// silently and counted. Problems become warnings naming file:line and what
// was expected, and reading goes on: malformed lines are skipped, scans and
// odometry messages out of time order are dropped (each stream keeps its
// longest run in time order, see time_order.h; fewer than half of the scans in
// order is an error), zero-beam scans are dropped. NaN and infinite ranges are
// kept (they mean "no return"). A gzip stream that breaks off after some lines
// keeps those lines with a warning.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

#include "scout/io/dataset.h"

namespace scout::io {

// What a CARMEN log held, by message kind.
struct CarmenLogCounts {
  // Messages read into the dataset.
  std::size_t flaser = 0;
  std::size_t robotlaser1 = 0;
  std::size_t odom = 0;
  // Messages dropped with a warning.
  std::size_t malformed_lines = 0;
  std::size_t backwards_scans = 0;     // out of time order
  std::size_t backwards_odometry = 0;  // out of time order
  std::size_t zero_beam_scans = 0;
  // Skipped silently: '#' comments and blank lines, and other message types
  // by name (e.g. "PARAM", "NEFF").
  std::size_t comment_lines = 0;
  std::map<std::string, std::size_t> other_messages;
};

// Reads the CARMEN log 'path' (plain or gzip). Fills 'counts' if not null.
// Throws InputError naming the file if it cannot be opened, if its gzip data
// is corrupt before any line, or if it holds no usable scan.
Dataset ReadCarmenLog(const std::filesystem::path& path, CarmenLogCounts* counts = nullptr);

}  // namespace scout::io

#endif  // SCOUT_IO_CARMEN_LOG_READER_H_
