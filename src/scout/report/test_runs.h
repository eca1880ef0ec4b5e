#ifndef SCOUT_REPORT_TEST_RUNS_H_
#define SCOUT_REPORT_TEST_RUNS_H_

// Test helper: small hand-written output directories.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "scout/common/atomic_file.h"

namespace scout::report::testing {

inline std::filesystem::path TestRoot() {
  return std::filesystem::temp_directory_path() /
         ("scout_report_test_" + std::to_string(::getpid()));
}

// Removes this process's test directories when the test program exits.
inline const struct RemoveTestRoot {
  ~RemoveTestRoot() {
    std::error_code ignored;
    std::filesystem::remove_all(TestRoot(), ignored);
  }
} kRemoveTestRoot;

// A fresh empty directory under the system temp directory.
inline std::filesystem::path FreshDir(const std::string& name) {
  const std::filesystem::path dir = TestRoot() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Three strategies over three rounds; dfd queries 100+120+140 = 360 points,
// direct 10+0+30 = 40 (P = 1 - 40/360 = 88.89 %), direct makes one error.
inline const char* kFrontierCsv =
    "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points\n"
    "0,full,100,4,900,30,0,70,0,100\n"
    "0,dfd,100,4,800,30,0,70,0,100\n"
    "0,direct,10,1,100,30,0,70,0,100\n"
    "1,full,120,5,1000,40,0,80,0,120\n"
    "1,dfd,120,5,900,40,0,80,0,120\n"
    "1,direct,0,0,5,39,0,80,1,120\n"
    "2,full,140,6,1200,50,0,90,0,140\n"
    "2,dfd,140,6,1100,50,0,90,0,140\n"
    "2,direct,30,2,300,50,0,90,0,140\n";

inline const char* kSummaryJson = R"({
  "world": "office", "seed": 7, "optimizations": 3, "epsilon_m": 0.1,
  "local_frontier_points": 140,
  "frontier": {"strategies": {
    "dfd": {"queried_points": 360, "time_ms": 2.8, "accuracy": 1.0, "precision": 1.0,
            "recall": 1.0, "P": 0.0},
    "direct": {"queried_points": 40, "time_ms": 0.405, "accuracy": 0.99722, "precision": 1.0,
               "recall": 0.99167, "P": 0.888889},
    "full": {"queried_points": 360, "time_ms": 3.1, "accuracy": 1.0, "precision": 1.0,
             "recall": 1.0, "P": 0.0}}},
  "config": {"frontier": {"epsilon_m": 0.1, "inflation_radius_m": 0.3}}
})";

// A frontier-bench-like run: summary.json, frontier.csv and a tiny PNG.
inline std::filesystem::path WriteFrontierRun(const std::string& name) {
  const std::filesystem::path dir = FreshDir(name);
  WriteTextFileAtomically(dir / "frontier.csv", kFrontierCsv);
  WriteTextFileAtomically(dir / "summary.json", kSummaryJson);
  // A valid 1x1 grey PNG.
  static const unsigned char kPng[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
      0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9c, 0x63, 0x38, 0x0b, 0x00, 0x00, 0xcf, 0x00, 0xce, 0xa0, 0xfe, 0x29, 0x50, 0x00,
      0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  WriteTextFileAtomically(dir / "frontiers.png",
                          std::string(reinterpret_cast<const char*>(kPng), sizeof(kPng)));
  return dir;
}

// An exploration-like run: summary.json and coverage.csv only.
inline std::filesystem::path WriteExploreRun(const std::string& name, double speed) {
  const std::filesystem::path dir = FreshDir(name);
  std::string csv = "sim_time_s,path_length_m,coverage\n";
  for (int i = 0; i <= 10; ++i) {
    csv += std::to_string(10.0 * i) + "," + std::to_string(speed * 10.0 * i) + "," +
           std::to_string(1.0 - std::pow(0.6, i)) + "\n";
  }
  WriteTextFileAtomically(dir / "coverage.csv", csv);
  WriteTextFileAtomically(
      dir / "summary.json",
      R"({"world": "museum", "seed": 3, "strategy": "exact", "goals_policy": "nearest"})");
  return dir;
}

}  // namespace scout::report::testing

#endif  // SCOUT_REPORT_TEST_RUNS_H_
