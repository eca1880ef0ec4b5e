#include "scout/frontier/frontier_engine.h"

#include <algorithm>
#include <limits>

#include "scout/common/error.h"
#include "scout/frontier/stopwatch.h"

namespace scout::frontier {
namespace {

double Ratio(int64_t num, int64_t den) {
  return den == 0 ? 1.0 : static_cast<double>(num) / static_cast<double>(den);
}

}  // namespace

double Confusion::accuracy() const { return Ratio(tp + tn, tp + tn + fp + fn); }
double Confusion::precision() const { return Ratio(tp, tp + fp); }
double Confusion::recall() const { return Ratio(tp, tp + fn); }

FrontierEngine::FrontierEngine(const FrontierOptions& options,
                               const std::vector<std::string>& strategies, bool evaluate)
    : catalog_(options), names_(strategies) {
  if (names_.empty()) throw InputError("no frontier strategy given: expected at least one");
  for (size_t a = 0; a < names_.size(); ++a) {
    for (size_t b = a + 1; b < names_.size(); ++b) {
      if (names_[a] == names_[b]) {
        throw InputError("frontier strategy '" + names_[a] + "' given twice");
      }
    }
  }
  if (evaluate && std::find(names_.begin(), names_.end(), "full") == names_.end()) {
    names_.insert(names_.begin(), "full");
  }
  for (const std::string& name : names_) strategies_.push_back(MakeStrategy(name, catalog_));
  if (evaluate) truth_ = IndexOf("full");
  last_round_submaps_.resize(names_.size());
  grid_change_points_.assign(names_.size(), 0);
  grid_change_time_us_.assign(names_.size(), 0.0);
}

int FrontierEngine::IndexOf(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) {
    throw InputError("frontier strategy '" + name + "' is not running in this engine");
  }
  return static_cast<int>(it - names_.begin());
}

const UpdateStrategy& FrontierEngine::strategy(const std::string& name) const {
  return *strategies_[IndexOf(name)];
}

const std::vector<int>& FrontierEngine::LastRoundSubmaps(const std::string& name) const {
  return last_round_submaps_[IndexOf(name)];
}

void FrontierEngine::Apply(const events::SubmapEvent& event) {
  if (const auto* changed = std::get_if<events::SubmapChanged>(&event)) {
    ++grid_change_events_;
    if (!catalog_.options().defer_grid_changes) {
      ApplyChange(*changed);
      return;
    }
    // Ids are dense: a change names a known submap or the next new one. Checked
    // now, so a bad stream fails at the event that is wrong.
    const int next_id =
        std::max(catalog_.size(), pending_.empty() ? 0 : pending_.rbegin()->first + 1);
    if (changed->id < 0 || changed->id > next_id) {
      throw InputError("submap event: submap id " + std::to_string(changed->id) +
                       " is neither known nor the next one (" + std::to_string(next_id) + ")");
    }
    pending_.insert_or_assign(changed->id, *changed);
    return;
  }
  Flush();
  const auto& optimized = std::get<events::Optimized>(event);
  const std::vector<geometry::Rigid2d> previous = catalog_.Apply(optimized);
  std::vector<StrategyRound> round(strategies_.size());
  for (size_t s = 0; s < strategies_.size(); ++s) {
    round[s].round = optimizations_;
    round[s].strategy = names_[s];
    round[s].local_points = catalog_.total_points();
    round[s].cost = strategies_[s]->OnOptimized(previous);
    last_round_submaps_[s] = round[s].cost.submap_ids;
  }
  if (truth_ >= 0) {
    for (size_t s = 0; s < strategies_.size(); ++s) {
      round[s].confusion = Compare(*strategies_[s], *strategies_[truth_]);
    }
  }
  for (StrategyRound& r : round) {
    r.cost.submap_ids.clear();  // kept only for the last round
    rounds_.push_back(std::move(r));
  }
  ++optimizations_;
}

void FrontierEngine::Flush() {
  // Ascending ids: a new submap always follows the ones before it.
  std::map<int, events::SubmapChanged> pending;
  pending.swap(pending_);
  for (const auto& [id, changed] : pending) ApplyChange(changed);
}

void FrontierEngine::ApplyChange(const events::SubmapChanged& changed) {
  const Stopwatch stopwatch;
  const SubmapChange change = catalog_.Apply(changed);
  catalog_time_ms_ += stopwatch.ElapsedUs() * 1e-3;
  ++grid_changes_;
  for (size_t s = 0; s < strategies_.size(); ++s) {
    const UpdateCost cost = strategies_[s]->OnSubmapChanged(change);
    grid_change_points_[s] += cost.queried_points;
    grid_change_time_us_[s] += cost.time_us;
  }
}

Confusion FrontierEngine::Compare(const UpdateStrategy& s, const UpdateStrategy& truth) const {
  Confusion c;
  for (int i = 0; i < catalog_.size(); ++i) {
    const std::vector<uint8_t>& got = s.answers(i);
    const std::vector<uint8_t>& want = truth.answers(i);
    for (size_t k = 0; k < got.size(); ++k) {
      if (want[k]) {
        (got[k] ? c.tp : c.fn) += 1;
      } else {
        (got[k] ? c.fp : c.tn) += 1;
      }
    }
  }
  return c;
}

std::vector<Eigen::Vector2d> FrontierEngine::GlobalFrontier(const std::string& name) const {
  const UpdateStrategy& s = strategy(name);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < catalog_.size(); ++i) {
    const std::vector<Eigen::Vector2d>& local = catalog_.submap(i).frontier.points_m;
    for (size_t k = 0; k < local.size(); ++k) {
      if (s.IsGlobalFrontier(i, static_cast<int>(k))) {
        points.push_back(catalog_.GlobalPosition(i, local[k]));
      }
    }
  }
  return points;
}

std::vector<StrategyTotals> FrontierEngine::Totals() const {
  std::vector<StrategyTotals> totals(names_.size());
  for (size_t s = 0; s < names_.size(); ++s) {
    totals[s].strategy = names_[s];
    totals[s].grid_change_queried_points = grid_change_points_[s];
    totals[s].grid_change_time_ms = grid_change_time_us_[s] * 1e-3;
  }
  for (const StrategyRound& r : rounds_) {
    StrategyTotals& t = totals[IndexOf(r.strategy)];
    t.queried_points += r.cost.queried_points;
    t.queried_submaps += r.cost.queried_submaps;
    t.time_ms += r.cost.time_us * 1e-3;
    t.confusion += r.confusion;
  }
  const auto dfd = std::find(names_.begin(), names_.end(), "dfd");
  for (StrategyTotals& t : totals) {
    if (dfd == names_.end()) {
      t.performance_p = std::numeric_limits<double>::quiet_NaN();
    } else {
      const int64_t base = totals[dfd - names_.begin()].queried_points;
      t.performance_p = base == 0 ? 0.0 : 1.0 - static_cast<double>(t.queried_points) / base;
    }
  }
  return totals;
}

}  // namespace scout::frontier
