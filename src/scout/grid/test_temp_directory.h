#ifndef SCOUT_GRID_TEST_TEMP_DIRECTORY_H_
#define SCOUT_GRID_TEST_TEMP_DIRECTORY_H_

// Test-only helper (included by the grid tests, not by the library).

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace scout::grid {

// A fresh directory under the system temp directory, removed with its
// contents on destruction. The name mixes pid and randomness because CTest runs
// every test case as its own process, possibly in parallel.
class TestTempDirectory {
 public:
  TestTempDirectory() {
    std::random_device random;
    for (int attempt = 0;; ++attempt) {
      path_ = std::filesystem::temp_directory_path() /
              ("scout_grid_test_" + std::to_string(::getpid()) + "_" + std::to_string(random()));
      if (std::filesystem::create_directory(path_) || attempt > 100) break;
    }
  }
  ~TestTempDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TestTempDirectory(const TestTempDirectory&) = delete;
  TestTempDirectory& operator=(const TestTempDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Writes 'content' (bytes) to 'name' inside the directory and returns its path.
  std::filesystem::path Write(const std::string& name, const std::string& content) const {
    const std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_TEST_TEMP_DIRECTORY_H_
