#include "scout/io/config.h"

#include <yaml-cpp/yaml.h>

#include "scout/common/error.h"
#include "scout/io/yaml_fields.h"

namespace scout::io {
namespace {

void ReadFrontier(YamlSection s, frontier::FrontierOptions* o) {
  s.ReadNonNegative("inflation_radius_m", &o->inflation_radius_m);
  s.ReadPositive("epsilon_m", &o->epsilon_m);
  s.ReadPositive("lidar_range_m", &o->lidar_range_m);
  s.ReadPositive("exact_slack_m", &o->exact_slack_m);
  s.RejectUnknownKeys();
}

}  // namespace

ScoutConfig LoadConfig(const std::filesystem::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
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
  top.RejectUnknownKeys();
  frontier::Validate(config.frontier);
  return config;
}

}  // namespace scout::io
