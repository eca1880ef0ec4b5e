#include "scout/io/config.h"

#include <yaml-cpp/yaml.h>

#include <numbers>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/input_file.h"
#include "scout/io/explore_config.h"
#include "scout/io/slam_config.h"
#include "scout/io/yaml_fields.h"

namespace scout::io {
namespace {

void ReadFrontier(YamlSection s, frontier::FrontierOptions* o) {
  // Wider than a few metres, the inflation is a memory exhaustion, not an option.
  s.ReadNonNegativeAtMost("inflation_radius_m", &o->inflation_radius_m, 5.0);
  s.ReadPositive("epsilon_m", &o->epsilon_m);
  s.ReadPositive("lidar_range_m", &o->lidar_range_m);
  s.ReadPositive("exact_slack_m", &o->exact_slack_m);
  s.ReadBool("defer_grid_changes", &o->defer_grid_changes);
  s.RejectUnknownKeys();
}

void ReadSynthetic(YamlSection s, synthetic::SyntheticStreamOptions* o) {
  s.ReadPositive("resolution_m", &o->resolution_m);
  s.ReadInt("scans_per_submap", &o->scans_per_submap, 1);
  // Spacings below these made tours of billions of scans (bad_alloc).
  s.ReadInRange("scan_spacing_m", &o->scan_spacing_m, 0.01, 100.0, YamlSection::Bound::kInclusive,
                YamlSection::Bound::kInclusive);
  double spacing_deg = o->scan_spacing_rad * 180.0 / std::numbers::pi;
  s.ReadInRange("scan_spacing_deg", &spacing_deg, 0.1, 360.0, YamlSection::Bound::kInclusive,
                YamlSection::Bound::kInclusive);
  o->scan_spacing_rad = spacing_deg * std::numbers::pi / 180.0;
  s.ReadPositive("linear_speed_mps", &o->linear_speed_mps);
  s.ReadPositive("angular_speed_radps", &o->angular_speed_radps);
  s.ReadInt("optimize_every_n_scans", &o->optimize_every_n_scans, 1);
  s.ReadInt("max_scans", &o->max_scans, 0);
  ReadLidarOptions(s.Section("lidar"), &o->lidar);
  {
    YamlSection r = s.Section("range_filter");
    r.ReadNonNegativeAtMost("min_range_m", &o->range_filter.min_range_m, 200.0);
    r.ReadPositive("max_range_m", &o->range_filter.max_range_m);
    r.ReadNonNegative("miss_ray_length_m", &o->range_filter.miss_ray_length_m);
    r.RejectUnknownKeys();
  }
  {
    YamlSection in = s.Section("insertion");
    ReadHitMissProbabilities(in, &o->insertion);
    in.RejectUnknownKeys();
  }
  {
    YamlSection t = s.Section("tour");
    t.ReadPositive("path_clearance_m", &o->tour.path_clearance_m);
    t.ReadPositive("waypoint_clearance_m", &o->tour.waypoint_clearance_m);
    t.ReadInRange("waypoint_spacing_m", &o->tour.waypoint_spacing_m, 0.01, 1000.0,
                  YamlSection::Bound::kInclusive, YamlSection::Bound::kInclusive);
    t.ReadBool("return_to_start", &o->tour.return_to_start);
    t.ReadPositive("max_shortcut_m", &o->tour.max_shortcut_m);
    t.ReadInRange("smoothing_spacing_m", &o->tour.smoothing_spacing_m, 0.01, 1000.0,
                  YamlSection::Bound::kInclusive, YamlSection::Bound::kInclusive);
    t.ReadInt("smoothing_iterations", &o->tour.smoothing_iterations, 0, 1000);
    t.ReadNonNegative("min_pose_clearance_m", &o->tour.min_pose_clearance_m);
    t.RejectUnknownKeys();
  }
  {
    YamlSection c = s.Section("corrections");
    synthetic::CorrectionModelOptions& m = o->corrections;
    // A drift of more than a metre (radian) per square-root metre is no SLAM any more;
    // 1e300 made the corrected poses infinite.
    c.ReadNonNegativeAtMost("drift_translation_m_per_sqrt_m", &m.drift_translation_m_per_sqrt_m,
                            1.0);
    c.ReadNonNegativeAtMost("drift_heading_rad_per_sqrt_m", &m.drift_heading_rad_per_sqrt_m, 1.0);
    c.ReadNonNegativeAtMost("drift_heading_rad_per_sqrt_rad", &m.drift_heading_rad_per_sqrt_rad,
                            1.0);
    c.ReadNonNegative("newest_pull_fraction", &m.newest_pull_fraction);
    c.ReadNonNegative("pull_decay_per_submap", &m.pull_decay_per_submap);
    c.ReadNonNegativeAtMost("newest_jitter_m", &m.newest_jitter_m, 10.0);
    c.ReadNonNegativeAtMost("newest_jitter_rad", &m.newest_jitter_rad, 3.15);
    c.ReadNonNegative("min_nudge_m", &m.min_nudge_m);
    c.ReadNonNegative("min_nudge_rad", &m.min_nudge_rad);
    c.ReadPositive("loop_closure_distance_m", &m.loop_closure_distance_m);
    c.ReadInt("min_loop_closure_age_submaps", &m.min_loop_closure_age_submaps, 1);
    c.ReadNonNegative("min_loop_closure_travel_m", &m.min_loop_closure_travel_m);
    c.ReadNonNegative("loop_closure_error_m", &m.loop_closure_error_m);
    c.ReadNonNegative("loop_closure_error_rad", &m.loop_closure_error_rad);
    c.ReadPositive("loop_closure_sample_spacing_m", &m.loop_closure_sample_spacing_m);
    c.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

}  // namespace

ScoutConfig LoadConfig(const std::filesystem::path& path) {
  RequireRegularFile(path, "an options file (YAML)");
  YAML::Node root;
  try {
    // All documents, so that a second one (after '---') is an error rather
    // than options silently ignored.
    const std::vector<YAML::Node> documents = YAML::LoadAllFromFile(path.string());
    if (documents.size() > 1) {
      throw InputError(path.string() + ": holds " + std::to_string(documents.size()) +
                       " YAML documents (separated by '---'); expected one");
    }
    if (!documents.empty()) root = documents.front();
  } catch (const YAML::BadFile&) {
    throw InputError(path.string() + ": cannot open options file");
  } catch (const YAML::Exception& e) {
    throw InputError(path.string() + ":" + std::to_string(e.mark.line + 1) +
                     ": malformed YAML: " + e.msg);
  }
  ScoutConfig config;
  YamlSection top(root, path.string(), "");
  ReadFrontier(top.Section("frontier"), &config.frontier);
  ReadSynthetic(top.Section("synthetic"), &config.synthetic);
  ReadSlamOptions(top.Section("slam"), &config.slam);
  ReadExploreOptions(top.Section("explore"), &config.explore);
  ReadRobotOptions(top.Section("robot"), &config.robot);
  top.RejectUnknownKeys();
  frontier::Validate(config.frontier);
  try {
    synthetic::Validate(config.synthetic);
  } catch (const InputError& e) {
    throw InputError(path.string() + ": " + e.what());
  }
  try {
    slam::Validate(config.slam);
  } catch (const std::invalid_argument& e) {
    throw InputError(path.string() + ": " + e.what());
  }
  ValidateExploreAndRobot(config.explore, config.robot, path.string());
  return config;
}

}  // namespace scout::io
