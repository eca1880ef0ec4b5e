#ifndef SCOUT_FRONTIER_FRONTIER_ENGINE_H_
#define SCOUT_FRONTIER_FRONTIER_ENGINE_H_

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scout/events/submap_events.h"
#include "scout/frontier/frontier_options.h"
#include "scout/frontier/submap_catalog.h"
#include "scout/frontier/update_strategy.h"

namespace scout::frontier {

// Confusion counts of a strategy's answers against "full", over all local
// frontier points (positive = global frontier).
struct Confusion {
  int64_t tp = 0, fp = 0, tn = 0, fn = 0;
  Confusion& operator+=(const Confusion& o) {
    tp += o.tp, fp += o.fp, tn += o.tn, fn += o.fn;
    return *this;
  }
  // Ratios are 1 when their denominator is 0 (nothing to get wrong).
  double accuracy() const;
  double precision() const;
  double recall() const;
};

// One optimisation round of one strategy.
struct StrategyRound {
  int round = 0;  // 0-based optimisation round
  std::string strategy;
  UpdateCost cost;
  Confusion confusion;  // against "full" after the round (zero without evaluation)
  // Local frontier points of all submaps when the round ran (shared by all
  // strategies: extraction is done once per grid change).
  int64_t local_points = 0;
};

// A strategy's totals over all optimisation rounds (ALGORITHMS §5).
struct StrategyTotals {
  std::string strategy;
  int64_t queried_points = 0;
  int64_t queried_submaps = 0;
  double time_ms = 0.0;
  Confusion confusion;
  // 1 - sum queried_points / sum queried_points(dfd); NaN without dfd.
  double performance_p = 0.0;
  // Grid changes (scan insertions), counted apart from optimisation rounds.
  int64_t grid_change_queried_points = 0;
  double grid_change_time_ms = 0.0;
};

// Runs one or more update strategies on one shared submap catalog, all fed the
// identical event stream (lockstep). Local frontier extraction runs once per
// grid change and is shared; each strategy keeps its own answers.
class FrontierEngine {
 public:
  // 'strategies' are names for MakeStrategy (duplicates rejected). With
  // 'evaluate', "full" is added when absent and every optimisation round is
  // scored against it. Throws InputError on a bad name or option.
  FrontierEngine(const FrontierOptions& options, const std::vector<std::string>& strategies,
                 bool evaluate);

  // Applies one event to the catalog, then to every strategy. With
  // FrontierOptions::defer_grid_changes, a SubmapChanged is only recorded
  // (replacing an older pending grid of the same submap) and applied by the
  // next Optimized event or Flush(). Throws InputError for a submap id that
  // is neither known nor the next one.
  void Apply(const events::SubmapEvent& event);
  // Applies every pending grid change, in submap id order. The accessors
  // below reflect the events up to the last Flush() or Optimized event.
  void Flush();
  bool has_pending_changes() const { return !pending_.empty(); }

  const SubmapCatalog& catalog() const { return catalog_; }
  const std::vector<std::string>& strategy_names() const { return names_; }
  // Returns the strategy called 'name'; throws InputError if it is not running.
  const UpdateStrategy& strategy(const std::string& name) const;
  // Returns the global positions of the points 'name' answers as global frontier.
  std::vector<Eigen::Vector2d> GlobalFrontier(const std::string& name) const;
  // Returns the submaps 'name' re-queried in the last optimisation round.
  const std::vector<int>& LastRoundSubmaps(const std::string& name) const;

  int optimizations() const { return optimizations_; }
  // True when every round is scored against "full" (see the constructor).
  bool evaluating() const { return truth_ >= 0; }
  // Grid changes applied to the catalog (after deferral), and received.
  int grid_changes() const { return grid_changes_; }
  int grid_change_events() const { return grid_change_events_; }
  const std::vector<StrategyRound>& rounds() const { return rounds_; }
  // Totals per strategy, in the order of strategy_names().
  std::vector<StrategyTotals> Totals() const;
  // Time spent in the shared catalog (answer maps, local frontier extraction).
  double catalog_time_ms() const { return catalog_time_ms_; }

 private:
  int IndexOf(const std::string& name) const;
  Confusion Compare(const UpdateStrategy& s, const UpdateStrategy& truth) const;
  void ApplyChange(const events::SubmapChanged& changed);

  SubmapCatalog catalog_;
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<UpdateStrategy>> strategies_;
  int truth_ = -1;  // index of "full" when evaluating
  std::vector<StrategyRound> rounds_;
  std::vector<std::vector<int>> last_round_submaps_;
  std::vector<int64_t> grid_change_points_;
  std::vector<double> grid_change_time_us_;
  int optimizations_ = 0;
  int grid_changes_ = 0;
  int grid_change_events_ = 0;
  // Deferred grid changes by submap id (the newest event of each submap).
  std::map<int, events::SubmapChanged> pending_;
  double catalog_time_ms_ = 0.0;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_FRONTIER_ENGINE_H_
