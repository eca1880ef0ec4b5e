#include "scout/io/dataset.h"

#include <array>
#include <string_view>

#include "scout/common/error.h"
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

Dataset LoadDataset(const std::filesystem::path& path, const DatasetOptions& options) {
  // Content, not the name, decides: logs come as .log, .clf, .txt, .gz ...
  const std::string head = ReadLeadingBytes(path, 13);
  if (head.starts_with("#ROSBAG V2.0")) return ReadRosBag(path, options);
  if (head.starts_with("#ROSBAG V")) {
    throw InputError(path.string() + ": ROS bag of format '" + head.substr(1, 11) +
                     "'; expected format V2.0 (rosbag reindex/fix can convert older bags)");
  }
  Dataset dataset = ReadCarmenLog(path);
  if (!options.scan_topic.empty() || !options.odometry_topic.empty()) {
    dataset.warnings.push_back(path.string() +
                               ": scan and odometry topics are options for ROS bags; ignored for "
                               "this CARMEN log");
  }
  return dataset;
}

}  // namespace scout::io
