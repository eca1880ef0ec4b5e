#include "scout/io/carmen_log_reader.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/input_limits.h"
#include "scout/io/dataset_warnings.h"
#include "scout/io/gzip_file.h"
#include "scout/io/time_order.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

// SICK LMS 2xx in cm mode: 81.91 m means "no return"; readings near it are
// error codes, never real returns.
constexpr float kSickRangeMaxM = 81.9f;
// A largest reading repeated this often is a saturation value, not a return.
constexpr std::size_t kMinSaturatedReadings = 10;
// Readings within 1 % below the saturation value count as no return too.
constexpr float kSaturationBand = 0.99f;
constexpr double kHalfPi = std::numbers::pi / 2.0;

std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > begin) fields.push_back(line.substr(begin, i - begin));
  }
  return fields;
}

// Times (s) beyond this are corrupt: about the year 5100 in Unix time.
constexpr double kMaxTimeS = 1e11;

// Parses all of 'text' as a number ("nan" and "inf" included).
std::optional<double> ParseNumber(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Parses all of 'text' as a float, directly: a range written as the shortest
// text of a float reads back exactly (through a double it could round twice).
// For the few decimals of the usual logs both ways give the same float.
std::optional<float> ParseFloat(std::string_view text) {
  float value = 0.f;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::size_t> ParseCount(std::string_view text) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Fills the dataset from one log, line by line. Parse functions return the
// reason a line is malformed ("expected ..."), or nothing.
class CarmenParser {
 public:
  CarmenParser(const fs::path& path, Dataset* dataset, CarmenLogCounts* counts)
      : source_(path.string()), dataset_(dataset), counts_(counts), warnings_(&dataset->warnings) {}

  void ParseLine(std::size_t line_number, std::string_view line) {
    line_number_ = line_number;
    const std::vector<std::string_view> fields = SplitFields(line);
    if (fields.empty() || fields[0].front() == '#') {
      ++counts_->comment_lines;
      return;
    }
    std::optional<std::string> problem;
    if (fields[0] == "FLASER") {
      problem = ParseFlaser(fields);
    } else if (fields[0] == "ROBOTLASER1") {
      problem = ParseRobotLaser(fields);
    } else if (fields[0] == "ODOM") {
      problem = ParseOdom(fields);
    } else {
      ++counts_->other_messages[std::string(fields[0])];
    }
    if (problem) {
      ++counts_->malformed_lines;
      warnings_.Add("malformed lines", Where() + ": malformed " + std::string(fields[0]) +
                                           " message skipped: " + *problem);
    }
  }

  // Called once after the last line.
  void Finish() {
    DropOutOfTimeOrder();
    InferFlaserRangeMax();
    WarnIfTimesCoarse();
    warnings_.Finish(source_);
  }

  DatasetWarnings& warnings() { return warnings_; }

 private:
  std::string Where() const { return source_ + ":" + std::to_string(line_number_); }

  std::optional<std::string> ParseFlaser(const std::vector<std::string_view>& f) {
    const std::optional<std::size_t> n = f.size() > 1 ? ParseCount(f[1]) : std::nullopt;
    if (!n) return "expected the beam count as field 2";
    if (*n > f.size() || f.size() != *n + 11) {  // first test: no overflow
      return "expected " + std::to_string(*n + 11) + " fields for " + std::to_string(*n) +
             " beams (FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp "
             "ipc_hostname logger_timestamp), found " +
             std::to_string(f.size());
    }
    sensor::LaserScan scan;
    scan.ranges.resize(*n);
    for (std::size_t k = 0; k < *n; ++k) {
      const std::optional<float> r = ParseFloat(f[2 + k]);
      if (!r)
        return "expected a number as range " + std::to_string(k + 1) + ", found '" +
               std::string(f[2 + k]) + "'";
      scan.ranges[k] = *r;
    }
    double x, y, theta, odom_x, odom_y, odom_theta, time;
    if (auto problem = Numbers(f, {{*n + 2, &x},
                                   {*n + 3, &y},
                                   {*n + 4, &theta},
                                   {*n + 5, &odom_x},
                                   {*n + 6, &odom_y},
                                   {*n + 7, &odom_theta},
                                   {*n + 8, &time, kMaxTimeS}})) {
      return problem;
    }
    const std::size_t steps = *n % 2 == 1 ? *n - 1 : *n;
    scan.time_s = time;
    scan.angle_min_rad = static_cast<float>(-kHalfPi);
    scan.angle_increment_rad = steps > 0 ? static_cast<float>(std::numbers::pi / steps) : 0.f;
    scan.range_max_m = kSickRangeMaxM;  // replaced in InferFlaserRangeMax()
    if (AddScan(std::move(scan), geometry::Rigid2d(x, y, theta),
                geometry::Rigid2d(odom_x, odom_y, odom_theta), "FLASER")) {
      ++counts_->flaser;
    }
    return std::nullopt;
  }

  std::optional<std::string> ParseRobotLaser(const std::vector<std::string_view>& f) {
    const std::optional<std::size_t> n = f.size() > 8 ? ParseCount(f[8]) : std::nullopt;
    if (!n) return "expected the beam count num_readings as field 9";
    // Counts are compared before adding them, so absurd ones cannot overflow.
    const std::optional<std::size_t> m =
        *n < f.size() && f.size() - *n > 9 ? ParseCount(f[*n + 9]) : std::nullopt;
    if (!m) return "expected num_remissions as field " + std::to_string(*n + 10);
    if (*m > f.size() || f.size() != *n + *m + 24) {
      return "expected " + std::to_string(*n + *m + 24) + " fields for " + std::to_string(*n) +
             " beams and " + std::to_string(*m) + " remissions, found " + std::to_string(f.size());
    }
    sensor::LaserScan scan;
    double start_angle, field_of_view, resolution, max_range;
    if (auto problem = Numbers(
            f, {{2, &start_angle}, {3, &field_of_view}, {4, &resolution}, {5, &max_range}})) {
      return problem;
    }
    if (resolution == 0.0) return "expected a nonzero angular_resolution as field 5, found 0";
    if (!(max_range > 0.0)) {
      return "expected a positive maximum_range as field 6, found '" + std::string(f[5]) + "'";
    }
    // Loggers write the field of view as (n - 1) or n resolution steps.
    const double steps = static_cast<double>(*n);
    const double step = std::abs(resolution);
    if (*n > 0 && std::abs(std::abs(field_of_view) - step * (steps - 1.0)) > 0.5 * step &&
        std::abs(std::abs(field_of_view) - step * steps) > 0.5 * step) {
      warnings_.Add("scans whose field of view disagrees with their beams",
                    Where() + ": ROBOTLASER1 field_of_view " + FormatNumber(field_of_view) +
                        " rad is not " + std::to_string(*n) + " (or " + std::to_string(*n - 1) +
                        ") steps of angular_resolution " + FormatNumber(resolution) +
                        " rad; the beams are placed by angular_resolution");
    }
    scan.ranges.resize(*n);
    for (std::size_t k = 0; k < *n; ++k) {
      const std::optional<double> r = ParseNumber(f[9 + k]);
      if (!r)
        return "expected a number as range " + std::to_string(k + 1) + ", found '" +
               std::string(f[9 + k]) + "'";
      scan.ranges[k] = static_cast<float>(*r);
    }
    const std::size_t tail = *n + *m + 10;  // first field after the remissions
    double x, y, theta, time;
    if (auto problem = Numbers(
            f,
            {{tail + 3, &x}, {tail + 4, &y}, {tail + 5, &theta}, {tail + 11, &time, kMaxTimeS}})) {
      return problem;
    }
    scan.time_s = time;
    scan.angle_min_rad = static_cast<float>(start_angle);
    scan.angle_increment_rad = static_cast<float>(resolution);
    scan.range_max_m = static_cast<float>(max_range);
    const geometry::Rigid2d robot_pose(x, y, theta);
    if (AddScan(std::move(scan), robot_pose, robot_pose, "ROBOTLASER1")) {
      ++counts_->robotlaser1;
    }
    return std::nullopt;
  }

  std::optional<std::string> ParseOdom(const std::vector<std::string_view>& f) {
    if (f.size() != 10) {
      return "expected 10 fields (ODOM x y theta tv rv accel ipc_timestamp ipc_hostname "
             "logger_timestamp), found " +
             std::to_string(f.size());
    }
    double x, y, theta, time;
    if (auto problem = Numbers(f, {{1, &x}, {2, &y}, {3, &theta}, {7, &time, kMaxTimeS}})) {
      return problem;
    }
    dataset_->odometry.push_back({time, geometry::Rigid2d(x, y, theta)});
    odometry_lines_.push_back(line_number_);
    ++counts_->odom;
    return std::nullopt;
  }

  // A field to parse: its index, where the number goes, and the largest
  // magnitude it may have (a pose 1e12 m out would make a submap grow without
  // bound; a time of 1e300 s would put every later scan "backwards").
  struct Field {
    std::size_t index;
    double* value;
    double max_magnitude = kMaxInputCoordinateM;  // also angles (rad) and scan parameters
  };

  // Parses the fields at the given indices as finite numbers within their
  // bounds (the ranges are parsed separately because they may be NaN or
  // infinite).
  std::optional<std::string> Numbers(const std::vector<std::string_view>& f,
                                     std::initializer_list<Field> wanted) {
    for (const Field& field : wanted) {
      const std::optional<double> parsed = ParseNumber(f[field.index]);
      if (!parsed || !std::isfinite(*parsed)) {
        return "expected a finite number as field " + std::to_string(field.index + 1) +
               ", found '" + std::string(f[field.index]) + "'";
      }
      if (std::abs(*parsed) > field.max_magnitude) {
        return "expected a number within +-" + FormatNumber(field.max_magnitude) + " as field " +
               std::to_string(field.index + 1) + ", found '" + std::string(f[field.index]) + "'";
      }
      *field.value = *parsed;
    }
    return std::nullopt;
  }

  // Appends 'scan' unless it has no beams (a warning).
  bool AddScan(sensor::LaserScan scan, const geometry::Rigid2d& pose,
               const geometry::Rigid2d& odometry, const char* kind) {
    if (scan.ranges.empty()) {
      ++counts_->zero_beam_scans;
      warnings_.Add("scans without beams",
                    Where() + ": " + kind + " with 0 beams skipped (expected at least one range)");
      return false;
    }
    dataset_->scan_odometry.push_back({scan.time_s, odometry});
    dataset_->scans.push_back(std::move(scan));
    dataset_->scan_poses.push_back(pose);
    scan_lines_.push_back({line_number_, kind});
    return true;
  }

  // Keeps each stream's longest run in time order (see time_order.h).
  void DropOutOfTimeOrder() {
    const std::vector<bool> keep_scan = LongestTimeOrderOf(dataset_->scans);
    for (std::size_t i = 0; i < keep_scan.size(); ++i) {
      if (keep_scan[i]) continue;
      const auto& [line, kind] = scan_lines_[i];
      ++counts_->backwards_scans;
      --(kind == std::string_view("FLASER") ? counts_->flaser : counts_->robotlaser1);
      warnings_.Add("scans out of time order",
                    source_ + ":" + std::to_string(line) + ": " + kind +
                        " at t=" + FormatNumber(dataset_->scans[i].time_s) +
                        " s is out of time order with the scans around it; dropped (expected "
                        "non-decreasing ipc_timestamp)");
    }
    KeepOnly(keep_scan, &dataset_->scans);
    KeepOnly(keep_scan, &dataset_->scan_poses);
    KeepOnly(keep_scan, &dataset_->scan_odometry);
    KeepOnly(keep_scan, &scan_lines_);

    const std::vector<bool> keep_odometry = LongestTimeOrderOf(dataset_->odometry);
    for (std::size_t i = 0; i < keep_odometry.size(); ++i) {
      if (keep_odometry[i]) continue;
      ++counts_->backwards_odometry;
      --counts_->odom;
      warnings_.Add("odometry messages out of time order",
                    source_ + ":" + std::to_string(odometry_lines_[i]) +
                        ": ODOM at t=" + FormatNumber(dataset_->odometry[i].time_s) +
                        " s is out of time order with the messages around it; dropped "
                        "(expected non-decreasing ipc_timestamp)");
    }
    KeepOnly(keep_odometry, &dataset_->odometry);
    KeepOnly(keep_odometry, &odometry_lines_);
  }

  void InferFlaserRangeMax() {
    std::vector<std::size_t> flaser_scans;
    for (std::size_t i = 0; i < scan_lines_.size(); ++i) {
      if (scan_lines_[i].second == std::string_view("FLASER")) flaser_scans.push_back(i);
    }
    float largest = 0.f;
    std::size_t repeats = 0;
    for (const std::size_t i : flaser_scans) {
      for (const float r : dataset_->scans[i].ranges) {
        if (!std::isfinite(r) || r < largest) continue;
        repeats = r == largest ? repeats + 1 : 1;
        largest = r;
      }
    }
    const float range_max =
        repeats >= kMinSaturatedReadings ? kSaturationBand * largest : kSickRangeMaxM;
    for (const std::size_t i : flaser_scans) dataset_->scans[i].range_max_m = range_max;
  }

  void WarnIfTimesCoarse() {
    const std::vector<sensor::LaserScan>& scans = dataset_->scans;
    std::size_t repeated = 0;
    for (std::size_t i = 1; i < scans.size(); ++i)
      repeated += scans[i].time_s == scans[i - 1].time_s;
    if (scans.size() >= 2 && 2 * repeated >= scans.size()) {
      dataset_->warnings.push_back(
          source_ + ": " + std::to_string(repeated) + " of " + std::to_string(scans.size()) +
          " scans have the same ipc_timestamp as the scan before; the log's times are too "
          "coarse (or zero) to match scans with odometry by time");
    }
  }

  std::string source_;
  Dataset* dataset_;
  CarmenLogCounts* counts_;
  DatasetWarnings warnings_;
  std::size_t line_number_ = 0;
  // The line and message kind of each scan, and the line of each odometry
  // message, in the dataset's order.
  std::vector<std::pair<std::size_t, const char*>> scan_lines_;
  std::vector<std::size_t> odometry_lines_;
};

}  // namespace

Dataset ReadCarmenLog(const fs::path& path, CarmenLogCounts* counts) {
  CarmenLogCounts local_counts;
  if (counts == nullptr) counts = &local_counts;
  *counts = CarmenLogCounts();
  Dataset dataset;
  dataset.name = DatasetName(path);
  dataset.format = "carmen";
  CarmenParser parser(path, &dataset, counts);
  LineReader reader(path);
  std::string line;
  while (reader.Next(line)) parser.ParseLine(reader.line_number(), line);
  const std::string source = path.string();
  if (!reader.error().empty()) {
    if (dataset.scans.empty()) {
      throw InputError(source + ": corrupt or truncated gzip data after line " +
                       std::to_string(reader.line_number()) + " (" + reader.error() +
                       ") before any usable scan; expected a complete gzip stream");
    }
    // First: of all the warnings, losing the rest of the log matters most.
    const bool cut = reader.error() == "unexpected end of file";
    dataset.warnings.insert(
        dataset.warnings.begin(),
        source + ": gzip data ends early after line " + std::to_string(reader.line_number()) +
            " (" + reader.error() + "); keeping the " + std::to_string(dataset.scans.size()) +
            " scans read up to there" +
            (cut ? std::string()
                 : " (corrupt data decodes to garbage for a while before zlib notices: "
                   "malformed lines just before it are likely part of the damage)"));
  }
  if (!reader.notice().empty()) {
    dataset.warnings.insert(dataset.warnings.begin(), source + ": " + reader.notice() + " (" +
                                                          std::to_string(reader.line_number()) +
                                                          " lines read)");
  }
  parser.Finish();
  const std::size_t read_scans = dataset.scans.size() + counts->backwards_scans;
  if (!dataset.scans.empty() && 2 * dataset.scans.size() < read_scans) {
    throw InputError(source + ": only " + std::to_string(dataset.scans.size()) + " of " +
                     std::to_string(read_scans) +
                     " scans are in time order; expected non-decreasing ipc_timestamp (are the "
                     "lines reversed, or the times corrupt?)");
  }
  if (dataset.scans.empty()) {
    throw InputError(source + ": no usable laser scan in " + std::to_string(reader.line_number()) +
                     " lines (expected FLASER or ROBOTLASER1 lines of a CARMEN log; " +
                     std::to_string(counts->malformed_lines) + " malformed, " +
                     std::to_string(counts->backwards_scans + counts->zero_beam_scans) +
                     " scans dropped" +
                     (dataset.warnings.empty() ? std::string()
                                               : "; first problem: " + dataset.warnings.front()) +
                     ")");
  }
  return dataset;
}

}  // namespace scout::io
