#include "scout/report/compare.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "scout/common/error.h"
#include "scout/report/coverage_curves.h"
#include "scout/report/strategy_stats.h"
#include "scout/report/svg_plot.h"

namespace scout::report {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// Strategies of all runs, in order of first appearance; "full" is the
// reference every other strategy is scored against, so it is left out.
std::vector<std::string> ScoredStrategies(const std::vector<std::vector<StrategyStats>>& stats) {
  std::vector<std::string> names;
  for (const auto& run : stats) {
    for (const StrategyStats& s : run) {
      if (s.strategy != "full" &&
          std::find(names.begin(), names.end(), s.strategy) == names.end()) {
        names.push_back(s.strategy);
      }
    }
  }
  return names;
}

const StrategyStats* Find(const std::vector<StrategyStats>& stats, const std::string& name) {
  for (const StrategyStats& s : stats) {
    if (s.strategy == name) return &s;
  }
  return nullptr;
}

// The first of 'keys' the summary holds, as text ("–" when none).
std::string FirstOf(const RunData& run, const std::vector<std::string>& keys) {
  for (const std::string& k : keys) {
    if (run.summary.is_object() && run.summary.contains(k)) return JsonText(run.summary[k]);
  }
  return "–";
}

std::string TimeToCoverage(const RunData& run, double fraction) {
  const CoverageSample* c = FirstReaching(run.coverage, fraction);
  return c ? FormatNumber("%.1f", c->sim_time_s) : "–";
}

// The path driven when coverage first reached 'fraction' (issue 4's measure).
std::string PathToCoverageText(const RunData& run, double fraction) {
  const CoverageSample* c = FirstReaching(run.coverage, fraction);
  return c ? FormatNumber("%.1f", c->path_length_m) : "–";
}

}  // namespace

std::vector<Figure> ComparisonFigures(const std::vector<RunData>& runs) {
  std::vector<std::vector<StrategyStats>> stats;
  for (const RunData& run : runs) stats.push_back(StrategyStatsOf(run));
  std::vector<Figure> figures;
  const std::vector<std::string> strategies = ScoredStrategies(stats);
  const auto bars = [&](const std::string& name, const std::string& title,
                        const std::string& y_label, bool zoom, const char* format,
                        const std::function<double(const StrategyStats&)>& value) {
    BarChart chart;
    chart.title = title;
    chart.y_label = y_label;
    chart.zoom = zoom;
    chart.value_format = format;
    chart.categories = strategies;
    for (size_t r = 0; r < runs.size(); ++r) {
      BarSeries series{runs[r].name, {}};
      for (const std::string& s : strategies) {
        const StrategyStats* found = Find(stats[r], s);
        series.values.push_back(found ? value(*found) : kNoValue);
      }
      chart.series.push_back(std::move(series));
    }
    // A measure no run reports (accuracy of runs without the reference) is no figure.
    const bool any = std::any_of(chart.series.begin(), chart.series.end(), [](const BarSeries& b) {
      return std::any_of(b.values.begin(), b.values.end(), [](double v) { return !std::isnan(v); });
    });
    if (any) figures.push_back({name, title + ", one bar per run.", RenderBarChart(chart)});
  };
  if (!strategies.empty()) {
    bars("compare_p", "Performance P per strategy", "P (% fewer points than dfd)", false, "%.1f",
         [](const StrategyStats& s) { return 100.0 * s.performance_p; });
    bars("compare_accuracy", "Accuracy against full per strategy", "accuracy (%)", true, "auto",
         [](const StrategyStats& s) { return 100.0 * s.accuracy; });
    bars("compare_time", "Update time per optimisation round", "time per round (ms)", false, "%.2f",
         [](const StrategyStats& s) { return s.time_per_round_ms; });
  }
  const CoverageLines lines = CoverageLinesOf(runs);
  if (!lines.over_path.empty()) {
    LineChart path, time;
    path.title = "Coverage over path length";
    path.x_label = "path length (m)";
    time.title = "Coverage over simulated time";
    time.x_label = "simulated time (s)";
    path.y_label = time.y_label = "coverage (% of reachable free area)";
    path.series = lines.over_path;
    time.series = lines.over_time;
    const std::string per = lines.grouped
                                ? ", one line per world and goal policy (the mean over its seeds)."
                                : ", one line per run.";
    figures.push_back(
        {"compare_coverage_path", "Coverage over path length" + per, RenderLineChart(path)});
    figures.push_back(
        {"compare_coverage_time", "Coverage over simulated time" + per, RenderLineChart(time)});
  }
  return figures;
}

std::string RenderComparison(const std::vector<RunData>& runs, const std::vector<Figure>& figures) {
  std::vector<std::string> header = {""};
  std::vector<std::vector<StrategyStats>> stats;
  for (const RunData& run : runs) {
    header.push_back(run.name);
    stats.push_back(StrategyStatsOf(run));
  }
  std::vector<std::vector<std::string>> rows;
  const auto row = [&](const std::string& label, const std::function<std::string(size_t)>& cell) {
    std::vector<std::string> r = {label};
    for (size_t i = 0; i < runs.size(); ++i) r.push_back(cell(i));
    rows.push_back(std::move(r));
  };
  row("world / dataset", [&](size_t i) { return FirstOf(runs[i], {"world", "dataset"}); });
  row("seed", [&](size_t i) { return FirstOf(runs[i], {"seed"}); });
  row("strategy / goal policy", [&](size_t i) {
    // scout explore writes both: the frontier strategy and the goal policy.
    const std::string goals = FirstOf(runs[i], {"goals_policy"});
    if (goals != "–") return FirstOf(runs[i], {"strategy"}) + " / " + goals;
    std::string policy = FirstOf(runs[i], {"goal_policy", "policy", "strategy"});
    if (policy != "–" || stats[i].empty()) return policy;
    std::string names;
    for (const StrategyStats& s : stats[i]) names += (names.empty() ? "" : ", ") + s.strategy;
    return names;
  });
  // Every other top-level scalar any run reports, in order of first appearance.
  std::vector<std::string> keys;
  for (const RunData& run : runs) {
    if (!run.summary.is_object()) continue;
    for (const auto& [k, v] : run.summary.items()) {
      const bool shown = k == "world" || k == "dataset" || k == "seed" || k == "goal_policy" ||
                         k == "goals_policy" || k == "policy" || k == "strategy";
      if (v.is_primitive() && !shown && std::find(keys.begin(), keys.end(), k) == keys.end()) {
        keys.push_back(k);
      }
    }
  }
  for (const std::string& k : keys) row(k, [&](size_t i) { return FirstOf(runs[i], {k}); });
  for (const std::string& s : ScoredStrategies(stats)) {
    const auto metric = [&](const std::string& label, const char* format,
                            double (*value)(const StrategyStats&)) {
      row(label + " (" + s + ")", [&](size_t i) {
        const StrategyStats* found = Find(stats[i], s);
        return found ? FormatNumber(format, value(*found)) : "–";
      });
    };
    metric("P (%)", "%.2f", [](const StrategyStats& x) { return 100.0 * x.performance_p; });
    metric("accuracy (%)", "%.3f", [](const StrategyStats& x) { return 100.0 * x.accuracy; });
    metric("precision (%)", "%.3f", [](const StrategyStats& x) { return 100.0 * x.precision; });
    metric("recall (%)", "%.3f", [](const StrategyStats& x) { return 100.0 * x.recall; });
    metric("time per round (ms)", "%.3f",
           [](const StrategyStats& x) { return x.time_per_round_ms; });
  }
  if (std::any_of(runs.begin(), runs.end(), [](const RunData& r) { return !r.coverage.empty(); })) {
    const auto last = [&](size_t i, double (*value)(const CoverageSample&), const char* format) {
      return runs[i].coverage.empty() ? std::string("–")
                                      : FormatNumber(format, value(runs[i].coverage.back()));
    };
    row("final coverage (%)", [&](size_t i) {
      return last(
          i, [](const CoverageSample& c) { return 100.0 * c.coverage; }, "%.2f");
    });
    row("path length (m)", [&](size_t i) {
      return last(
          i, [](const CoverageSample& c) { return c.path_length_m; }, "%.1f");
    });
    row("time to 90 % coverage (s)", [&](size_t i) { return TimeToCoverage(runs[i], 0.9); });
    row("time to 99 % coverage (s)", [&](size_t i) { return TimeToCoverage(runs[i], 0.99); });
    row("path to 95 % coverage (m)", [&](size_t i) { return PathToCoverageText(runs[i], 0.95); });
    row("path to 99 % coverage (m)", [&](size_t i) { return PathToCoverageText(runs[i], 0.99); });
  }
  std::ostringstream body;
  body << "<h2 id=\"runs\">Runs side by side</h2>\n" << HtmlTable(header, rows);
  if (!figures.empty()) body << "<h2 id=\"figures\">Figures</h2>\n";
  for (const Figure& f : figures) {
    body << "<figure id=\"fig-" << EscapeXml(f.name) << "\">\n"
         << f.svg << "<figcaption>" << EscapeXml(f.caption) << " (figures/" << EscapeXml(f.name)
         << ".svg)</figcaption></figure>\n";
  }
  return HtmlPage(
      "Scout comparison of " + std::to_string(runs.size()) + (runs.size() == 1 ? " run" : " runs"),
      body.str());
}

std::vector<ReportFile> BuildComparison(const std::vector<std::filesystem::path>& dirs) {
  if (dirs.empty()) throw InputError("compare needs at least one output directory");
  std::vector<RunData> runs;
  for (const std::filesystem::path& dir : dirs) {
    RunData run = ReadRun(dir);
    // Same-named directories (a/out, b/out) would be indistinguishable in legends.
    const std::string base = run.name;
    for (int n = 2; std::any_of(runs.begin(), runs.end(),
                                [&](const RunData& r) { return r.name == run.name; });
         ++n) {
      run.name = base + " (" + std::to_string(n) + ")";
    }
    runs.push_back(std::move(run));
  }
  const std::vector<Figure> figures = ComparisonFigures(runs);
  std::vector<ReportFile> files;
  for (const Figure& f : figures) files.push_back({"figures/" + f.name + ".svg", f.svg});
  files.push_back({"compare.html", RenderComparison(runs, figures)});
  return files;
}

}  // namespace scout::report
