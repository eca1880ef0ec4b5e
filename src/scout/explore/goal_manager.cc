#include "scout/explore/goal_manager.h"

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "scout/common/parallel.h"
#include "scout/explore/option_check.h"
#include "scout/explore/scan_contradiction.h"
#include "scout/explore/stand_off.h"

namespace scout::explore {

void Validate(const GoalManagerOptions& o) {
  const std::string g = "goal_manager";
  CheckAtLeast(g, "progress_timeout_s", o.progress_timeout_s, 0.0, /*strict=*/true);
  CheckAtLeast(g, "progress_min_m", o.progress_min_m, 0.0);
  CheckAtLeast(g, "replan_interval_s", o.replan_interval_s, 0.0);
  CheckAtLeast(g, "max_plan_attempts", o.max_plan_attempts, 1.0);
  CheckAtLeast(g, "finish_after_empty_s", o.finish_after_empty_s, 0.0);
  CheckAtLeast(g, "finish_with_frontier_after_s", o.finish_with_frontier_after_s, 0.0);
  CheckAtLeast(g, "stuck_timeout_s", o.stuck_timeout_s, 0.0);
  CheckAtLeast(g, "stuck_min_motion_m", o.stuck_min_motion_m, 0.0);
  CheckAtLeast(g, "back_up_distance_m", o.back_up_distance_m, 0.0);
  CheckAtLeast(g, "back_up_speed_mps", o.back_up_speed_mps, 0.0);
  CheckAtLeast(g, "back_up_timeout_s", o.back_up_timeout_s, 0.0);
  CheckAtLeast(g, "back_up_look_behind_m", o.back_up_look_behind_m, 0.0);
  CheckAtLeast(g, "back_up_trail_m", o.back_up_trail_m, 0.0);
  CheckAtLeast(g, "back_up_trail_tolerance_m", o.back_up_trail_tolerance_m, 0.0);
  CheckAtLeast(g, "retrace_m", o.retrace_m, 0.0);
  CheckAtLeast(g, "retrace_clearance_m", o.retrace_clearance_m, 0.0);
  CheckAtLeast(g, "last_resort_retrace_m", o.last_resort_retrace_m, 0.0);
  CheckAtLeast(g, "last_resort_confined_radius_m", o.last_resort_confined_radius_m, 0.0);
  CheckAtLeast(g, "last_resort_confined_s", o.last_resort_confined_s, 0.0);
  CheckAtLeast(g, "max_last_resorts", o.max_last_resorts, 0.0);
  CheckAtLeast(g, "close_stuck_passage_radius_m", o.close_stuck_passage_radius_m, 0.0);
  CheckAtLeast(g, "goal_frontier_radius_m", o.goal_frontier_radius_m, 0.0);
  CheckAtLeast(g, "goal_switch_margin", o.goal_switch_margin, 0.0);
  CheckAtLeast(g, "goal_match_radius_m", o.goal_match_radius_m, 0.0);
  CheckAtLeast(g, "max_stand_off_m", o.max_stand_off_m, 0.0);
  CheckAtLeast(g, "scan_check_radius_m", o.scan_check_radius_m, 0.0);
  CheckAtLeast(g, "scan_check_memory_s", o.scan_check_memory_s, 0.0);
  CheckAtLeast(g, "stand_off_unknown_margin_m", o.stand_off_unknown_margin_m, 0.0);
  Validate(o.guard);
  if (!o.boundary.empty() && o.boundary.size() < 3) {
    RejectOption(g, "boundary", "no vertices or at least 3 vertices",
                 static_cast<double>(o.boundary.size()));
  }
  for (const Eigen::Vector2d& v : o.boundary) {
    if (!v.allFinite()) RejectOption(g, "boundary", "finite vertices", v.x() + v.y());
  }
  Validate(o.failed_goals);
}

std::string_view ToString(ExploreState state) {
  switch (state) {
    case ExploreState::kIdle:
      return "idle";
    case ExploreState::kPlanning:
      return "planning";
    case ExploreState::kDriving:
      return "driving";
    case ExploreState::kReached:
      return "reached";
    case ExploreState::kFailed:
      return "failed";
    case ExploreState::kReturning:
      return "returning";
    case ExploreState::kFinished:
      return "finished";
  }
  return "unknown";
}

std::string_view ToString(GoalOutcome outcome) {
  switch (outcome) {
    case GoalOutcome::kOpen:
      return "open";
    case GoalOutcome::kReached:
      return "reached";
    case GoalOutcome::kSeen:
      return "seen";
    case GoalOutcome::kFailed:
      return "failed";
    case GoalOutcome::kUnreachable:
      return "unreachable";
    case GoalOutcome::kSuperseded:
      return "superseded";
    case GoalOutcome::kDropped:
      return "dropped";
    case GoalOutcome::kStuck:
      return "stuck";
    case GoalOutcome::kStopped:
      return "stopped";
  }
  return "unknown";
}

bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

GoalManager::GoalManager(const GoalManagerOptions& options,
                         const TraversabilityOptions& traversability,
                         const PathPlannerOptions& planner, const PathFollowerOptions& follower,
                         std::unique_ptr<GoalPolicy> policy)
    : options_(options),
      traversability_(traversability),
      planner_(planner),
      follower_(follower),
      policy_(std::move(policy)),
      failed_(options.failed_goals),
      visited_(options.failed_goals),
      stuck_places_(options.failed_goals) {
  Validate(options_);
  Validate(traversability_);
  if (!policy_) throw std::invalid_argument("GoalManager: no goal policy");
}

void GoalManager::Start() {
  if (state_ == ExploreState::kIdle || state_ == ExploreState::kFinished) {
    state_ = ExploreState::kPlanning;
    need_selection_ = true;
    empty_since_s_.reset();
  }
}

void GoalManager::Stop() {
  CloseGoalRecord(GoalOutcome::kStopped);
  state_ = ExploreState::kIdle;
  goal_.reset();
  follower_.Clear();
  // A recovery under way ends with the goal: after Start() the robot drives
  // to its next goal, not on backing up or retracing.
  moving_since_.reset();
  backing_up_since_.reset();
  retracing_since_.reset();
}

std::vector<Eigen::Vector2d> GoalManager::FrontierInBoundary(
    const std::vector<Eigen::Vector2d>& frontier) const {
  if (options_.boundary.empty()) return frontier;
  std::vector<Eigen::Vector2d> inside;
  for (const Eigen::Vector2d& p : frontier) {
    if (InsidePolygon(options_.boundary, p)) inside.push_back(p);
  }
  return inside;
}

void GoalManager::RefreshMap(const ExploreInput& in) {
  if (map_ && !map_dirty_) return;
  // Between optimisations the map changes only near the robot: the previous
  // planning map is inflated again only there.
  map_ = std::make_unique<PlanningMap>(*in.map, traversability_,
                                       planner_.options().clearance_weight > 0.0, map_.get());
  // Stuck places close their passages first; the cells the robot has driven
  // over open again, so closing never seals it into a room it entered.
  stuck_places_.RetryChangedGoals(*map_, in.submaps);
  const std::vector<Eigen::Vector2d> stuck = stuck_places_.Blacklisted(in.submaps);
  for (const Eigen::Vector2d& p : stuck) {
    map_->CloseNarrow(p, options_.close_stuck_passage_radius_m);
  }
  if (in.driven && stuck.empty()) {
    map_->AllowDriven(*in.driven);
  } else if (in.driven) {
    // Where the robot stands counts as driven too: it backs up less than the
    // closing radius, so it stands among closed cells, and the trajectory
    // (SLAM nodes) may end short of it. Without this the office seed 5
    // nearest-frontier run was sealed into a room corner after 200 s. Only
    // while a stuck place is closed: otherwise the start region's escape
    // already leaves blocked cells, and runs without a stuck recovery keep
    // exactly the map they had.
    std::vector<Eigen::Vector2d> driven = *in.driven;
    driven.push_back(in.robot_pose.translation());
    map_->AllowDriven(driven);
  }
  map_dirty_ = false;
  counters_.goals_retried += failed_.RetryChangedGoals(*map_, in.submaps);
  visited_.RetryChangedGoals(*map_, in.submaps);
}

double GoalManager::DistanceToFrontier(const Eigen::Vector2d& goal,
                                       const std::vector<Eigen::Vector2d>& frontier) {
  double d2 = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : frontier) d2 = std::min(d2, (p - goal).squaredNorm());
  return std::sqrt(d2);
}

GoalManager::Reach GoalManager::ReachFrom(const Eigen::Vector2d& robot,
                                          const std::vector<Eigen::Vector2d>& frontier,
                                          double settle_m) {
  const double snap = map_->options().goal_snap_radius_m;
  // Settles the field until it reaches a frontier point or every cell, from
  // 'settle_m' on, doubling (the nearest frontier is usually near). A point
  // is reached when a cell within the snap radius is (NearestReached); the
  // first look gathers those cells, so that the looks after it, when none
  // was reached, read a list instead of walking tens of thousands of discs
  // again.
  const grid::MapLimits& limits = map_->limits();
  const auto reaches_frontier = [&](PathDistanceField& field) {
    std::vector<int64_t> cells;
    bool gathered = false;
    for (double d = settle_m;; d = std::max(2.0 * d, kFirstSettle_m)) {
      field.SettleUpTo(d);
      if (!gathered) {
        bool reached = false;
        for (const Eigen::Vector2d& p : frontier) {
          ForEachCellWithin(limits, p, snap, [&](const grid::CellIndex& c) {
            cells.push_back(limits.FlatIndex(c));
            reached = reached || std::isfinite(field.at(cells.back()));
          });
          if (reached) return true;
        }
        gathered = true;
      } else if (std::any_of(cells.begin(), cells.end(),
                             [&](int64_t flat) { return std::isfinite(field.at(flat)); })) {
        return true;
      }
      if (field.complete()) return false;
    }
  };
  Reach reach;
  reach.start.emplace(*map_, robot);
  reach.field.emplace(*map_, *reach.start, settle_m);
  counters_.escapes += reach.start->escaped();
  if (reach.start->escaped() || frontier.empty()) return reach;
  if (reaches_frontier(*reach.field)) return reach;
  // Boxed in: the robot's cell is traversable but its component reaches no
  // frontier (a pocket that even narrow passages cannot leave). Leave it
  // wherever the disc keeps the clearance it has.
  reach.start.emplace(*map_, robot, /*escape=*/true);
  reach.field.emplace(*map_, *reach.start, settle_m);
  ++counters_.escapes;
  return reach;
}

std::optional<double> GoalManager::ScoreNear(const std::vector<GoalCandidate>& ranked,
                                             const Eigen::Vector2d& goal) const {
  std::optional<double> score;
  const double match2 = options_.goal_match_radius_m * options_.goal_match_radius_m;
  for (const GoalCandidate& c : ranked) {
    if ((c.position - goal).squaredNorm() > match2) continue;
    if (!score || c.score > *score) score = c.score;
  }
  return score;
}

void GoalManager::ReachAndRank(const ExploreInput& in, const std::vector<Eigen::Vector2d>& frontier,
                               RankFor use, Ranking& ranking) {
  PolicyInput& pi = ranking.input;
  pi.map = map_.get();
  pi.frontier = &frontier;
  pi.robot = in.robot_pose.translation();
  if (goal_) pi.current_goal = Resolve(*goal_, in.submaps);
  // Reached goals are avoided like failed ones until the map around them
  // changes: a frontier that stays after arrival cannot be seen from there.
  ranking.blacklisted = failed_.Blacklisted(in.submaps);
  const std::vector<Eigen::Vector2d> visited = visited_.Blacklisted(in.submaps);
  ranking.blacklisted.insert(ranking.blacklisted.end(), visited.begin(), visited.end());
  pi.avoid = &ranking.blacklisted;
  pi.avoid_radius_m = options_.failed_goals.blacklist_radius_m;
  // How far the field is settled first: everything when scores are not
  // bounded by path cost; nothing beyond the first frontier for policies that
  // rank without it; else what a candidate can score above its path cost, a
  // little more, and against the current goal a detour's worth of the way
  // to it.
  const bool distances = policy_->needs_path_distances();
  ranking.above_cost_m = distances ? policy_->ScoreAbovePathCost(*map_) : std::nullopt;
  if (use == RankFor::kAgainstCurrentGoal && !pi.current_goal) ranking.above_cost_m.reset();
  double settle_m = distances ? std::numeric_limits<double>::infinity() : 0.0;
  if (ranking.above_cost_m) {
    settle_m = *ranking.above_cost_m + kFirstSettle_m;
    if (use == RankFor::kAgainstCurrentGoal) {
      settle_m += kDetourFactor * (*pi.current_goal - pi.robot).norm();
    }
  }
  // The path distances cover the whole map, and so does the scout policy's
  // clustering (mean-shift, connectivity split), which needs none: in the
  // museum each took a tenth to a quarter of the wall time. Both only read
  // the planning map and the frontier, so they run side by side.
  common::ParallelInvoke([&] { ranking.prepared = policy_->Prepare(pi); },
                         [&] { ranking.reach = ReachFrom(pi.robot, frontier, settle_m); });
  pi.distances = distances ? &*ranking.reach.field : nullptr;
  pi.prepared = &ranking.prepared;
  RankSettled(ranking);
  if (use == RankFor::kAgainstCurrentGoal) {
    // Every candidate not ranked yet scores at most above_cost − settled_m:
    // settled so far that it can neither raise the current goal's score nor
    // beat it. Without a candidate near the goal yet, one may still come.
    while (ranking.above_cost_m) {
      const PathDistanceField& field = *ranking.reach.field;
      const std::optional<double> current = ScoreNear(ranking.candidates, *pi.current_goal);
      const double needed_m =
          current ? *ranking.above_cost_m - *current + kScoreSlack : 2.0 * field.settled_m();
      if (current && field.settled_m() >= needed_m) break;
      ranking.reach.field->SettleUpTo(std::max(needed_m, field.settled_m() + kFirstSettle_m));
      RankSettled(ranking);
    }
  }
}

void GoalManager::RankSettled(Ranking& ranking) {
  ranking.candidates.clear();
  for (const GoalCandidate& c : policy_->Rank(ranking.input)) {
    if (!failed_.IsNear(c.position, ranking.blacklisted)) ranking.candidates.push_back(c);
  }
  const PathDistanceField* field = ranking.input.distances;
  if (field != nullptr && field->complete()) ranking.above_cost_m.reset();
  ranking.sure = ranking.candidates.size();
  if (ranking.above_cost_m) {
    // Best first: the candidates scoring more than any candidate beyond
    // settled_m can come first in the complete ranking too.
    const double beyond = *ranking.above_cost_m - field->settled_m() + kScoreSlack;
    ranking.sure = 0;
    while (ranking.sure < ranking.candidates.size() &&
           ranking.candidates[ranking.sure].score > beyond) {
      ++ranking.sure;
    }
  }
  candidates_.clear();
  for (const GoalCandidate& c : ranking.candidates) candidates_.push_back(c.position);
}

bool GoalManager::MoreCandidates(Ranking& ranking) {
  if (!ranking.above_cost_m) return false;
  PathDistanceField& field = *ranking.reach.field;
  // Far enough for the best candidate not sure yet, if one is ranked.
  double needed_m = 2.0 * field.settled_m();
  if (ranking.sure < ranking.candidates.size()) {
    needed_m = *ranking.above_cost_m - ranking.candidates[ranking.sure].score + 2.0 * kScoreSlack;
  }
  field.SettleUpTo(std::max(needed_m, field.settled_m() + kFirstSettle_m));
  RankSettled(ranking);
  return true;
}

GoalManager::Selection GoalManager::PlanFirst(
    const std::function<const GoalCandidate*(size_t)>& candidate_at, const ExploreInput& in,
    const StartRegion& start, bool fall_back) {
  Selection sel;
  sel.none_left = candidate_at(0) == nullptr;
  Selection contradicted;
  const std::vector<Eigen::Vector2d> returns = CheckedReturns(in);
  int attempts = 0;
  ReachableCells reachable;
  for (size_t i = 0; const GoalCandidate* next = candidate_at(i); ++i) {
    const GoalCandidate c = *next;
    if (attempts++ >= options_.max_plan_attempts) break;
    // A candidate near one that failed during this very loop shares its fate.
    if (failed_.IsNear(c.position, failed_.Blacklisted(in.submaps))) continue;
    std::optional<PlannedPath> path = planner_.Plan(*map_, start, c.position, reachable);
    if (!path) {
      ++counters_.goals_unreachable;
      failed_.RecordFailure(c.position, in.submaps, *map_);
      continue;
    }
    if (ContradictedByScan(*path, returns)) {
      ++counters_.goals_contradicted;
      if (!contradicted.goal) {
        contradicted.goal = c.position;
        contradicted.path = std::move(path);
        contradicted.score = c.score;
      }
      continue;
    }
    sel.goal = c.position;
    sel.path = std::move(path);
    sel.score = c.score;
    return sel;
  }
  if (fall_back && contradicted.goal) {
    sel.goal = contradicted.goal;
    sel.path = std::move(contradicted.path);
    sel.score = contradicted.score;
  }
  return sel;
}

double GoalManager::StandOffUnknownMarginM() const {
  return policy_->keeps_stand_off_from_unknown() ? options_.stand_off_unknown_margin_m : 0.0;
}

std::vector<Eigen::Vector2d> GoalManager::CheckedReturns(const ExploreInput& in) const {
  std::vector<Eigen::Vector2d> returns;
  if (options_.scan_check_radius_m <= 0.0 || in.obstacles == nullptr ||
      !policy_->checks_paths_against_scan()) {
    return returns;
  }
  returns.reserve(in.obstacles->size());
  for (const Eigen::Vector2d& q : *in.obstacles) returns.push_back(in.robot_pose * q);
  if (options_.scan_check_memory_s > 0.0 && in.scan_check_returns) {
    for (const Eigen::Vector2d& q : in.scan_check_returns()) returns.push_back(in.robot_pose * q);
  }
  return returns;
}

bool GoalManager::ContradictedByScan(const PlannedPath& path,
                                     const std::vector<Eigen::Vector2d>& returns) const {
  if (returns.empty()) return false;
  const std::vector<Eigen::Vector2d> driven =
      CutAtStandOff(*map_, path.points, options_.max_stand_off_m,
                    follower_.options().goal_tolerance_m, StandOffUnknownMarginM());
  return PathCrossesReturns(driven, returns, options_.scan_check_radius_m);
}

GoalManager::Selection GoalManager::SelectAndPlan(const ExploreInput& in) {
  ++counters_.selections;
  const std::vector<Eigen::Vector2d> frontier = FrontierInBoundary(*in.frontier);
  Ranking ranking;
  ReachAndRank(in, frontier, RankFor::kBestFirst, ranking);
  // The i-th candidate of the complete ranking: settle farther until it is
  // sure (or there is none).
  const auto candidate_at = [&](size_t i) -> const GoalCandidate* {
    while (i >= ranking.sure && MoreCandidates(ranking)) {
    }
    return i < ranking.sure ? &ranking.candidates[i] : nullptr;
  };
  return PlanFirst(candidate_at, in, *ranking.reach.start, /*fall_back=*/true);
}

void GoalManager::BeginDriving(const Eigen::Vector2d& goal, const PlannedPath& path,
                               const ExploreInput& in, ExploreState state, bool new_goal,
                               double score) {
  goal_ = Anchor(goal, in.submaps);
  // Home is where the robot stood: no stand-off needed.
  std::vector<Eigen::Vector2d> points =
      state == ExploreState::kDriving
          ? CutAtStandOff(*map_, path.points, options_.max_stand_off_m,
                          follower_.options().goal_tolerance_m, StandOffUnknownMarginM())
          : path.points;
  const double length_m = PolylineLength(points);
  follower_.SetPath(std::move(points));
  if (new_goal || length_m < best_remaining_m_) best_remaining_m_ = length_m;
  last_replan_s_ = in.time_s;
  if (new_goal) {
    last_progress_s_ = in.time_s;
    // A centroid goal (baselines) may lie off the frontier: the goal stays
    // valid while the frontier is no farther than when it was chosen.
    goal_frontier_reach_m_ = DistanceToFrontier(goal, FrontierInBoundary(*in.frontier)) +
                             options_.goal_frontier_radius_m;
    if (state == ExploreState::kDriving) {
      ++counters_.goals_issued;
      CloseGoalRecord(GoalOutcome::kSuperseded);
      goal_log_.push_back({in.time_s, goal, score, length_m});
    }
  }
  state_ = state;
}

void GoalManager::CloseGoalRecord(GoalOutcome outcome) {
  if (goal_log_.empty() || goal_log_.back().outcome != GoalOutcome::kOpen) return;
  goal_log_.back().outcome = outcome;
  goal_log_.back().ended_s = now_s_;
}

void GoalManager::EndGoal(ExploreState next, GoalOutcome outcome) {
  if (goal_ && state_ != ExploreState::kReturning) CloseGoalRecord(outcome);
  moving_since_.reset();
  backing_up_since_.reset();
  retracing_since_.reset();
  goal_.reset();
  follower_.Clear();
  state_ = next;
  need_selection_ = true;
}

void GoalManager::Plan(const ExploreInput& in) {
  RefreshMap(in);
  if (!need_selection_) return;  // nothing changed since the last empty selection
  Selection sel = SelectAndPlan(in);
  if (sel.goal) {
    empty_since_s_.reset();
    BeginDriving(*sel.goal, *sel.path, in, ExploreState::kDriving, /*new_goal=*/true, sel.score);
    return;
  }
  // Candidates left whose plans were not tried yet: go on next cycle.
  need_selection_ = !sel.none_left;
  if (!sel.none_left) empty_since_s_.reset();
}

void GoalManager::FinishOrGoHome(const ExploreInput& in, ExploreStatus& status) {
  if (!empty_since_s_) empty_since_s_ = in.time_s;
  frontier_left_ = static_cast<int>(FrontierInBoundary(*in.frontier).size());
  const double wait_s =
      frontier_left_ > 0 ? options_.finish_with_frontier_after_s : options_.finish_after_empty_s;
  if (in.time_s - *empty_since_s_ < wait_s) {
    // Unreached frontier may only need a fresh look (a 180 degree lidar sees
    // half of the robot's surroundings): turn on the spot while waiting.
    if (frontier_left_ > 0)
      status.command.angular_radps = follower_.options().max_angular_speed_radps;
    return;
  }
  visited_frontier_left_ = 0;
  reachable_frontier_left_points_.clear();
  if (frontier_left_ > 0) {
    const StartRegion start(*map_, in.robot_pose.translation());
    const PathDistanceField field(*map_, start);
    const std::vector<Eigen::Vector2d> visited = visited_.Blacklisted(in.submaps);
    for (const Eigen::Vector2d& p : FrontierInBoundary(*in.frontier)) {
      if (!field.NearestReached(p, map_->options().goal_snap_radius_m)) continue;
      if (visited_.IsNear(p, visited)) {
        ++visited_frontier_left_;
      } else {
        reachable_frontier_left_points_.push_back(p);
      }
    }
  }
  // Frontier a plan reaches now, next to goals that failed when the map was
  // different: the change since may be too small for the retry rule (office
  // seed 2: a pocket whose entrance opened by a few cells). One more try
  // before giving up; each failure counts, so this ends at max_failures.
  if (const int lifted = failed_.RetryNear(reachable_frontier_left_points_, in.submaps)) {
    counters_.goals_retried += lifted;
    reachable_frontier_left_points_.clear();
    visited_frontier_left_ = 0;
    empty_since_s_.reset();
    need_selection_ = true;
    return;
  }
  if (options_.return_to_start && home_) {
    const Eigen::Vector2d home = Resolve(*home_, in.submaps);
    if ((home - in.robot_pose.translation()).norm() <= follower_.options().goal_tolerance_m) {
      returned_home_ = true;
    } else if (auto path = planner_.Plan(*map_, in.robot_pose.translation(), home)) {
      BeginDriving(home, *path, in, ExploreState::kReturning, /*new_goal=*/true);
      return;
    }
  }
  EndGoal(ExploreState::kFinished, GoalOutcome::kOpen);
}

void GoalManager::ReplanHome(const ExploreInput& in) {
  // Home moves with its submap; a failed re-plan keeps the old path.
  const Eigen::Vector2d home = Resolve(*home_, in.submaps);
  if (auto path = planner_.Plan(*map_, in.robot_pose.translation(), home)) {
    BeginDriving(home, *path, in, state_, /*new_goal=*/false);
  }
}

void GoalManager::Replan(const ExploreInput& in) {
  RefreshMap(in);
  last_replan_s_ = in.time_s;
  if (state_ == ExploreState::kReturning) return ReplanHome(in);
  const Eigen::Vector2d current = Resolve(*goal_, in.submaps);
  const std::vector<Eigen::Vector2d> frontier = FrontierInBoundary(*in.frontier);
  if (DistanceToFrontier(current, frontier) > goal_frontier_reach_m_) {
    // Seen on the way: the goal did its job.
    ++counters_.goals_seen;
    visited_.RecordFailure(current, in.submaps, *map_);
    return EndGoal(ExploreState::kPlanning, GoalOutcome::kSeen);
  }
  ++counters_.selections;
  Ranking ranking;
  ReachAndRank(in, frontier, RankFor::kAgainstCurrentGoal, ranking);
  const std::vector<GoalCandidate>& ranked = ranking.candidates;
  // The current goal's score: its component's best candidate.
  const std::optional<double> current_score = ScoreNear(ranked, current);
  const double match2 = options_.goal_match_radius_m * options_.goal_match_radius_m;
  if (current_score) {
    std::vector<GoalCandidate> better;
    for (const GoalCandidate& c : ranked) {
      if (c.score > *current_score + options_.goal_switch_margin &&
          (c.position - current).squaredNorm() > match2) {
        better.push_back(c);
      }
    }
    if (!better.empty()) {
      // Only for a way the scan does not contradict.
      const auto better_at = [&](size_t i) { return i < better.size() ? &better[i] : nullptr; };
      Selection sel = PlanFirst(better_at, in, *ranking.reach.start, /*fall_back=*/false);
      if (sel.goal) {
        ++counters_.goals_superseded;
        return BeginDriving(*sel.goal, *sel.path, in, ExploreState::kDriving, /*new_goal=*/true,
                            sel.score);
      }
    }
  }
  // Keep the goal; only its path changes with the map.
  if (std::optional<PlannedPath> path = planner_.Plan(*map_, *ranking.reach.start, current)) {
    return BeginDriving(current, *path, in, ExploreState::kDriving, /*new_goal=*/false);
  }
  if (map_->NearestTraversable(current, map_->options().goal_snap_radius_m)) {
    // The map now blocks every way there.
    ++counters_.goals_unreachable;
    failed_.RecordFailure(current, in.submaps, *map_);
    return EndGoal(ExploreState::kPlanning, GoalOutcome::kUnreachable);
  }
  // A wall seen next to the goal put it in the band: its frontier is
  // still there, so the next selection offers a reachable point of it.
  ++counters_.goals_dropped;
  EndGoal(ExploreState::kPlanning, GoalOutcome::kDropped);
}

void GoalManager::FailGoal(const ExploreInput& in) {
  // Failing the way home ends exploration; a failed goal is remembered.
  if (state_ == ExploreState::kReturning) {
    EndGoal(ExploreState::kFinished, GoalOutcome::kFailed);
    return;
  }
  ++counters_.goals_failed;
  failed_.RecordFailure(Resolve(*goal_, in.submaps), in.submaps, *map_);
  EndGoal(ExploreState::kFailed, GoalOutcome::kFailed);
}

void GoalManager::Drive(const ExploreInput& in, ExploreStatus& status) {
  const Eigen::Vector2d here = in.robot_pose.translation();
  if (backing_up_since_) {
    const auto [since_s, from] = *backing_up_since_;
    VelocityCommand back{-options_.back_up_speed_mps, 0.0};
    const bool blocked = BlockedBehind(in.robot_pose) || GuardRear(in, &back);
    counters_.back_ups_blocked += blocked;
    if (blocked || (here - from).norm() >= options_.back_up_distance_m ||
        in.time_s - since_s >= options_.back_up_timeout_s) {
      backing_up_since_.reset();
      return EndRecovery(in, from);
    }
    status.command = back;
    return;
  }
  if (retracing_since_) return Retrace(in, status);
  // Backing up and retracing add nothing: recoveries in a row do not add up.
  trail_.Record(here, options_.back_up_trail_m);
  retrace_trail_.Record(here, options_.retrace_m);
  if (map_dirty_ && in.time_s - last_replan_s_ >= options_.replan_interval_s) {
    Replan(in);
    if (state_ != ExploreState::kDriving && state_ != ExploreState::kReturning) return;
  }
  const bool returning = state_ == ExploreState::kReturning;
  const FollowStatus fs = follower_.Update(in.robot_pose);
  if (fs.reached) {
    if (returning) {
      returned_home_ = true;
      EndGoal(ExploreState::kFinished, GoalOutcome::kReached);
    } else {
      ++counters_.goals_reached;
      visited_.RecordFailure(Resolve(*goal_, in.submaps), in.submaps, *map_);
      EndGoal(ExploreState::kReached, GoalOutcome::kReached);
    }
    return;
  }
  if (fs.remaining_m < best_remaining_m_ - options_.progress_min_m) {
    best_remaining_m_ = fs.remaining_m;
    last_progress_s_ = in.time_s;
  }
  if (in.time_s - last_progress_s_ > options_.progress_timeout_s) {
    FailGoal(in);
    return;
  }
  status.command = fs.command;
  const bool forward = status.command.linear_mps > 0.0;
  Guard(in, &status.command);
  // Commanded forward without moving (stuck against something, or held by
  // the guard while turning does not clear the way).
  if (StuckAfterMotion(forward, in)) {
    ++counters_.recoveries;
    status.command = {};
    // Stuck again where the last back-up began: backing up did not help.
    const bool again =
        last_stuck_at_ && (here - *last_stuck_at_).norm() <= options_.back_up_distance_m;
    last_stuck_at_ = here;
    VelocityCommand back{-options_.back_up_speed_mps, 0.0};
    const bool blocked = BlockedBehind(in.robot_pose) || GuardRear(in, &back);
    if ((blocked || again) && StartRetrace(in)) return;
    if (!blocked) status.command = back;
    backing_up_since_ = {in.time_s, here};
  }
}

ExploreStatus GoalManager::Update(const ExploreInput& in) {
  if (!in.map || !in.frontier) throw std::invalid_argument("GoalManager::Update: no map/frontier");
  now_s_ = in.time_s;
  if (in.map_changed) {
    map_dirty_ = true;
    need_selection_ = true;
  }
  ExploreStatus status;
  if (state_ != ExploreState::kIdle && state_ != ExploreState::kFinished) {
    if (!home_) home_ = Anchor(in.robot_pose.translation(), in.submaps);
    if (state_ == ExploreState::kReached || state_ == ExploreState::kFailed) {
      state_ = ExploreState::kPlanning;
    }
    if (state_ == ExploreState::kPlanning) {
      Plan(in);
      if (state_ == ExploreState::kPlanning && !need_selection_) FinishOrGoHome(in, status);
    }
    if (state_ == ExploreState::kDriving || state_ == ExploreState::kReturning) {
      frontier_left_ = 0;
      Drive(in, status);
    }
  }
  status.state = state_;
  if (goal_) status.goal = Resolve(*goal_, in.submaps);
  if (follower_.has_path()) status.target = follower_.path().back();
  if (follower_.has_path()) status.path = follower_.path();
  status.blacklisted = failed_.Blacklisted(in.submaps);
  status.candidates = candidates_;
  status.frontier_left = frontier_left_;
  status.reachable_frontier_left = static_cast<int>(reachable_frontier_left_points_.size());
  status.reachable_frontier_left_points = reachable_frontier_left_points_;
  status.visited_frontier_left = visited_frontier_left_;
  status.returned_home = returned_home_;
  return status;
}

}  // namespace scout::explore
