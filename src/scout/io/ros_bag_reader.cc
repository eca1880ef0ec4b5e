// C++17 translation unit: the ROS 1 message headers do not compile as C++20.
#include "scout/io/ros_bag_reader.h"

// Compiled as C++20 this would break on the ROS headers in confusing ways.
static_assert(__cplusplus == 201703L, "compile ros_bag_reader.cc with scout_ros1_sources()");

#include <nav_msgs/Odometry.h>
#include <ros/exception.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/input_limits.h"
#include "scout/io/dataset_warnings.h"
#include "scout/io/gzip_file.h"
#include "scout/io/time_order.h"

// Length probes: read through rosbag like messages, they walk a LaserScan's
// or an Odometry's serialised fields for the lengths of its strings and
// arrays only. ros deserialisation sizes a string or array from its length
// field before it finds the message too short, so a corrupt length of 1e9
// would first allocate gigabytes; a probe names the field instead.
namespace scout::io::bag_probe {
struct ScanLengths {
  std::string problem;  // empty: every length fits the message
};
struct OdometryLengths {
  std::string problem;
};

// Skips a length-prefixed string or array of 'element_bytes' elements, or
// records why it does not fit in what is left of the message.
template <typename Stream>
bool SkipVariable(Stream& stream, const char* field, uint64_t element_bytes, std::string* problem) {
  uint32_t length = 0;
  stream.next(length);
  if (element_bytes * length > stream.getLength()) {
    *problem = std::string(field) + " length " + std::to_string(length) + " runs past the message";
    return false;
  }
  stream.advance(static_cast<uint32_t>(element_bytes * length));
  return true;
}
}  // namespace scout::io::bag_probe

namespace ros::message_traits {
// "*": rosbag instantiates a probe from a message of any type.
template <>
struct MD5Sum<scout::io::bag_probe::ScanLengths> {
  static const char* value() { return "*"; }
  static const char* value(const scout::io::bag_probe::ScanLengths&) { return "*"; }
};
template <>
struct MD5Sum<scout::io::bag_probe::OdometryLengths> {
  static const char* value() { return "*"; }
  static const char* value(const scout::io::bag_probe::OdometryLengths&) { return "*"; }
};
}  // namespace ros::message_traits

namespace ros::serialization {
template <>
struct Serializer<scout::io::bag_probe::ScanLengths> {
  template <typename Stream>
  static void read(Stream& stream, scout::io::bag_probe::ScanLengths& m) {
    stream.advance(4 + 8);  // header: seq, stamp
    if (!scout::io::bag_probe::SkipVariable(stream, "header.frame_id", 1, &m.problem)) return;
    stream.advance(7 * 4);  // angle_min ... range_max
    if (!scout::io::bag_probe::SkipVariable(stream, "ranges", 4, &m.problem)) return;
    scout::io::bag_probe::SkipVariable(stream, "intensities", 4, &m.problem);
  }
};
template <>
struct Serializer<scout::io::bag_probe::OdometryLengths> {
  template <typename Stream>
  static void read(Stream& stream, scout::io::bag_probe::OdometryLengths& m) {
    stream.advance(4 + 8);
    if (!scout::io::bag_probe::SkipVariable(stream, "header.frame_id", 1, &m.problem)) return;
    scout::io::bag_probe::SkipVariable(stream, "child_frame_id", 1, &m.problem);
  }
};
}  // namespace ros::serialization

namespace scout::io {
namespace {

namespace fs = std::filesystem;

constexpr char kScanType[] = "sensor_msgs/LaserScan";
constexpr char kOdometryType[] = "nav_msgs/Odometry";

std::vector<BagTopic> TopicsOf(rosbag::Bag& bag) {
  std::map<std::string, BagTopic> by_name;
  rosbag::View view(bag);
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    BagTopic& topic = by_name[connection->topic];
    topic.name = connection->topic;
    topic.type = connection->datatype;
  }
  for (auto& [name, topic] : by_name) {
    topic.message_count = rosbag::View(bag, rosbag::TopicQuery(name)).size();
  }
  std::vector<BagTopic> topics;
  for (auto& [name, topic] : by_name) topics.push_back(std::move(topic));
  return topics;
}

std::string Describe(const std::vector<BagTopic>& topics, const std::string& type) {
  std::string text;
  for (const BagTopic& topic : topics) {
    if (!type.empty() && topic.type != type) continue;
    text += (text.empty() ? "" : ", ") + topic.name + " (" +
            (type.empty() ? topic.type + ", " : "") + std::to_string(topic.message_count) +
            " messages)";
  }
  return text.empty() ? "none" : text;
}

// Returns the topic to read for 'type': 'requested' if set (InputError if it
// is not a topic of that type), else the one with most messages, or nothing.
std::optional<BagTopic> ChooseTopic(const std::vector<BagTopic>& topics, const std::string& type,
                                    const std::string& requested, const std::string& source,
                                    std::vector<std::string>* warnings) {
  if (!requested.empty()) {
    for (const BagTopic& topic : topics) {
      if (topic.name == requested && topic.type == type) return topic;
    }
    throw InputError(source + ": topic '" + requested + "' is not a " + type +
                     " topic of the bag; expected one of: " + Describe(topics, type));
  }
  std::vector<BagTopic> candidates;
  for (const BagTopic& topic : topics) {
    if (topic.type == type) candidates.push_back(topic);
  }
  if (candidates.empty()) return std::nullopt;
  // Most messages first; ties by name, so the choice does not depend on order.
  std::sort(candidates.begin(), candidates.end(), [](const BagTopic& a, const BagTopic& b) {
    return a.message_count != b.message_count ? a.message_count > b.message_count : a.name < b.name;
  });
  if (candidates.size() > 1) {
    warnings->push_back(source + ": several " + type + " topics (" + Describe(candidates, type) +
                        "); reading " + candidates.front().name +
                        " (the one with most messages; choose another in the options)");
  }
  return candidates.front();
}

double StampOrBagTime(const ros::Time& stamp, const ros::Time& bag_time) {
  return stamp.isZero() ? bag_time.toSec() : stamp.toSec();
}

// A stamp's nanoseconds must be below 1e9 (deserialised stamps are not
// normalised; 0xFFFFFFFF would shift the time by 4 s).
bool ValidStamp(const ros::Time& stamp) { return stamp.nsec < 1000000000u; }

double YawOf(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

class BagConverter {
 public:
  BagConverter(const std::string& source, Dataset* dataset)
      : source_(source), dataset_(dataset), warnings_(&dataset->warnings) {}

  void AddScan(const sensor_msgs::LaserScan& message, const ros::Time& bag_time) {
    const double time = StampOrBagTime(message.header.stamp, bag_time);
    if (!ValidStamp(message.header.stamp)) {
      warnings_.Add("messages with invalid stamps",
                    source_ + ": LaserScan at bag time " + FormatNumber(bag_time.toSec()) +
                        " s has header.stamp.nsec " + std::to_string(message.header.stamp.nsec) +
                        "; skipped (expected nanoseconds below 1e9)");
      return;
    }
    if (message.ranges.empty()) {
      warnings_.Add("scans without beams", source_ + ": LaserScan at t=" + FormatNumber(time) +
                                               " s has 0 beams; skipped (expected ranges)");
      return;
    }
    if (!std::isfinite(message.angle_min) || !std::isfinite(message.angle_increment) ||
        message.angle_increment == 0.f) {
      warnings_.Add("scans with unusable angles",
                    source_ + ": LaserScan at t=" + FormatNumber(time) + " s has angle_min " +
                        FormatNumber(message.angle_min) + " and angle_increment " +
                        FormatNumber(message.angle_increment) +
                        "; skipped (expected finite angles and a nonzero increment)");
      return;
    }
    if (!(message.range_min >= 0.f) || !(message.range_max > message.range_min)) {
      warnings_.Add("scans with unusable range limits",
                    source_ + ": LaserScan at t=" + FormatNumber(time) + " s has range_min " +
                        FormatNumber(message.range_min) + " and range_max " +
                        FormatNumber(message.range_max) +
                        "; skipped (expected 0 <= range_min < range_max)");
      return;
    }
    sensor::LaserScan scan;
    scan.time_s = time;
    scan.angle_min_rad = message.angle_min;
    scan.angle_increment_rad = message.angle_increment;
    scan.range_min_m = message.range_min;
    scan.range_max_m = message.range_max;
    scan.ranges = message.ranges;
    dataset_->scans.push_back(std::move(scan));
  }

  void AddOdometry(const nav_msgs::Odometry& message, const ros::Time& bag_time) {
    const double time = StampOrBagTime(message.header.stamp, bag_time);
    if (!ValidStamp(message.header.stamp)) {
      warnings_.Add("messages with invalid stamps",
                    source_ + ": Odometry at bag time " + FormatNumber(bag_time.toSec()) +
                        " s has header.stamp.nsec " + std::to_string(message.header.stamp.nsec) +
                        "; skipped (expected nanoseconds below 1e9)");
      return;
    }
    const geometry_msgs::Pose& pose = message.pose.pose;
    const geometry_msgs::Quaternion& q = pose.orientation;
    // A zero or garbage quaternion has no heading (atan2(0, 1) would say 0).
    const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    const double yaw = YawOf(q);
    if (!(std::abs(pose.position.x) <= kMaxInputCoordinateM) ||
        !(std::abs(pose.position.y) <= kMaxInputCoordinateM) || !std::isfinite(yaw) ||
        !(std::abs(norm - 1.0) <= 0.1)) {
      warnings_.Add("odometry messages with unusable poses",
                    source_ + ": Odometry at t=" + FormatNumber(time) + " s at (" +
                        FormatNumber(pose.position.x) + ", " + FormatNumber(pose.position.y) +
                        ") with an orientation quaternion of norm " + FormatNumber(norm) +
                        "; dropped (expected finite coordinates within 1000 km and a unit "
                        "quaternion)");
      return;
    }
    dataset_->odometry.push_back({time, geometry::Rigid2d(pose.position.x, pose.position.y, yaw)});
  }

  void SkipCorrupt(const std::string& topic, const ros::Time& bag_time, const std::string& why) {
    warnings_.Add("unreadable messages", source_ + ": message on " + topic + " at bag time " +
                                             FormatNumber(bag_time.toSec()) + " s is corrupt (" +
                                             why + "); skipped");
  }

  // Keeps each stream's longest run in time order (see time_order.h); throws
  // InputError if that leaves fewer than half of the scans.
  void Finish() {
    const std::vector<bool> keep_scan = LongestTimeOrderOf(dataset_->scans);
    for (std::size_t i = 0; i < keep_scan.size(); ++i) {
      if (keep_scan[i]) continue;
      warnings_.Add("scans out of time order",
                    source_ + ": LaserScan at t=" + FormatNumber(dataset_->scans[i].time_s) +
                        " s is out of time order with the scans around it; dropped (expected "
                        "non-decreasing header stamps)");
    }
    KeepOnly(keep_scan, &dataset_->scans);
    if (2 * dataset_->scans.size() < keep_scan.size()) {
      throw InputError(source_ + ": only " + std::to_string(dataset_->scans.size()) + " of " +
                       std::to_string(keep_scan.size()) +
                       " scans are in time order; expected non-decreasing header stamps (are "
                       "the stamps corrupt?)");
    }
    const std::vector<bool> keep_odometry = LongestTimeOrderOf(dataset_->odometry);
    for (std::size_t i = 0; i < keep_odometry.size(); ++i) {
      if (keep_odometry[i]) continue;
      warnings_.Add("odometry messages out of time order",
                    source_ + ": Odometry at t=" + FormatNumber(dataset_->odometry[i].time_s) +
                        " s is out of time order with the messages around it; dropped "
                        "(expected non-decreasing header stamps)");
    }
    KeepOnly(keep_odometry, &dataset_->odometry);
    warnings_.Finish(source_);
  }

 private:
  std::string source_;
  Dataset* dataset_;
  DatasetWarnings warnings_;
};

// Reads the plain bag 'bag_path'; errors and warnings name 'source'.
void ReadPlainBag(const fs::path& bag_path, const std::string& source,
                  const DatasetOptions& options, Dataset* dataset) {
  rosbag::Bag bag(bag_path.string(), rosbag::bagmode::Read);
  const std::vector<BagTopic> topics = TopicsOf(bag);
  const std::optional<BagTopic> scan_topic =
      ChooseTopic(topics, kScanType, options.scan_topic, source, &dataset->warnings);
  if (!scan_topic) {
    throw InputError(source + ": no " + std::string(kScanType) +
                     " topic in the bag; expected at least one. " +
                     (topics.empty() ? std::string("The bag holds no messages")
                                     : "Topics: " + Describe(topics, "")));
  }
  const std::optional<BagTopic> odometry_topic =
      ChooseTopic(topics, kOdometryType, options.odometry_topic, source, &dataset->warnings);
  std::vector<std::string> wanted = {scan_topic->name};
  if (odometry_topic) {
    wanted.push_back(odometry_topic->name);
  } else {
    dataset->warnings.push_back(source + ": no " + std::string(kOdometryType) +
                                " topic in the bag; the dataset has no odometry");
  }
  BagConverter converter(source, dataset);
  rosbag::View view(bag, rosbag::TopicQuery(wanted));
  for (const rosbag::MessageInstance& message : view) {
    // A message whose bytes are corrupt (a length field beyond the message)
    // is skipped; the chunks around it still read.
    try {
      const bool is_scan = message.getTopic() == scan_topic->name;
      const std::string problem = is_scan
                                      ? message.instantiate<bag_probe::ScanLengths>()->problem
                                      : message.instantiate<bag_probe::OdometryLengths>()->problem;
      if (!problem.empty()) {
        converter.SkipCorrupt(message.getTopic(), message.getTime(), problem);
        continue;
      }
      if (is_scan) {
        if (auto scan = message.instantiate<sensor_msgs::LaserScan>()) {
          converter.AddScan(*scan, message.getTime());
        }
      } else if (auto odometry = message.instantiate<nav_msgs::Odometry>()) {
        converter.AddOdometry(*odometry, message.getTime());
      }
    } catch (const ros::Exception& e) {
      converter.SkipCorrupt(message.getTopic(), message.getTime(), e.what());
    }
  }
  converter.Finish();
  if (dataset->scans.empty()) {
    // The reasons are in the warnings, which an error would not show.
    throw InputError(source + ": topic " + scan_topic->name +
                     " holds no usable scan; expected LaserScan messages with ranges" +
                     (dataset->warnings.empty()
                          ? std::string()
                          : " (first problem: " + dataset->warnings.front() + ")"));
  }
}

// Runs 'read', turning library exceptions (rosbag, serialization, allocation
// from corrupt sizes) into InputError naming 'source'.
template <typename Read>
auto WithInputErrors(const std::string& source, Read read) {
  try {
    return read();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(source + ": not a readable ROS 1 bag (" + e.what() +
                     "); expected a complete, indexed bag of format 2.0 (a bag cut short loses "
                     "its index at the end: `rosbag reindex` rebuilds it)");
  }
}

}  // namespace

Dataset ReadRosBag(const fs::path& path, const DatasetOptions& options) {
  const std::string source = path.string();
  Dataset dataset;
  dataset.name = DatasetName(path);
  dataset.format = "rosbag";
  if (IsGzipFile(path)) {
    const TemporaryFile plain("scout_bag_");
    DecompressGzipFile(path, plain.path());
    WithInputErrors(source, [&] { ReadPlainBag(plain.path(), source, options, &dataset); });
  } else {
    WithInputErrors(source, [&] { ReadPlainBag(path, source, options, &dataset); });
  }
  return dataset;
}

std::vector<BagTopic> ListBagTopics(const fs::path& path) {
  return WithInputErrors(path.string(), [&] {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Read);
    return TopicsOf(bag);
  });
}

}  // namespace scout::io
