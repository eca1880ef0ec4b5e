#include "scout/report/run_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/common/input_file.h"
#include "scout/report/csv_reader.h"

namespace scout::report {
namespace {

int64_t Count(const CsvReader& csv, int column) {
  const double v = csv.Number(column);
  // Beyond 2^53 a double no longer counts in ones (and 1e23 would not fit int64_t).
  if (v < 0 || v != std::floor(v) || v > 9007199254740992.0) {
    throw InputError(csv.Where() + ": column '" + csv.Name(column) + "' is '" +
                     std::string(csv.Text(column)) + "', expected a count (integer >= 0)");
  }
  return static_cast<int64_t>(v);
}

// The numbers the tables, reports and figures read from a summary ('*' = every
// member). Each may be absent or null (not measured); anything else there is an
// error, so a damaged file is named instead of showing as a blank or a zero.
constexpr const char* kSummaryNumbers[] = {"seed",
                                           "scans",
                                           "submaps",
                                           "optimizations",
                                           "loop_closures",
                                           "local_frontier_points",
                                           "epsilon_m",
                                           "wall_time_s",
                                           "sim_time_s",
                                           "data_duration_s",
                                           "realtime_factor",
                                           "peak_rss_mb",
                                           "odom_noise",
                                           "coverage",
                                           "mapped_free_m2",
                                           "reachable_free_m2",
                                           "path_length_m",
                                           "collisions",
                                           "ate_rmse_m",
                                           "goals/*",
                                           "time_to_coverage_s/*",
                                           "slam/nodes",
                                           "slam/submaps",
                                           "slam/optimizations",
                                           "slam/loop_closures",
                                           "reference/matched_scans",
                                           "reference/reference_scans",
                                           "reference/ate_rmse_m",
                                           "reference/ate_max_m",
                                           "reference/rpe_1s_trans_m",
                                           "reference/rpe_1s_rot_deg",
                                           "reference/rpe_10s_trans_m",
                                           "reference/rpe_10s_rot_deg",
                                           "reference/rpe_1s_trans_mean_m",
                                           "reference/rpe_1s_rot_mean_deg",
                                           "reference/rpe_10s_trans_mean_m",
                                           "reference/rpe_10s_rot_mean_deg",
                                           "consistency/previous_scans",
                                           "consistency/max_distance_m",
                                           "consistency/scans",
                                           "consistency/estimate_mean_distance_m",
                                           "consistency/reference_mean_distance_m",
                                           "consistency/revisits/*",
                                           "frontier/strategies/*/*"};

// A value as it stands in the file, cut short: a message must not print
// a hundred kilobytes of brackets.
std::string Excerpt(const nlohmann::json& node) {
  std::string text = node.dump();
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

// Summaries Scout writes nest four levels deep; printing or walking a value
// nested 100,000 deep overflowed the stack.
constexpr size_t kMaxSummaryDepth = 32;

// Returns how deep 'root' nests, looking no deeper than 'limit' + 1 (an
// explicit stack: recursion is what a deep file would break).
size_t Depth(const nlohmann::json& root, size_t limit) {
  std::vector<std::pair<const nlohmann::json*, size_t>> stack = {{&root, 1}};
  size_t deepest = 0;
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    if (depth > limit || !node->is_structured()) continue;
    for (const nlohmann::json& child : *node) stack.push_back({&child, depth + 1});
  }
  return deepest;
}

// Checks 'node' against the path segments from 'at' on; 'where' names the
// keys walked so far.
void CheckNumbers(const nlohmann::json& node, const std::vector<std::string>& segments, size_t at,
                  const std::string& where, const std::filesystem::path& path) {
  if (at == segments.size()) {
    if (node.is_null()) return;
    if (!node.is_number()) {
      throw InputError(path.string() + ": key '" + where + "' is " + Excerpt(node) +
                       ", expected a number");
    }
    // Counts, times, sizes and errors alike: none of them is negative.
    if (node.get<double>() < 0.0) {
      throw InputError(path.string() + ": key '" + where + "' is " + Excerpt(node) +
                       ", expected a number >= 0");
    }
    return;
  }
  if (node.is_null()) return;
  // frontier-bench writes "reference": false when it ran no reference.
  if (where == "reference" && node.is_boolean()) return;
  if (!node.is_object()) {
    throw InputError(path.string() + ": key '" + where + "' is " + Excerpt(node) +
                     ", expected an object");
  }
  const std::string& key = segments[at];
  const auto child = [&](const std::string& name) {
    return where.empty() ? name : where + "/" + name;
  };
  if (key == "*") {
    for (const auto& [name, value] : node.items()) {
      CheckNumbers(value, segments, at + 1, child(name), path);
    }
  } else if (node.contains(key)) {
    CheckNumbers(node[key], segments, at + 1, child(key), path);
  }
}

nlohmann::json ReadSummary(const std::filesystem::path& path) {
  RequireRegularFile(path, "a run's summary.json");
  std::ifstream in(path);
  if (!in) throw InputError("cannot open '" + path.string() + "'");
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for numbers such as 1e999.
    throw InputError(path.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!summary.is_object()) throw InputError(path.string() + ": expected a JSON object");
  if (Depth(summary, kMaxSummaryDepth) > kMaxSummaryDepth) {
    throw InputError(path.string() + ": values nested more than " +
                     std::to_string(kMaxSummaryDepth) + " levels deep; expected a Scout summary");
  }
  for (const char* pattern : kSummaryNumbers) {
    std::vector<std::string> segments;
    std::string text = pattern;
    for (size_t start = 0;;) {
      const size_t slash = text.find('/', start);
      segments.push_back(text.substr(start, slash - start));
      if (slash == std::string::npos) break;
      start = slash + 1;
    }
    CheckNumbers(summary, segments, 0, "", path);
  }
  return summary;
}

}  // namespace

const CoverageSample* FirstReaching(const std::vector<CoverageSample>& coverage, double fraction) {
  for (const CoverageSample& c : coverage) {
    if (c.coverage >= fraction) return &c;
  }
  return nullptr;
}

std::vector<FrontierRound> ReadFrontierCsv(const std::filesystem::path& path) {
  CsvReader csv(path, {"round", "strategy", "queried_points", "queried_submaps", "time_us", "tp",
                       "fp", "tn", "fn"});
  const int round = csv.Column("round"), strategy = csv.Column("strategy"),
            queried_points = csv.Column("queried_points"),
            queried_submaps = csv.Column("queried_submaps"), time_us = csv.Column("time_us"),
            tp = csv.Column("tp"), fp = csv.Column("fp"), tn = csv.Column("tn"),
            fn = csv.Column("fn");
  const int local_points = csv.Has("local_points") ? csv.Column("local_points") : -1;
  std::vector<FrontierRound> rounds;
  while (csv.Next()) {
    FrontierRound r;
    r.round = static_cast<int>(Count(csv, round));
    const std::string_view name = csv.Text(strategy);
    if (name.empty()) throw InputError(csv.Where() + ": empty strategy name");
    r.strategy = name;
    r.queried_points = Count(csv, queried_points);
    r.queried_submaps = Count(csv, queried_submaps);
    r.time_us = csv.Number(time_us);
    if (!(r.time_us >= 0.0)) {
      throw InputError(csv.Where() + ": column 'time_us' is '" + std::string(csv.Text(time_us)) +
                       "', expected a time >= 0");
    }
    r.tp = Count(csv, tp);
    r.fp = Count(csv, fp);
    r.tn = Count(csv, tn);
    r.fn = Count(csv, fn);
    if (local_points >= 0) r.local_points = Count(csv, local_points);
    rounds.push_back(std::move(r));
  }
  return rounds;
}

std::vector<CoverageSample> ReadCoverageCsv(const std::filesystem::path& path) {
  CsvReader csv(path, {"sim_time_s", "path_length_m", "coverage"});
  const int sim_time = csv.Column("sim_time_s"), path_length = csv.Column("path_length_m"),
            coverage = csv.Column("coverage");
  std::vector<CoverageSample> samples;
  while (csv.Next()) {
    CoverageSample s{csv.Number(sim_time), csv.Number(path_length), csv.Number(coverage)};
    if (s.coverage < 0.0 || s.coverage > 1.0 + 1e-9) {
      throw InputError(csv.Where() + ": coverage '" + std::string(csv.Text(coverage)) +
                       "' is outside 0..1");
    }
    // The figures plot coverage against time and path: both only grow.
    for (const auto& [column, value, before] :
         {std::tuple{sim_time, s.sim_time_s,
                     samples.empty() ? s.sim_time_s : samples.back().sim_time_s},
          std::tuple{path_length, s.path_length_m,
                     samples.empty() ? s.path_length_m : samples.back().path_length_m}}) {
      if (value < before) {
        throw InputError(csv.Where() + ": " + csv.Name(column) + " '" +
                         std::string(csv.Text(column)) + "' falls below the row before's (" +
                         FormatNumber(before) + "); expected it never to fall");
      }
    }
    samples.push_back(s);
  }
  return samples;
}

std::vector<NavigationPointRow> ReadNavigationPointsCsv(const std::filesystem::path& path) {
  CsvReader csv(path, {"rank", "x_m", "y_m", "path_cost_m", "info_gain_m2", "revenue"});
  const int rank = csv.Column("rank"), x = csv.Column("x_m"), y = csv.Column("y_m"),
            cost = csv.Column("path_cost_m"), gain = csv.Column("info_gain_m2"),
            revenue = csv.Column("revenue");
  std::vector<NavigationPointRow> rows;
  while (csv.Next()) {
    NavigationPointRow r;
    r.rank = static_cast<int>(Count(csv, rank));
    if (r.rank != static_cast<int>(rows.size()) + 1) {
      throw InputError(csv.Where() + ": rank '" + std::string(csv.Text(rank)) + "', expected " +
                       std::to_string(rows.size() + 1) + " (ranks count up from 1)");
    }
    r.x_m = csv.Number(x);
    r.y_m = csv.Number(y);
    r.path_cost_m = csv.Number(cost);
    r.info_gain_m2 = csv.Number(gain);
    r.revenue = csv.Number(revenue);
    rows.push_back(r);
  }
  return rows;
}

std::vector<GoalRow> ReadGoalsCsv(const std::filesystem::path& path) {
  CsvReader csv(path, {"issued_s", "robot_x", "robot_y", "goal_x", "goal_y", "score", "path_m",
                       "ended_s", "outcome", "reachable_in_truth"});
  const int issued = csv.Column("issued_s"), rx = csv.Column("robot_x"), ry = csv.Column("robot_y"),
            gx = csv.Column("goal_x"), gy = csv.Column("goal_y"), score = csv.Column("score"),
            path_m = csv.Column("path_m"), ended = csv.Column("ended_s"),
            outcome = csv.Column("outcome"), reachable = csv.Column("reachable_in_truth");
  // The names explore::ToString(GoalOutcome) writes; this module reads only
  // the files, never the module that wrote them.
  static const std::vector<std::string_view> kOutcomes = {"open",    "reached",     "seen",
                                                          "failed",  "unreachable", "superseded",
                                                          "dropped", "stuck",       "stopped"};
  std::string expected;
  for (const std::string_view o : kOutcomes)
    expected += (expected.empty() ? "" : ", ") + std::string(o);
  std::vector<GoalRow> rows;
  while (csv.Next()) {
    GoalRow r;
    r.issued_s = csv.Number(issued);
    if (!rows.empty() && r.issued_s < rows.back().issued_s) {
      throw InputError(csv.Where() + ": issued_s '" + std::string(csv.Text(issued)) +
                       "' falls below the row before's; expected goals in order of issue");
    }
    r.robot_x_m = csv.Number(rx);
    r.robot_y_m = csv.Number(ry);
    r.goal_x_m = csv.Number(gx);
    r.goal_y_m = csv.Number(gy);
    r.score = csv.Text(score).empty() ? std::nan("") : csv.Number(score);
    r.path_m = csv.Number(path_m);
    r.outcome = std::string(csv.Text(outcome));
    if (std::find(kOutcomes.begin(), kOutcomes.end(), r.outcome) == kOutcomes.end()) {
      throw InputError(csv.Where() + ": outcome '" + r.outcome + "', expected one of " + expected);
    }
    const bool open = r.outcome == "open";
    if (open != csv.Text(ended).empty()) {
      throw InputError(csv.Where() + ": ended_s '" + std::string(csv.Text(ended)) +
                       "' for outcome '" + r.outcome +
                       "'; expected it empty exactly for an open goal");
    }
    r.ended_s = open ? std::nan("") : csv.Number(ended);
    if (!open && r.ended_s < r.issued_s) {
      throw InputError(csv.Where() + ": ended_s '" + std::string(csv.Text(ended)) +
                       "' before issued_s; expected a goal to end after it was issued");
    }
    const std::string_view flag = csv.Text(reachable);
    if (flag != "0" && flag != "1") {
      throw InputError(csv.Where() + ": reachable_in_truth '" + std::string(flag) +
                       "', expected 0 or 1");
    }
    r.reachable_in_truth = flag == "1";
    rows.push_back(r);
  }
  return rows;
}

RunData ReadRun(const std::filesystem::path& dir, const std::string& name) {
  if (!std::filesystem::is_directory(dir)) {
    throw InputError("'" + dir.string() + "' is not a directory");
  }
  RunData run;
  run.dir = dir;
  run.name = name;
  if (run.name.empty()) run.name = RunName(dir);
  const bool has_summary = std::filesystem::exists(dir / "summary.json");
  const bool has_frontier = std::filesystem::exists(dir / "frontier.csv");
  const bool has_coverage = std::filesystem::exists(dir / "coverage.csv");
  if (!has_summary && !has_frontier && !has_coverage) {
    throw InputError("'" + dir.string() +
                     "' holds no Scout outputs (summary.json, frontier.csv or coverage.csv)");
  }
  if (has_summary) run.summary = ReadSummary(dir / "summary.json");
  if (has_frontier) run.rounds = ReadFrontierCsv(dir / "frontier.csv");
  if (has_coverage) run.coverage = ReadCoverageCsv(dir / "coverage.csv");
  if (std::filesystem::exists(dir / "navigation_points.csv")) {
    run.navigation_points = ReadNavigationPointsCsv(dir / "navigation_points.csv");
  }
  if (std::filesystem::exists(dir / "goals.csv")) run.goals = ReadGoalsCsv(dir / "goals.csv");
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".png") {
      run.pictures.push_back(entry.path());
    }
  }
  // The maps the commands write come first, the rest by name.
  const auto rank = [](const std::filesystem::path& p) {
    const std::string f = p.filename().string();
    return std::make_pair(f == "frontiers.png" ? 0 : f == "map.png" ? 1 : 2, f);
  };
  std::sort(run.pictures.begin(), run.pictures.end(),
            [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
  return run;
}

std::string RunName(const std::filesystem::path& dir) {
  // "out/office/" has an empty filename; normalising drops it (and "/.").
  std::filesystem::path p = std::filesystem::absolute(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().string();
}

std::vector<std::string> StrategiesOf(const std::vector<FrontierRound>& rounds) {
  std::vector<std::string> names;
  for (const FrontierRound& r : rounds) {
    if (std::find(names.begin(), names.end(), r.strategy) == names.end()) {
      names.push_back(r.strategy);
    }
  }
  return names;
}

}  // namespace scout::report
