#include "scout/io/config.h"

#include <gtest/gtest.h>

#include <random>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

class ConfigTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("scout_config_test_" + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path Write(const std::string& text) {
    const fs::path p = dir_ / "options.yaml";
    WriteTextFileAtomically(p, text);
    return p;
  }
  std::string ErrorOf(const std::string& text) {
    try {
      LoadConfig(Write(text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(ConfigTest, DefaultFileMatchesTheBuiltInDefaults) {
  const ScoutConfig c = LoadConfig(fs::path(SCOUT_SOURCE_DIR) / "config" / "default.yaml");
  const ScoutConfig d;
  EXPECT_DOUBLE_EQ(c.frontier.inflation_radius_m, d.frontier.inflation_radius_m);
  EXPECT_DOUBLE_EQ(c.frontier.epsilon_m, d.frontier.epsilon_m);
  EXPECT_DOUBLE_EQ(c.frontier.exact_slack_m, d.frontier.exact_slack_m);
  EXPECT_EQ(c.synthetic.scans_per_submap, d.synthetic.scans_per_submap);
  EXPECT_NEAR(c.synthetic.scan_spacing_rad, d.synthetic.scan_spacing_rad, 1e-12);
  EXPECT_DOUBLE_EQ(c.synthetic.lidar.range_max_m, d.synthetic.lidar.range_max_m);
  EXPECT_DOUBLE_EQ(c.synthetic.corrections.newest_jitter_m,
                   d.synthetic.corrections.newest_jitter_m);
}

TEST_F(ConfigTest, ValuesOverrideDefaults) {
  const ScoutConfig c =
      LoadConfig(Write("frontier:\n  epsilon_m: 0.2\nsynthetic:\n  lidar:\n    beams: 361\n"));
  EXPECT_DOUBLE_EQ(c.frontier.epsilon_m, 0.2);
  EXPECT_EQ(c.synthetic.lidar.beams, 361);
}

TEST_F(ConfigTest, ErrorsNameTheFileAndKey) {
  std::string e = ErrorOf("frontier:\n  epsilon: 0.1\n");
  EXPECT_NE(e.find("options.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("frontier.epsilon"), std::string::npos) << e;
  e = ErrorOf("frontier:\n  epsilon_m: fast\n");
  EXPECT_NE(e.find("frontier.epsilon_m"), std::string::npos) << e;
  e = ErrorOf("frontier:\n  epsilon_m: -0.1\n");
  EXPECT_NE(e.find("positive"), std::string::npos) << e;
  e = ErrorOf("synthetic:\n  scans_per_submap: 0\n");
  EXPECT_NE(e.find("synthetic.scans_per_submap"), std::string::npos) << e;
  e = ErrorOf("synthetic:\n  lidar:\n    beam: 3\n");
  EXPECT_NE(e.find("synthetic.lidar.beam"), std::string::npos) << e;
  e = ErrorOf("frontier: [1, 2\n");
  EXPECT_NE(e.find("malformed YAML"), std::string::npos) << e;
  e = ErrorOf("frontier: 3\n");
  EXPECT_NE(e.find("expected a mapping"), std::string::npos) << e;
  try {
    LoadConfig(dir_ / "absent.yaml");
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("absent.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace scout::io
