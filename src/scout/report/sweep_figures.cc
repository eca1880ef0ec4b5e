#include "scout/report/sweep_figures.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include "scout/report/svg_plot.h"

namespace scout::report {
namespace {

using Json = nlohmann::json;

double JsonNumberOr(const Json& j, const char* key, double fallback) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

const Json* Strategies(const RunData& run) {
  const Json& s = run.summary;
  if (!s.contains("frontier") || !s["frontier"].contains("strategies")) return nullptr;
  return &s["frontier"]["strategies"];
}

// Optimisation rounds of 'strategy' in 'run' (frontier.csv rows, else the
// summary's count).
double RoundsOf(const RunData& run, const std::string& strategy) {
  int n = 0;
  for (const FrontierRound& r : run.rounds) n += r.strategy == strategy ? 1 : 0;
  return n > 0 ? n : JsonNumberOr(run.summary, "optimizations", 0.0);
}

// One series per strategy: (x of the run, value(strategy json, run)), sorted by x.
std::vector<Series> PerStrategy(
    const std::vector<std::pair<double, const RunData*>>& points,
    const std::vector<std::string>& strategies,
    const std::function<double(const Json&, const RunData&, const std::string&)>& value) {
  std::vector<Series> series;
  for (const std::string& name : strategies) {
    Series line{name, {}, {}};
    for (const auto& [x, run] : points) {
      const Json* all = Strategies(*run);
      if (all == nullptr || !all->contains(name)) continue;
      line.x.push_back(x);
      line.y.push_back(value((*all)[name], *run, name));
    }
    if (!line.x.empty()) series.push_back(line);
  }
  return series;
}

std::vector<std::string> StrategyNames(const std::vector<RunData>& runs) {
  std::vector<std::string> names;
  for (const char* known : {"full", "dfd", "bfs", "direct", "exact"}) {
    for (const RunData& run : runs) {
      const Json* all = Strategies(run);
      if (all != nullptr && all->contains(known)) {
        names.push_back(known);
        break;
      }
    }
  }
  return names;
}

std::vector<std::pair<double, const RunData*>> SortedBy(
    const std::vector<RunData>& runs, const std::function<double(const RunData&)>& key) {
  std::vector<std::pair<double, const RunData*>> points;
  for (const RunData& run : runs) {
    const double x = key(run);
    if (std::isfinite(x)) points.emplace_back(x, &run);
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return points;
}

size_t DistinctX(const std::vector<std::pair<double, const RunData*>>& points) {
  std::set<double> xs;
  for (const auto& p : points) xs.insert(p.first);
  return xs.size();
}

}  // namespace

std::vector<Figure> SweepFigures(const std::vector<RunData>& runs) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<Figure> figures;
  const auto epsilon =
      SortedBy(runs, [](const RunData& r) { return JsonNumberOr(r.summary, "epsilon_m", kNaN); });
  if (DistinctX(epsilon) >= 2) {
    const std::vector<std::string> thresholded = {"bfs", "direct"};
    LineChart points{
        "Points re-queried over all optimisation rounds against ε", "ε (m)", "points re-queried",
        PerStrategy(epsilon, thresholded, [](const Json& s, const RunData&, const std::string&) {
          return JsonNumberOr(s, "queried_points", kNaN);
        })};
    figures.push_back(
        {"epsilon_points", "ε sweep: points re-queried (bfs, direct)", RenderLineChart(points)});
    LineChart accuracy{
        "Accuracy against full recomputation against ε", "ε (m)", "accuracy",
        PerStrategy(epsilon, thresholded, [](const Json& s, const RunData&, const std::string&) {
          return JsonNumberOr(s, "accuracy", kNaN);
        })};
    figures.push_back(
        {"epsilon_accuracy", "ε sweep: accuracy (bfs, direct)", RenderLineChart(accuracy)});
  }
  const auto size = SortedBy(runs, [](const RunData& r) {
    const Json& s = r.summary;
    return s.contains("world_size_m") && s["world_size_m"].is_array() &&
                   !s["world_size_m"].empty() && s["world_size_m"][0].is_number()
               ? s["world_size_m"][0].get<double>()
               : kNaN;
  });
  if (DistinctX(size) >= 2) {
    const std::vector<std::string> names = StrategyNames(runs);
    const auto per_round = [](const char* key) {
      return [key](const Json& s, const RunData& run, const std::string& name) {
        const double rounds = RoundsOf(run, name);
        return rounds > 0 ? JsonNumberOr(s, key, kNaN) / rounds : kNaN;
      };
    };
    LineChart points{"Points re-queried per optimisation round against world size",
                     "world width (m)", "points per round",
                     PerStrategy(size, names, per_round("queried_points"))};
    points.log_y = true;
    figures.push_back(
        {"size_points", "World size: points re-queried per round", RenderLineChart(points)});
    LineChart time{"Update time per optimisation round against world size", "world width (m)",
                   "ms per round", PerStrategy(size, names, per_round("time_ms"))};
    time.log_y = true;
    figures.push_back({"size_time", "World size: update time per round", RenderLineChart(time)});
  }
  return figures;
}

}  // namespace scout::report
