#include "scout/report/run_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "scout/common/error.h"
#include "scout/report/csv_table.h"

namespace scout::report {
namespace {

int64_t Count(const CsvTable& table, int row, const std::string& column) {
  const double v = table.Number(row, column);
  if (v < 0 || v != std::floor(v)) {
    throw InputError(table.Where(row) + ": column '" + column + "' is '" + table.Text(row, column) +
                     "', expected a count (integer >= 0)");
  }
  return static_cast<int64_t>(v);
}

nlohmann::json ReadSummary(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open '" + path.string() + "'");
  try {
    nlohmann::json summary = nlohmann::json::parse(in);
    if (!summary.is_object()) throw InputError(path.string() + ": expected a JSON object");
    return summary;
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace

std::vector<FrontierRound> ReadFrontierCsv(const std::filesystem::path& path) {
  const CsvTable table =
      CsvTable::Read(path, {"round", "strategy", "queried_points", "queried_submaps", "time_us",
                            "tp", "fp", "tn", "fn"});
  const bool has_local_points = table.Has("local_points");
  std::vector<FrontierRound> rounds;
  for (int row = 0; row < table.rows(); ++row) {
    FrontierRound r;
    r.round = static_cast<int>(Count(table, row, "round"));
    r.strategy = table.Text(row, "strategy");
    if (r.strategy.empty()) throw InputError(table.Where(row) + ": empty strategy name");
    r.queried_points = Count(table, row, "queried_points");
    r.queried_submaps = Count(table, row, "queried_submaps");
    r.time_us = table.Number(row, "time_us");
    r.tp = Count(table, row, "tp");
    r.fp = Count(table, row, "fp");
    r.tn = Count(table, row, "tn");
    r.fn = Count(table, row, "fn");
    if (has_local_points) r.local_points = Count(table, row, "local_points");
    rounds.push_back(std::move(r));
  }
  return rounds;
}

std::vector<CoverageSample> ReadCoverageCsv(const std::filesystem::path& path) {
  const CsvTable table = CsvTable::Read(path, {"sim_time_s", "path_length_m", "coverage"});
  std::vector<CoverageSample> samples;
  for (int row = 0; row < table.rows(); ++row) {
    CoverageSample s{table.Number(row, "sim_time_s"), table.Number(row, "path_length_m"),
                     table.Number(row, "coverage")};
    if (s.coverage < 0.0 || s.coverage > 1.0 + 1e-9) {
      throw InputError(table.Where(row) + ": coverage '" + table.Text(row, "coverage") +
                       "' is outside 0..1");
    }
    samples.push_back(s);
  }
  return samples;
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
