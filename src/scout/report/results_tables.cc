#include "scout/report/results_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "scout/common/error.h"
#include "scout/report/run_data.h"

namespace scout::report {
namespace {

using Json = nlohmann::json;
using Row = std::vector<std::string>;

constexpr const char* kMissing = "—";

// The number at 'path' (keys separated by '/') in 'j', if there is one.
std::optional<double> Number(const Json& j, const std::string& path) {
  const Json* node = &j;
  std::istringstream keys(path);
  std::string key;
  while (std::getline(keys, key, '/')) {
    if (!node->is_object() || !node->contains(key)) return std::nullopt;
    node = &(*node)[key];
  }
  if (!node->is_number()) return std::nullopt;
  return node->get<double>();
}

std::string Text(const Json& j, const std::string& key) {
  if (!j.is_object() || !j.contains(key)) return kMissing;
  const Json& v = j[key];
  if (v.is_string()) return v.get<std::string>();
  if (v.is_null()) return kMissing;
  return v.dump();
}

std::string Fixed(std::optional<double> v, int decimals) {
  if (!v || !std::isfinite(*v)) return kMissing;
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, *v);
  return buffer;
}

// Integers with thousands separators, as in the README's tables.
std::string Count(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return kMissing;
  const long long n = std::llround(*v);
  std::string digits = std::to_string(n < 0 ? -n : n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, ",");
  return (n < 0 ? "-" : "") + digits;
}

// Fractions as percent; accuracy-like values need 3 decimals to show errors.
std::string Percent(std::optional<double> v, int decimals) {
  if (!v || !std::isfinite(*v)) return kMissing;
  return Fixed(*v * 100.0, decimals) + " %";
}

void AppendTable(const Row& header, const std::vector<Row>& rows, std::ostringstream& out) {
  const auto line = [&out](const Row& cells) {
    out << '|';
    for (const std::string& c : cells) out << ' ' << c << " |";
    out << '\n';
  };
  line(header);
  out << '|';
  for (size_t i = 0; i < header.size(); ++i) out << "---|";
  out << '\n';
  for (const Row& r : rows) line(r);
  out << '\n';
}

std::string CommandOf(const std::filesystem::path& dir) {
  std::ifstream in(dir / "command.txt");
  if (!in) return "(command not recorded) # " + dir.string();
  std::string command;
  std::getline(in, command);
  return command.empty() ? "(command not recorded) # " + dir.string() : command;
}

std::vector<RunData> ReadRuns(const std::vector<std::filesystem::path>& dirs,
                              std::ostringstream& out) {
  if (dirs.empty()) throw InputError("results tables: no output directories given");
  std::vector<RunData> runs;
  out << "```sh\n";
  for (const std::filesystem::path& dir : dirs) {
    if (!std::filesystem::is_regular_file(dir / "summary.json")) {
      throw InputError(dir.string() +
                       ": no summary.json (the run did not finish, or this is "
                       "not a Scout output directory)");
    }
    runs.push_back(ReadRun(dir));
    out << CommandOf(dir) << '\n';
  }
  out << "```\n\n";
  return runs;
}

// Optimisation rounds a strategy took part in: frontier.csv rows, else the
// summary's count.
std::optional<double> Rounds(const RunData& run, const std::string& strategy) {
  int64_t n = 0;
  for (const FrontierRound& r : run.rounds) n += r.strategy == strategy ? 1 : 0;
  if (n > 0 || !run.rounds.empty()) return static_cast<double>(n);
  if (auto v = Number(run.summary, "optimizations")) return v;
  return Number(run.summary, "slam/optimizations");
}

// One row per run and strategy: the paper's figures plus the cost per round.
// P of a run without dfd (null in its summary): dfd would have queried every
// local frontier point of every round, frontier.csv's local_points (their sum
// equals dfd's count in the 350 m museum: 67,752,512,197).
std::optional<double> PAgainstEveryLocalPoint(const RunData& run, const std::string& strategy,
                                              std::optional<double> queried_points) {
  int64_t all_points = 0;
  bool any = false;
  for (const FrontierRound& r : run.rounds) {
    if (r.strategy != strategy) continue;
    if (!r.local_points) return std::nullopt;
    all_points += *r.local_points;
    any = true;
  }
  if (!any || all_points <= 0 || !queried_points) return std::nullopt;
  return 1.0 - *queried_points / static_cast<double>(all_points);
}

void AppendStrategyTable(const std::vector<RunData>& runs, bool with_epsilon,
                         std::ostringstream& out) {
  Row header = {"run",       "strategy", "rounds",      "points re-queried",
                "per round", "P",        "accuracy",    "wrong answers",
                "precision", "recall",   "ms per round"};
  if (with_epsilon) header.insert(header.begin() + 1, "ε m");
  std::vector<Row> rows;
  for (const RunData& run : runs) {
    const Json* strategies = nullptr;
    if (run.summary.contains("frontier") && run.summary["frontier"].contains("strategies")) {
      strategies = &run.summary["frontier"]["strategies"];
    }
    if (strategies == nullptr || !strategies->is_object()) continue;
    // Summary order is alphabetical; the README's order reads better.
    std::vector<std::string> names;
    for (const char* known : {"full", "dfd", "bfs", "direct", "exact"}) {
      if (strategies->contains(known)) names.push_back(known);
    }
    for (const auto& [name, unused] : strategies->items()) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    for (const std::string& name : names) {
      const Json& s = (*strategies)[name];
      const std::optional<double> rounds = Rounds(run, name);
      const auto per_round = [&](const std::string& key) -> std::optional<double> {
        const std::optional<double> total = Number(s, key);
        if (!total || !rounds || *rounds <= 0) return std::nullopt;
        return *total / *rounds;
      };
      std::optional<double> wrong;
      if (auto fp = Number(s, "fp"), fn = Number(s, "fn"); fp && fn) wrong = *fp + *fn;
      std::optional<double> p = Number(s, "P");
      if (!p) p = PAgainstEveryLocalPoint(run, name, Number(s, "queried_points"));
      Row row = {run.name,
                 name,
                 Count(rounds),
                 Count(Number(s, "queried_points")),
                 Count(per_round("queried_points")),
                 Percent(p, 1),
                 Percent(Number(s, "accuracy"), 4),
                 Count(wrong),
                 Percent(Number(s, "precision"), 3),
                 Percent(Number(s, "recall"), 3),
                 Fixed(per_round("time_ms"), 3)};
      if (with_epsilon) row.insert(row.begin() + 1, Fixed(Number(run.summary, "epsilon_m"), 2));
      rows.push_back(row);
    }
  }
  AppendTable(header, rows, out);
}

void AppendReplay(const std::vector<RunData>& runs, std::ostringstream& out) {
  std::vector<Row> rows;
  for (const RunData& run : runs) {
    const Json& s = run.summary;
    // RMSE, and the mean absolute error in brackets (runs before it was
    // recorded show the RMSE only).
    const auto pair = [&](const std::string& interval) {
      const std::string prefix = "reference/rpe_" + interval;
      const std::optional<double> t = Number(s, prefix + "_trans_m"),
                                  r = Number(s, prefix + "_rot_deg");
      if (!t || !r) return std::string(kMissing);
      std::string text = Fixed(t, 3) + " / " + Fixed(r, 2);
      const std::optional<double> tm = Number(s, prefix + "_trans_mean_m"),
                                  rm = Number(s, prefix + "_rot_mean_deg");
      if (tm && rm) text += " (" + Fixed(tm, 3) + " / " + Fixed(rm, 2) + ")";
      return text;
    };
    // Millimetres, the reference's own in brackets (runs before it was measured: a dash).
    const auto consistency = [&](const std::string& prefix) {
      const std::optional<double> e = Number(s, prefix + "estimate_mean_distance_m");
      if (!e) return std::string(kMissing);
      std::string text = Fixed(*e * 1000.0, 1);
      if (const std::optional<double> r = Number(s, prefix + "reference_mean_distance_m")) {
        text += " (" + Fixed(*r * 1000.0, 1) + ")";
      }
      return text;
    };
    rows.push_back({run.name, Text(s, "dataset"), Fixed(Number(s, "odom_noise"), 1),
                    Count(Number(s, "scans")), Fixed(Number(s, "data_duration_s"), 0),
                    Fixed(Number(s, "wall_time_s"), 0), Fixed(Number(s, "realtime_factor"), 2),
                    Fixed(Number(s, "peak_rss_mb"), 0), Count(Number(s, "slam/submaps")),
                    Count(Number(s, "slam/loop_closures")),
                    Count(Number(s, "reference/matched_scans")),
                    Fixed(Number(s, "reference/ate_rmse_m"), 3), pair("1s"), pair("10s"),
                    consistency("consistency/"), consistency("consistency/revisits/")});
  }
  AppendTable({"run", "dataset", "odom noise", "scans", "data s", "wall s", "× real time",
               "peak RSS MiB", "submaps", "loop closures", "matched scans", "ATE RMSE m",
               "RPE 1 s m / ° RMSE (mean)", "RPE 10 s m / ° RMSE (mean)",
               "scan consistency mm (reference)", "revisit consistency mm (reference)"},
              rows, out);
  AppendStrategyTable(runs, /*with_epsilon=*/false, out);
}

void AppendBench(const std::vector<RunData>& runs, std::ostringstream& out) {
  std::vector<Row> rows;
  for (const RunData& run : runs) {
    const Json& s = run.summary;
    std::string size = kMissing;
    if (s.contains("world_size_m") && s["world_size_m"].is_array() &&
        s["world_size_m"].size() == 2) {
      size = Fixed(s["world_size_m"][0].get<double>(), 0) + " × " +
             Fixed(s["world_size_m"][1].get<double>(), 0);
    }
    rows.push_back({run.name, Text(s, "world"), size, Text(s, "seed"),
                    Fixed(Number(s, "epsilon_m"), 2), Count(Number(s, "scans")),
                    Count(Number(s, "submaps")), Count(Number(s, "optimizations")),
                    Count(Number(s, "loop_closures")), Count(Number(s, "local_frontier_points")),
                    Fixed(Number(s, "wall_time_s"), 0)});
  }
  AppendTable({"run", "world", "size m", "seed", "ε m", "scans", "submaps", "optimisations",
               "loop closures", "local frontier points", "wall s"},
              rows, out);
  AppendStrategyTable(runs, /*with_epsilon=*/true, out);
}

// Path length when coverage first reached 'level', from coverage.csv.
std::optional<double> PathToCoverage(const RunData& run, double level) {
  const CoverageSample* c = FirstReaching(run.coverage, level);
  return c ? std::optional<double>(c->path_length_m) : std::nullopt;
}

// Simulated seconds per wall-clock second of the run.
std::optional<double> RealtimeFactor(const Json& summary) {
  const std::optional<double> sim = Number(summary, "sim_time_s");
  const std::optional<double> wall = Number(summary, "wall_time_s");
  if (!sim || !wall || !(*wall > 0.0)) return std::nullopt;
  return *sim / *wall;
}

// (world, goal policy, seed) of an explore run, and its paths to 99 % and 95 %.
using PolicyRun = std::tuple<std::string, std::string, std::string>;
struct PathsToCoverage {
  std::optional<double> path_99, path_95;
};

// Scout's policy against each other policy of the same world, on the seeds
// where both reached the level: means over different sets of seeds (a policy
// that reaches 99 % only on its easy seeds) would favour the one that fails
// more often.
void AppendAgainstBaselines(const std::vector<std::pair<std::string, std::string>>& order,
                            const std::map<PolicyRun, PathsToCoverage>& paths,
                            std::ostringstream& out) {
  constexpr const char* kScout = "scout";
  std::vector<Row> rows;
  for (const auto& [world, policy] : order) {
    if (policy == kScout) continue;
    struct Paired {
      int seeds = 0;
      double scout_m = 0.0, other_m = 0.0;
    };
    Paired at_99, at_95;
    bool scout_ran = false;
    for (const auto& [run, other] : paths) {
      const auto& [w, p, seed] = run;
      if (w != world || p != policy) continue;
      const auto scout = paths.find({world, kScout, seed});
      if (scout == paths.end()) continue;
      scout_ran = true;
      const auto pair = [](Paired& sum, std::optional<double> a, std::optional<double> b) {
        if (!a || !b) return;
        ++sum.seeds, sum.scout_m += *a, sum.other_m += *b;
      };
      pair(at_99, scout->second.path_99, other.path_99);
      pair(at_95, scout->second.path_95, other.path_95);
    }
    if (!scout_ran) continue;
    Row row{world, policy};
    for (const Paired& p : {at_99, at_95}) {
      row.push_back(std::to_string(p.seeds));
      const auto mean = [&](double sum) {
        return p.seeds > 0 ? std::optional<double>(sum / p.seeds) : std::nullopt;
      };
      row.push_back(Fixed(mean(p.scout_m), 0));
      row.push_back(Fixed(mean(p.other_m), 0));
      row.push_back(Fixed(p.seeds > 0 && p.other_m > 0.0
                              ? std::optional<double>(p.scout_m / p.other_m)
                              : std::nullopt,
                          2));
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) return;
  out << "Scout's goal policy against each other policy, on the seeds where both reached the "
         "level (paired by seed; ratio below 1: Scout needed less path):\n\n";
  AppendTable({"world", "other policy", "seeds both 99 %", "Scout path to 99 % m",
               "other path to 99 % m", "Scout / other (99 %)", "seeds both 95 %",
               "Scout path to 95 % m", "other path to 95 % m", "Scout / other (95 %)"},
              rows, out);
}

void AppendExplore(const std::vector<RunData>& runs, std::ostringstream& out) {
  std::vector<Row> rows;
  struct Group {
    int runs = 0, reached = 0, reached_95 = 0;
    double coverage = 0.0, min_coverage = 1.0, path_99 = 0.0, time_99 = 0.0, path_95 = 0.0;
    double unreachable = 0.0, collisions = 0.0;
    int with_ate = 0;
    double ate_sum = 0.0, ate_max = 0.0;
  };
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, Group> groups;
  std::map<PolicyRun, PathsToCoverage> paths;
  for (const RunData& run : runs) {
    const Json& s = run.summary;
    const std::optional<double> path_99 = PathToCoverage(run, 0.99);
    const std::optional<double> time_99 = Number(s, "time_to_coverage_s/0.99");
    // Where map error keeps coverage below 99 % (a wall drawn a few cm off
    // leaves cells along it unmatched), 95 % still compares the policies.
    const std::optional<double> path_95 = PathToCoverage(run, 0.95);
    rows.push_back({run.name, Text(s, "world"), Text(s, "goals_policy"), Text(s, "seed"),
                    Text(s, "terminated"), Percent(Number(s, "coverage"), 1),
                    Fixed(Number(s, "path_length_m"), 0), Fixed(path_99, 0),
                    Fixed(Number(s, "sim_time_s"), 0), Fixed(time_99, 0),
                    Count(Number(s, "goals/issued")), Count(Number(s, "goals/reached")),
                    Count(Number(s, "goals/unreachable")), Count(Number(s, "collisions")),
                    Fixed(Number(s, "ate_rmse_m"), 3), Fixed(Number(s, "wall_time_s"), 0),
                    Fixed(RealtimeFactor(s), 1)});
    const std::pair<std::string, std::string> key{Text(s, "world"), Text(s, "goals_policy")};
    paths[{key.first, key.second, Text(s, "seed")}] = {path_99, path_95};
    if (!groups.count(key)) order.push_back(key);
    Group& g = groups[key];
    const double coverage = Number(s, "coverage").value_or(0.0);
    ++g.runs;
    g.coverage += coverage;
    g.min_coverage = std::min(g.min_coverage, coverage);
    g.unreachable += Number(s, "goals/unreachable").value_or(0.0);
    g.collisions += Number(s, "collisions").value_or(0.0);
    if (const std::optional<double> ate = Number(s, "ate_rmse_m")) {
      ++g.with_ate;
      g.ate_sum += *ate;
      g.ate_max = std::max(g.ate_max, *ate);
    }
    if (path_99 && time_99) {
      ++g.reached;
      g.path_99 += *path_99;
      g.time_99 += *time_99;
    }
    if (path_95) {
      ++g.reached_95;
      g.path_95 += *path_95;
    }
  }
  AppendTable({"run", "world", "goal policy", "seed", "ended by", "coverage", "path m",
               "path to 99 % m", "sim s", "sim s to 99 %", "goals", "reached", "unreachable",
               "collisions", "ATE m", "wall s", "× real time"},
              rows, out);
  std::vector<Row> means;
  for (const auto& key : order) {
    const Group& g = groups[key];
    const auto mean_over = [](double sum, int n) -> std::optional<double> {
      return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
    };
    const auto of_runs = [&](int n) { return std::to_string(n) + " of " + std::to_string(g.runs); };
    means.push_back(
        {key.first, key.second, std::to_string(g.runs), Percent(g.coverage / g.runs, 1),
         Percent(g.min_coverage, 1), of_runs(g.reached), Fixed(mean_over(g.path_99, g.reached), 0),
         Fixed(mean_over(g.time_99, g.reached), 0), of_runs(g.reached_95),
         Fixed(mean_over(g.path_95, g.reached_95), 0), Count(g.unreachable), Count(g.collisions),
         Fixed(g.with_ate > 0 ? std::optional<double>(g.ate_sum / g.with_ate) : std::nullopt, 3),
         Fixed(g.with_ate > 0 ? std::optional<double>(g.ate_max) : std::nullopt, 3)});
  }
  AppendTable({"world", "goal policy", "runs", "mean coverage", "min coverage", "reached 99 %",
               "mean path to 99 % m", "mean sim s to 99 %", "reached 95 %", "mean path to 95 % m",
               "unreachable goals", "collisions", "mean ATE m", "max ATE m"},
              means, out);
  AppendAgainstBaselines(order, paths, out);
}

}  // namespace

TableKind ParseTableKind(const std::string& text) {
  if (text == "replay") return TableKind::kReplay;
  if (text == "bench") return TableKind::kBench;
  if (text == "explore") return TableKind::kExplore;
  throw InputError("table kind '" + text + "': expected replay, bench or explore");
}

namespace {

// The command that wrote a run, told by its summary's keys; nullptr if none
// fits. A table of the wrong kind would show blanks and zeros, not an error.
const char* CommandOfSummary(const nlohmann::json& summary) {
  if (summary.contains("terminated") && summary.contains("goals_policy")) return "explore";
  if (summary.contains("dataset")) return "replay";
  if (summary.contains("world") && summary.contains("epsilon_m")) return "frontier-bench";
  return nullptr;
}

}  // namespace

std::string ResultsTables(TableKind kind, const std::vector<std::filesystem::path>& dirs) {
  std::ostringstream out;
  const std::vector<RunData> runs = ReadRuns(dirs, out);
  const char* wanted = kind == TableKind::kReplay  ? "replay"
                       : kind == TableKind::kBench ? "frontier-bench"
                                                   : "explore";
  for (const RunData& run : runs) {
    // A summary that fits no command (written by hand) is taken as it is.
    const char* command = CommandOfSummary(run.summary);
    if (command != nullptr && std::string(command) != wanted) {
      throw InputError((run.dir / "summary.json").string() + ": a run of `scout " +
                       std::string(command) + "`; expected runs of `scout " + wanted +
                       "` for these tables");
    }
  }
  switch (kind) {
    case TableKind::kReplay:
      AppendReplay(runs, out);
      break;
    case TableKind::kBench:
      AppendBench(runs, out);
      break;
    case TableKind::kExplore:
      AppendExplore(runs, out);
      break;
  }
  return out.str();
}

}  // namespace scout::report
