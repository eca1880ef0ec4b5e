#ifndef SCOUT_IO_OPTIONS_FILE_TEST_FIXTURE_H_
#define SCOUT_IO_OPTIONS_FILE_TEST_FIXTURE_H_

// Test-only: writes options files into a fresh temporary directory and loads
// them with LoadConfig.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/io/config.h"

namespace scout::io::testing {

class OptionsFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() / ("scout_options_test_" + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // Writes 'text' as options.yaml and returns its path.
  std::filesystem::path Write(const std::string& text) {
    const std::filesystem::path p = dir_ / "options.yaml";
    WriteTextFileAtomically(p, text);
    return p;
  }
  ScoutConfig Load(const std::string& text) { return LoadConfig(Write(text)); }
  // Returns the InputError message loading 'text' gives, or "" if it loads.
  std::string ErrorOf(const std::string& text) {
    try {
      Load(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  // Expects loading each options text to fail with a message holding its
  // paired text.
  void ExpectErrors(const std::vector<std::pair<std::string, std::string>>& text_and_message) {
    for (const auto& [text, message] : text_and_message) {
      const std::string e = ErrorOf(text);
      EXPECT_NE(e.find(message), std::string::npos) << text << ": " << e;
    }
  }

  std::filesystem::path dir_;
};

}  // namespace scout::io::testing

#endif  // SCOUT_IO_OPTIONS_FILE_TEST_FIXTURE_H_
