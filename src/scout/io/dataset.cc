#include "scout/io/dataset.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/io/carmen_log_reader.h"
#include "scout/io/gzip_file.h"
#include "scout/io/ros_bag_reader.h"

namespace scout::io {

std::string DatasetName(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  // Inner suffixes after ".gz" (x.bag.gz, x.log.gz).
  for (const std::string_view suffix : {".gz", ".log", ".bag", ".clf"}) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      name.resize(name.size() - suffix.size());
    }
  }
  return name;
}

namespace {

// A gap between consecutive scans longer than this is worth a word: the
// real-time factor and the data's duration include it.
constexpr double kLongGapS = 3600.0;

bool HasReturn(const sensor::LaserScan& scan) {
  for (const float range : scan.ranges) {
    if (std::isfinite(range) && range > 0.f && range >= scan.range_min_m &&
        range < scan.range_max_m) {
      return true;
    }
  }
  return false;
}

// Checks what both formats share: some scan must see something, and long
// gaps in time are reported.
void CheckScans(const std::string& source, Dataset* dataset) {
  if (std::none_of(dataset->scans.begin(), dataset->scans.end(), HasReturn)) {
    throw InputError(source + ": none of the " + std::to_string(dataset->scans.size()) +
                     " scans has a single return (every range is NaN, infinite, zero or outside "
                     "the scan's range limits); expected ranges of a lidar that sees something");
  }
  const std::vector<sensor::LaserScan>& scans = dataset->scans;
  for (std::size_t i = 1; i < scans.size(); ++i) {
    if (scans[i].time_s - scans[i - 1].time_s > kLongGapS) {
      dataset->warnings.push_back(
          source + ": " + FormatNumber(scans[i].time_s - scans[i - 1].time_s) +
          " s pass between the scans at t=" + FormatNumber(scans[i - 1].time_s) +
          " s and t=" + FormatNumber(scans[i].time_s) +
          " s; the data's duration and real-time factor include them");
    }
  }
}

}  // namespace

Dataset LoadDataset(const std::filesystem::path& path, const DatasetOptions& options) {
  // Content, not the name, decides: logs come as .log, .clf, .txt, .gz ...
  const std::string head = ReadLeadingBytes(path, 13);
  Dataset dataset;
  if (head.starts_with("#ROSBAG V2.0")) {
    dataset = ReadRosBag(path, options);
  } else if (head.starts_with("#ROSBAG V")) {
    throw InputError(path.string() + ": ROS bag of format '" + head.substr(1, 11) +
                     "'; expected format V2.0 (rosbag reindex/fix can convert older bags)");
  } else {
    try {
      dataset = ReadCarmenLog(path);
    } catch (const InputError& e) {
      // Content decides, but a bag's bytes read as a log only give "no
      // usable laser scan": say why it was read as a log.
      const std::string name = path.filename().string();
      if (!name.ends_with(".bag") && !name.ends_with(".bag.gz")) throw;
      throw InputError(std::string(e.what()) +
                       "; the file is named like a ROS bag but does not start with '#ROSBAG "
                       "V2.0', so it was read as a CARMEN log");
    }
    if (!options.scan_topic.empty() || !options.odometry_topic.empty()) {
      dataset.warnings.push_back(path.string() +
                                 ": scan and odometry topics are options for ROS bags; ignored "
                                 "for this CARMEN log");
    }
  }
  CheckScans(path.string(), &dataset);
  return dataset;
}

}  // namespace scout::io
