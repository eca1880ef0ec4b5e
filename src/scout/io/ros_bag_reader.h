#ifndef SCOUT_IO_ROS_BAG_READER_H_
#define SCOUT_IO_ROS_BAG_READER_H_

// Reader for ROS 1 bags (format 2.0), plain or gzip-compressed. The
// implementation is a C++17 translation unit (ROS 1 message headers); this
// header includes no ROS headers, so C++20 code may include it.
//
// Scans come from one sensor_msgs/LaserScan topic, odometry from one
// nav_msgs/Odometry topic. Time is the message header stamp, or the bag's
// receive time when the stamp is zero. Odometry keeps x, y and the yaw of the
// orientation quaternion. Messages whose time is earlier than the previous one
// of their stream and scans without beams are dropped with a warning.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "scout/io/dataset.h"

namespace scout::io {

// One topic of a bag.
struct BagTopic {
  std::string name;
  std::string type;  // e.g. "sensor_msgs/LaserScan"
  std::size_t message_count = 0;
};

// Reads the bag 'path'. A .gz bag is decompressed into a temporary file that
// is removed again, also on error. Topics are chosen by 'options' (empty: the
// topic of the right type with most messages; a warning names the others if
// there are several). Throws InputError naming the file if the bag is
// corrupt, truncated or unreadable, has no scan topic, or if a topic named in
// 'options' is not in the bag with the right type (the message lists the
// topics of that type). Missing odometry is only a warning.
Dataset ReadRosBag(const std::filesystem::path& path, const DatasetOptions& options = {});

// Returns the topics of the bag 'path' (plain, not gzip) in name order.
// Throws InputError naming the file if it is not a readable bag.
std::vector<BagTopic> ListBagTopics(const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_ROS_BAG_READER_H_
