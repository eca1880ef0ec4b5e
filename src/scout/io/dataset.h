#ifndef SCOUT_IO_DATASET_H_
#define SCOUT_IO_DATASET_H_

// Recorded sensor data (CARMEN logs, ROS 1 bags) as Scout's sensor types.
// This header is included by C++17 translation units (the ROS 1 bag reader),
// so it must stay C++17-compatible.

#include <filesystem>
#include <string>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/sensor/laser_scan.h"
#include "scout/sensor/odometry.h"

namespace scout::io {

// Everything a dataset file holds that Scout uses.
struct Dataset {
  // The file name without directories and without .gz/.log/.bag/.clf suffixes.
  std::string name;
  // "carmen" or "rosbag".
  std::string format;
  // Strictly ordered by time_s, except that equal times are kept (some logs
  // carry no usable timing; a warning says so).
  std::vector<sensor::LaserScan> scans;
  // Ordered by time_s like 'scans'; empty if the file has no odometry.
  std::vector<sensor::Odometry> odometry;
  // For CARMEN logs, the robot pose stored with each scan (same size as
  // 'scans'); in "-corrected" logs this is the corrected pose, usable as a
  // reference trajectory. Empty for bags.
  std::vector<geometry::Rigid2d> scan_poses;
  // For CARMEN logs, the odometry pose each laser line carries (FLASER
  // odom_x/y/theta, ROBOTLASER1 robot pose), stamped with the scan's time
  // (same size as 'scans'). Unlike the ODOM messages of the Radish
  // "-corrected" logs, which restart from the corrected pose after every scan,
  // this is one consistent odometry trajectory. Empty for bags.
  std::vector<sensor::Odometry> scan_odometry;
  // Problems that were worked around (skipped lines, dropped messages), each
  // naming the file and where possible the line.
  std::vector<std::string> warnings;
};

struct DatasetOptions {
  // Bags only: the topics to read. Empty means: the topic of type
  // sensor_msgs/LaserScan (resp. nav_msgs/Odometry) with the most messages.
  std::string scan_topic;
  std::string odometry_topic;
};

// Loads a CARMEN log or a ROS 1 bag, plain or gzip-compressed; the format is
// detected from the content (gzip magic, then "#ROSBAG V2.0" versus text), not
// from the file name. Throws InputError naming the file when it cannot be
// read or holds no usable scan.
Dataset LoadDataset(const std::filesystem::path& path, const DatasetOptions& options = {});

// Returns the dataset name of 'path': its file name without the suffixes
// .gz, .log, .bag and .clf (e.g. "intel-corrected" for intel-corrected.log.gz).
std::string DatasetName(const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_DATASET_H_
