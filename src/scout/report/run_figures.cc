#include "scout/report/run_figures.h"

#include <algorithm>
#include <cmath>

#include "scout/report/strategy_stats.h"
#include "scout/report/svg_plot.h"

namespace scout::report {
namespace {

// One line per strategy of 'value' over the optimisation rounds.
std::vector<Series> PerStrategy(const std::vector<FrontierRound>& rounds,
                                double (*value)(const FrontierRound&)) {
  std::vector<Series> series;
  for (const std::string& name : StrategiesOf(rounds)) {
    Series s{name, {}, {}};
    for (const FrontierRound& r : rounds) {
      if (r.strategy != name) continue;
      s.x.push_back(r.round);
      s.y.push_back(value(r));
    }
    series.push_back(std::move(s));
  }
  return series;
}

// Returns the largest over the smallest per-series median of the positive
// values (1 when fewer than two series have any).
double MedianSpread(const std::vector<Series>& series) {
  std::vector<double> medians;
  for (const Series& s : series) {
    std::vector<double> positive;
    for (const double y : s.y) {
      if (y > 0.0) positive.push_back(y);
    }
    if (positive.empty()) continue;
    std::nth_element(positive.begin(), positive.begin() + positive.size() / 2, positive.end());
    medians.push_back(positive[positive.size() / 2]);
  }
  if (medians.size() < 2) return 1.0;
  const auto [lo, hi] = std::minmax_element(medians.begin(), medians.end());
  return *hi / *lo;
}

std::string WithRun(const std::string& title, const RunData& run) {
  return title + " — " + run.name;
}

void AddFrontierFigures(const RunData& run, std::vector<Figure>* figures) {
  if (run.rounds.empty()) return;
  // local_points is shared by all strategies: draw it once, from the first.
  const std::string first = run.rounds.front().strategy;
  Series local{"all submaps", {}, {}};
  for (const FrontierRound& r : run.rounds) {
    if (r.strategy != first || !r.local_points) continue;
    local.x.push_back(r.round);
    local.y.push_back(static_cast<double>(*r.local_points));
  }
  if (!local.x.empty()) {
    LineChart chart;
    chart.title = WithRun("Total local frontier points", run);
    chart.x_label = "optimisation round";
    chart.y_label = "local frontier points";
    chart.series = {local};
    figures->push_back({"local_points", "Local frontier points of all submaps at each round.",
                        RenderLineChart(chart)});
  }
  LineChart queried;
  queried.title = WithRun("Points re-queried per optimisation round", run);
  queried.x_label = "optimisation round";
  queried.y_label = "local frontier points re-queried";
  queried.series = PerStrategy(
      run.rounds, [](const FrontierRound& r) { return static_cast<double>(r.queried_points); });
  figures->push_back({"queried_points",
                      "Local frontier points each strategy stabbing-queried in each round.",
                      RenderLineChart(queried)});
  LineChart time;
  time.title = WithRun("Update time per optimisation round", run);
  time.x_label = "optimisation round";
  time.y_label = "update time (ms)";
  time.series = PerStrategy(run.rounds, [](const FrontierRound& r) { return r.time_us * 1e-3; });
  // One slow strategy (full) flattens the others against the axis on a linear
  // scale; a log axis keeps their differences readable.
  time.log_y = MedianSpread(time.series) >= 5.0;
  if (time.log_y) time.y_label += ", log scale";
  figures->push_back({"update_time", "Wall time each strategy spent on each optimisation round.",
                      RenderLineChart(time)});

  BarChart bars;
  bars.title = WithRun("Accuracy, precision and recall against full", run);
  bars.y_label = "percent (%)";
  bars.zoom = true;
  bars.value_format = "auto";
  bars.series = {{"accuracy", {}}, {"precision", {}}, {"recall", {}}};
  for (const StrategyStats& s : StrategyStatsOf(run)) {
    // "full" is the reference: its bars are 100 % by definition.
    // Without the reference nothing was scored: no bars rather than NaN ones.
    if (s.strategy == "full" || std::isnan(s.accuracy)) continue;
    bars.categories.push_back(s.strategy);
    bars.series[0].values.push_back(100.0 * s.accuracy);
    bars.series[1].values.push_back(100.0 * s.precision);
    bars.series[2].values.push_back(100.0 * s.recall);
  }
  if (!bars.categories.empty()) {
    figures->push_back({"accuracy",
                        "Answers of each strategy against full recomputation, over all local "
                        "frontier points after every round.",
                        RenderBarChart(bars)});
  }
}

void AddCoverageFigures(const RunData& run, std::vector<Figure>* figures) {
  if (run.coverage.empty()) return;
  Series by_path{run.name, {}, {}}, by_time{run.name, {}, {}};
  for (const CoverageSample& c : run.coverage) {
    by_path.x.push_back(c.path_length_m);
    by_path.y.push_back(100.0 * c.coverage);
    by_time.x.push_back(c.sim_time_s);
    by_time.y.push_back(100.0 * c.coverage);
  }
  LineChart path;
  path.title = WithRun("Coverage over path length", run);
  path.x_label = "path length (m)";
  path.y_label = "coverage (% of reachable free area)";
  path.series = {by_path};
  figures->push_back({"coverage_path", "Explored share of the reachable free area over distance.",
                      RenderLineChart(path)});
  LineChart time = path;
  time.title = WithRun("Coverage over simulated time", run);
  time.x_label = "simulated time (s)";
  time.series = {by_time};
  figures->push_back({"coverage_time", "Explored share of the reachable free area over time.",
                      RenderLineChart(time)});
}

}  // namespace

std::vector<Figure> RunFigures(const RunData& run) {
  std::vector<Figure> figures;
  AddFrontierFigures(run, &figures);
  AddCoverageFigures(run, &figures);
  return figures;
}

}  // namespace scout::report
