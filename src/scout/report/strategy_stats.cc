#include "scout/report/strategy_stats.h"

#include <cmath>
#include <limits>

namespace scout::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Ratios are 1 when their denominator is 0, as the frontier module defines them.
double Ratio(int64_t num, int64_t den) { return den == 0 ? 1.0 : static_cast<double>(num) / den; }

std::vector<StrategyStats> FromRounds(const std::vector<FrontierRound>& rounds) {
  std::vector<StrategyStats> stats;
  int64_t dfd_points = -1;
  for (const std::string& name : StrategiesOf(rounds)) {
    StrategyStats s;
    s.strategy = name;
    int64_t tp = 0, fp = 0, tn = 0, fn = 0;
    for (const FrontierRound& r : rounds) {
      if (r.strategy != name) continue;
      ++s.rounds;
      s.queried_points += r.queried_points;
      s.time_ms += r.time_us * 1e-3;
      tp += r.tp, fp += r.fp, tn += r.tn, fn += r.fn;
    }
    s.time_per_round_ms = s.rounds > 0 ? s.time_ms / s.rounds : kNaN;
    // No answer scored in any round: the run had no reference ("full"), and
    // an empty confusion matrix's ratios of 1 would claim a perfect score.
    const bool scored = tp + fp + tn + fn > 0;
    s.accuracy = scored ? Ratio(tp + tn, tp + fp + tn + fn) : kNaN;
    s.precision = scored ? Ratio(tp, tp + fp) : kNaN;
    s.recall = scored ? Ratio(tp, tp + fn) : kNaN;
    if (name == "dfd") dfd_points = s.queried_points;
    stats.push_back(s);
  }
  for (StrategyStats& s : stats) {
    s.performance_p =
        dfd_points > 0 ? 1.0 - static_cast<double>(s.queried_points) / dfd_points : kNaN;
  }
  return stats;
}

double NumberOr(const nlohmann::json& object, const char* key, double fallback) {
  if (!object.contains(key)) return fallback;
  const nlohmann::json& v = object[key];
  if (v.is_number()) return v.get<double>();
  return v.is_null() ? kNaN : fallback;
}

}  // namespace

std::vector<StrategyStats> StrategyStatsOf(const RunData& run) {
  std::vector<StrategyStats> stats = FromRounds(run.rounds);
  const nlohmann::json* listed = nullptr;
  if (run.summary.is_object() && run.summary.contains("frontier") &&
      run.summary["frontier"].is_object() && run.summary["frontier"].contains("strategies") &&
      run.summary["frontier"]["strategies"].is_object()) {
    listed = &run.summary["frontier"]["strategies"];
  }
  if (listed == nullptr) return stats;
  const double optimizations = NumberOr(run.summary, "optimizations", kNaN);
  for (const auto& [name, values] : listed->items()) {
    if (!values.is_object()) continue;
    StrategyStats* s = nullptr;
    for (StrategyStats& candidate : stats) {
      if (candidate.strategy == name) s = &candidate;
    }
    if (s == nullptr) {
      stats.push_back({});
      s = &stats.back();
      s->strategy = name;
      s->rounds = std::isfinite(optimizations) ? static_cast<int>(optimizations) : 0;
      s->time_per_round_ms = kNaN;
    }
    s->queried_points = static_cast<int64_t>(NumberOr(values, "queried_points", s->queried_points));
    s->time_ms = NumberOr(values, "time_ms", s->time_ms);
    if (s->rounds > 0) s->time_per_round_ms = s->time_ms / s->rounds;
    s->accuracy = NumberOr(values, "accuracy", s->accuracy);
    s->precision = NumberOr(values, "precision", s->precision);
    s->recall = NumberOr(values, "recall", s->recall);
    s->performance_p = NumberOr(values, "P", s->performance_p);
  }
  return stats;
}

}  // namespace scout::report
