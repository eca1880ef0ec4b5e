#ifndef SCOUT_REPORT_RUN_DATA_H_
#define SCOUT_REPORT_RUN_DATA_H_

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace scout::report {

// One row of frontier.csv: one strategy in one optimisation round.
struct FrontierRound {
  int round = 0;
  std::string strategy;
  int64_t queried_points = 0;
  int64_t queried_submaps = 0;
  double time_us = 0.0;
  int64_t tp = 0, fp = 0, tn = 0, fn = 0;
  // Local frontier points of all submaps at the round; absent in files
  // written before the column existed.
  std::optional<int64_t> local_points;
};

// One row of coverage.csv (exploration runs).
struct CoverageSample {
  double sim_time_s = 0.0;
  double path_length_m = 0.0;
  double coverage = 0.0;  // fraction of the reachable free area, 0..1
};

// One row of navigation_points.csv (replay): where an explorer would go next
// from the run's last pose, best first.
struct NavigationPointRow {
  int rank = 0;
  double x_m = 0.0, y_m = 0.0;
  double path_cost_m = 0.0;
  double info_gain_m2 = 0.0;
  double revenue = 0.0;
};

// One row of goals.csv (exploration runs): a goal the robot was sent to.
struct GoalRow {
  double issued_s = 0.0;
  double robot_x_m = 0.0, robot_y_m = 0.0;
  double goal_x_m = 0.0, goal_y_m = 0.0;
  double score = 0.0;  // NaN when the file has none
  double path_m = 0.0;
  double ended_s = 0.0;  // NaN while open
  std::string outcome;   // reached, seen, failed, ..., open
  bool reachable_in_truth = true;
};

// What a Scout output directory holds, read back from its files. Each part is
// empty when its file is absent.
struct RunData {
  std::string name;  // the directory's name
  std::filesystem::path dir;
  nlohmann::json summary;  // null without summary.json
  std::vector<FrontierRound> rounds;
  std::vector<CoverageSample> coverage;
  std::vector<NavigationPointRow> navigation_points;
  std::vector<GoalRow> goals;
  std::vector<std::filesystem::path> pictures;  // *.png, frontiers.png and map.png first
};

// Reads frontier.csv. Throws InputError naming file:line on a missing file,
// header column or malformed value.
std::vector<FrontierRound> ReadFrontierCsv(const std::filesystem::path& path);

// Reads coverage.csv (sim_time_s,path_length_m,coverage). Throws like
// ReadFrontierCsv.
std::vector<CoverageSample> ReadCoverageCsv(const std::filesystem::path& path);

// Reads navigation_points.csv. Throws like ReadFrontierCsv.
std::vector<NavigationPointRow> ReadNavigationPointsCsv(const std::filesystem::path& path);

// Reads goals.csv. Throws like ReadFrontierCsv, also on an unknown outcome,
// an issue time that falls, an end before the issue, or an end given for an
// open goal (or none for an ended one).
std::vector<GoalRow> ReadGoalsCsv(const std::filesystem::path& path);

// Returns the first sample whose coverage reached 'fraction' (0-1), or null.
const CoverageSample* FirstReaching(const std::vector<CoverageSample>& coverage, double fraction);

// Reads every known output of 'dir'. 'name' defaults to the directory's name.
// Throws InputError when 'dir' is not a directory, holds none of summary.json,
// frontier.csv and coverage.csv, or one of them is malformed.
RunData ReadRun(const std::filesystem::path& dir, const std::string& name = "");

// Returns the name of the run in 'dir': its last path component ("out/a/" and
// "out/a/." give "a").
std::string RunName(const std::filesystem::path& dir);

// Returns the strategies of 'rounds' in order of first appearance.
std::vector<std::string> StrategiesOf(const std::vector<FrontierRound>& rounds);

}  // namespace scout::report

#endif  // SCOUT_REPORT_RUN_DATA_H_
