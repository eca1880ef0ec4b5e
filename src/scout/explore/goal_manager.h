#ifndef SCOUT_EXPLORE_GOAL_MANAGER_H_
#define SCOUT_EXPLORE_GOAL_MANAGER_H_

#include <Eigen/Core>
#include <any>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "scout/explore/anchored_point.h"
#include "scout/explore/collision_guard.h"
#include "scout/explore/failed_goal_memory.h"
#include "scout/explore/goal_policies.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/path_follower.h"
#include "scout/explore/path_planner.h"
#include "scout/explore/planning_map.h"
#include "scout/explore/start_region.h"
#include "scout/explore/trail.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore {

struct GoalManagerOptions {
  // A goal fails when the remaining path length has not shrunk by
  // progress_min_m within progress_timeout_s (explore_lite's 30 s).
  double progress_timeout_s = 30.0;
  double progress_min_m = 0.25;
  // While driving, a map change re-plans the path to the kept goal (and
  // checks whether a clearly better goal appeared), at most this often.
  double replan_interval_s = 1.0;
  // The goal is kept until reached, failed, or no frontier point is left
  // within this radius of it (metres): then its frontier has been seen.
  double goal_frontier_radius_m = 0.5;
  // Another goal replaces the current one only when its score beats the
  // current goal's by more than this (the policy's units; metres of path for
  // scout): a marginally better point must not make the robot turn around.
  // The current goal's score is that of the best candidate within
  // goal_match_radius_m of it (a component's navigation point moves with the
  // robot); without one the goal is simply kept.
  double goal_switch_margin = 5.0;
  double goal_match_radius_m = 1.5;
  // Candidates planned to per selection before giving up until the next map
  // change (bounds the work when many baseline goals are unreachable).
  int max_plan_attempts = 10;
  // Exploration ends only after no goal was left for this long; at the start
  // the map may simply not have arrived yet.
  double finish_after_empty_s = 2.0;
  // With frontier points left but none reachable, the robot turns on the spot
  // (refreshing the map around it) for this long before it gives up.
  double finish_with_frontier_after_s = 10.0;
  // Recovery: when the robot is commanded forward but has not moved
  // stuck_min_motion_m for stuck_timeout_s (pressed against an obstacle the
  // map places elsewhere; a blocked arc stops turning too), it backs up
  // back_up_distance_m at back_up_speed_mps (at most back_up_timeout_s). In
  // willow-garage the robot otherwise stayed pressed against a door post for
  // the last 250 s of its run. The first time for a goal, the goal is
  // selected afresh (the passage there is closed, see below): where the
  // robot got stuck need not say anything about the goal. Office seed 3 got
  // stuck next to the goal it had just reached, 16 m from the next one, and
  // failing that one left the frontier behind a desk unexplored. The second
  // time (a goal within failed_goals.blacklist_radius_m of one it got stuck
  // on before) the goal fails. A stuck_timeout_s of 0 turns the recovery off.
  double stuck_timeout_s = 3.0;
  double stuck_min_motion_m = 0.05;
  double back_up_distance_m = 0.3;
  double back_up_speed_mps = 0.15;
  double back_up_timeout_s = 4.0;
  // The lidar sees only ahead: backing up stops early when the map holds an
  // occupied cell behind the robot (rear half) within its radius of the path
  // the next back_up_look_behind_m would sweep, closer than any mapped
  // obstacle is now (a disc the map already has on a wall may back along
  // it). Only as good as the map: office seed 3's nearest-frontier run still
  // backs into a wall its map placed 0.2 m too far (one collision; see
  // back_up_trail_m). 0: blind, which also turns the trail check off.
  double back_up_look_behind_m = 0.10;
  // Backing up also stops before the next back_up_look_behind_m would take
  // the disc's centre farther than back_up_trail_tolerance_m from the path
  // it drove (other than backing up) in its last back_up_trail_m of travel:
  // the disc fit there in the world, while the map behind it can be wrong
  // (office seed 3's nearest-frontier run had turned round and backed twice,
  // 0.45 m, into a wall its map placed 0.2 m too far). Back-ups in a row
  // therefore do not add up. 0 trail (the default): anywhere the map allows.
  // Off by default until every world's runs are redone with it: on the
  // office it removed that collision, but seed 5 of Scout's own policy then
  // ended with coverage 0.978 (ATE 0.268 m: another trajectory, another
  // SLAM drift) where it had 1.000.
  double back_up_trail_m = 0.0;
  double back_up_trail_tolerance_m = 0.3;
  // When the robot gets stuck and cannot back up (something mapped or seen
  // right behind it), or gets stuck again within back_up_distance_m of where
  // it last got stuck (backing up did not help), it drives back along the
  // way it came instead: the last retrace_m metres it drove (backing up and
  // retracing add nothing), turning round first and with the guard on; then
  // the goal is selected afresh or fails as after a back-up. The disc fit
  // along that way in the world. Office seed 13 otherwise stood in a pocket
  // between a desk and a wall from 820 s to the end (no_progress at coverage
  // 0.868): facing the way out, with every arc it could steer passing a
  // corner closer than the guard allows, and the wall behind it; with 2 m it
  // completes. 0 (the default): off. Off until the evaluation is made with
  // it: it changes every run with a blocked back-up or a second recovery at
  // one place, and on office seeds 1-14 it traded seed 13's deadlock for two
  // runs whose SLAM drifted on their new trajectories (docs/EXPERIMENTS.md).
  double retrace_m = 0.0;
  // The collision guard's clearance while retracing, if smaller than its
  // own (guard.clearance_m): that way was driven, so only what the lidar
  // sees on it now should stop the robot. With the guard's 3 cm the robot
  // did not leave office seed 13's pocket, a few mm closer to a corner on
  // the way out than it had been on the way in.
  double retrace_clearance_m = 0.01;
  // The last resort before a run ends no_progress (ExplorationLoop: its map
  // has not grown for the no-progress timeout) when the robot stood confined
  // in that time (its estimated poses over at least last_resort_confined_s
  // all within last_resort_confined_radius_m of one place). If it still
  // stands there, the goal it has fails, it drives back the way it came (its
  // SLAM trajectory, loops erased: WayBack) until it stands
  // last_resort_retrace_m away in a straight line, as a retrace (clearance
  // retrace_clearance_m), closes the passage behind it as after a back-up,
  // and selects afresh. If it got out by itself, it goes on. Either way the
  // no-progress clock starts again; at most max_last_resorts times per run. A
  // run that never reaches the timer is not changed by it. Office seed 13
  // stood in a pocket between a desk and a wall from 820 s and ended
  // no_progress at 0.869; with this it leaves at 1300 s. Willow-garage seed 7
  // got out of its corner by itself 8 s before the timer ended it at 0.702
  // (docs/EXPERIMENTS.md). 0: off.
  double last_resort_retrace_m = 2.0;
  double last_resort_confined_radius_m = 1.0;
  double last_resort_confined_s = 60.0;
  int max_last_resorts = 2;
  // Where the robot got stuck (the back-up began), the narrow-passage cells
  // within this radius (metres) are closed to planning; they reopen, as
  // failed goals do, when the map around them changes (failed_goals' retry
  // options and max_failures). The map shows a passage there, but the
  // robot did not fit through it, and only the goal was blacklisted: the
  // next goal, just outside the blacklist radius, sends it the same way.
  // Office seed 3 (with the guard steering): 3 goals failed that way and
  // the run ended no_progress; with this, 2 failed and it completed. Cells
  // the robot has driven over stay open (ExploreInput::driven): without
  // that, seeds 3 and 5 closed themselves in and ended "complete" at
  // coverage 0.44 and 0.71. 0: off.
  double close_stuck_passage_radius_m = 0.5;
  // The robot is sent to the last point of the path, at most this far (path
  // metres) before a goal, where its disc covers known-free cells only and,
  // where there is such a point, outside narrow passages: a frontier point
  // may lie on the edge of unseen furniture, and a wall mapped a little off
  // leaves no room at a stop that keeps only the narrow margin (see
  // CutAtStandOff). 0 drives to the goal itself.
  double max_stand_off_m = 0.5;
  // For policies that ask for it (scout): that stop should also keep this
  // much (metres) from unknown space beyond the robot's disc, where a point
  // within max_stand_off_m does (see CutAtStandOff; museum seed 3 at
  // 3559 s). 0: off, the default until the evaluation is made with it: at
  // 0.1, office seeds 1-13 ended no_progress twice (4 and 10) against once
  // (13) without (docs/EXPERIMENTS.md).
  double stand_off_unknown_margin_m = 0.0;
  // For policies that ask for it (scout): a candidate whose path (to its
  // stand-off point) passes within this distance (metres) of a return of
  // the latest scan (ExploreInput::obstacles) is passed over for the next
  // one whose path does not, among the max_plan_attempts planned; when
  // every one of those is contradicted, the first is taken as before. The
  // lidar sees a wall where the map, fused from submaps a loop closure may
  // have left misplaced, shows a way (see PathCrossesReturns; museum seed
  // 1 at 1812 s). It only reorders: where local SLAM holds the robot's
  // pose off, the scan contradicts every way out (office seed 2 at 1132 s,
  // returns 0.5 m ahead 0.3 m from the mapped wall), and refusing them all
  // stranded the robot and cost that run its map (docs/EXPERIMENTS.md).
  // Paths keep at least the narrow margin plus the robot radius from
  // mapped walls, so walls mapped within that minus this of where the
  // lidar sees them pass. 0: off.
  double scan_check_radius_m = 0.15;
  // The scan check also uses the returns of the scans of the last this many
  // seconds of moving time (ExploreInput::scan_check_returns): a 180 degree
  // lidar does not see the face of a block beside or behind the robot that
  // it saw a few seconds before, and a path round the end of the edge the
  // latest scan saw can run into it (museum seed 1 at 2898 s). 0: the
  // latest scan only.
  double scan_check_memory_s = 10.0;
  // Forward commands are checked against the latest scan (ExploreInput::
  // obstacles): see CollisionGuardOptions.
  CollisionGuardOptions guard;
  // After exploring, drive back to where Start() was called.
  bool return_to_start = false;
  // Optional exploration area: a simple polygon in the global frame (at least
  // three vertices); frontier points outside it are ignored. Empty: no limit.
  std::vector<Eigen::Vector2d> boundary;
  FailedGoalOptions failed_goals;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const GoalManagerOptions& options);

enum class ExploreState {
  kIdle,       // not started, or stopped: commands are zero
  kPlanning,   // choosing a goal and planning to it
  kDriving,    // following the path to the goal
  kReached,    // the goal was reached (one update; then kPlanning)
  kFailed,     // the goal failed (one update; then kPlanning)
  kReturning,  // driving back to the start
  kFinished,   // nothing left to explore (and back home, if asked)
};
std::string_view ToString(ExploreState state);

// One control cycle's view of the world.
struct ExploreInput {
  double time_s = 0.0;
  geometry::Rigid2d robot_pose;  // global frame
  // The fused global map and the global frontier points (global frame).
  const grid::OccupancyMap* map = nullptr;
  const std::vector<Eigen::Vector2d>* frontier = nullptr;
  // Current global poses of the submaps (empty: goals are kept globally).
  std::vector<SubmapPose> submaps;
  // The robot's trajectory so far (global positions, oldest first): where it
  // has driven stays passable (TraversabilityOptions::driven_width_m). Read
  // when the map changed; null: none.
  const std::vector<Eigen::Vector2d>* driven = nullptr;
  // The latest scan's returns in the robot frame (metres), for the collision
  // guard; null: no guard.
  const std::vector<Eigen::Vector2d>* obstacles = nullptr;
  // The base's velocity now and its limits, for the guard's predict_motion;
  // empty: the commanded arc alone is checked.
  std::optional<BaseMotion> base;
  // The returns of the recent scans (ScanMemory) in the robot frame, asked
  // for only when backing up (CollisionGuardOptions::memory_s); empty: the
  // map alone is checked behind the robot.
  std::function<std::vector<Eigen::Vector2d>()> recent_returns;
  // The returns of the scans of the last GoalManagerOptions::
  // scan_check_memory_s seconds in the robot frame, for the scan check,
  // asked for only when it runs; empty: the latest scan alone.
  std::function<std::vector<Eigen::Vector2d>()> scan_check_returns;
  // True when the map or the frontier changed since the previous update.
  bool map_changed = false;
};

struct ExploreCounters {
  int goals_issued = 0;
  int goals_reached = 0;       // the robot arrived within the goal tolerance
  int goals_seen = 0;          // its frontier was seen before the robot arrived
  int goals_failed = 0;        // progress timeout
  int goals_unreachable = 0;   // no plan
  int goals_superseded = 0;    // a clearly better goal replaced it on the way
  int goals_dropped = 0;       // the map put it inside the inflated band
  int goals_contradicted = 0;  // passed over: its path crossed what the latest scan sees
  int goals_retried = 0;       // lifted from the blacklist after a map change
  int selections = 0;
  int escapes = 0;             // searches that started by leaving the band or a pocket
  int recoveries = 0;          // back-ups after the robot got stuck (closing its passage)
  int stuck_reselections = 0;  // ... after which the goal was selected afresh, not failed
  int back_ups_blocked = 0;  // ... that stopped early (a mapped obstacle behind, or off the trail)
  int retraces = 0;          // ... that drove back the way it came instead (retrace_m)
  int last_resorts = 0;      // before no_progress: drives back, or going on (last_resort_*)
  int guard_stops = 0;       // the collision guard stopped a forward command
  int guard_steers = 0;      // control cycles it steered another arc instead
};

// How an issued goal ended.
enum class GoalOutcome {
  kOpen,         // still the goal (or the exploration ended with it)
  kReached,      // the robot arrived within the goal tolerance
  kSeen,         // its frontier was seen before the robot arrived
  kFailed,       // no progress in time, or stuck on it twice, or a last resort
  kUnreachable,  // the map came to block every way there
  kSuperseded,   // a clearly better goal replaced it on the way
  kDropped,      // the map put it inside the inflated band
  kStuck,        // the robot got stuck on the way and selected afresh
  kStopped,      // Stop() dropped it
};
std::string_view ToString(GoalOutcome outcome);

// A goal the goal manager issued (global frame, as when issued): why the
// robot drove where it did, for a user reading a run.
struct GoalRecord {
  double issued_s = 0.0;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
  // The policy's score when chosen, higher is better (Scout's: revenue,
  // info_multiplier × m² − path metres; nearest: −distance; explore-lite:
  // −cost).
  double score = std::numeric_limits<double>::quiet_NaN();
  // Length of the path planned then, to the stand-off point (metres).
  double path_m = 0.0;
  double ended_s = std::numeric_limits<double>::quiet_NaN();
  GoalOutcome outcome = GoalOutcome::kOpen;
};

struct ExploreStatus {
  ExploreState state = ExploreState::kIdle;
  VelocityCommand command;
  std::optional<Eigen::Vector2d> goal;  // global
  // Where the robot's centre is sent (global): the goal, or the stand-off
  // point before it (GoalManagerOptions::max_stand_off_m).
  std::optional<Eigen::Vector2d> target;
  std::vector<Eigen::Vector2d> path;  // global, for display
  std::vector<Eigen::Vector2d> blacklisted;
  // The goal candidates of the latest selection, best first (global): those
  // ranked so far, as path distances are settled only as far as the
  // selection or re-ranking needed them.
  std::vector<Eigen::Vector2d> candidates;
  // Frontier points (inside the boundary) left when no goal was: nonzero in
  // kFinished means exploration gave up on them rather than completed.
  int frontier_left = 0;
  // Of those, the ones a plan from the robot reaches (within the goal snap
  // radius) when it finished and that no goal the robot reached lies near
  // (within the failed-goal blacklist radius): more than zero means it gave
  // up on them.
  int reachable_frontier_left = 0;
  // Where those are (global frame), so a user can find what it gave up on.
  std::vector<Eigen::Vector2d> reachable_frontier_left_points;
  // The reachable ones near a goal the robot reached: it went there, looked,
  // and they stayed (the unknown beyond cannot be seen from where the robot
  // fits, e.g. a gap behind furniture).
  int visited_frontier_left = 0;
  bool returned_home = false;
};

// The exploration state machine: IDLE → PLANNING → DRIVING → REACHED/FAILED →
// PLANNING …, FINISHED when no goal is left (optionally via RETURNING).
// Owns the policy, the planner and the follower; the caller owns SLAM and
// the frontier, and applies the velocity commands.
class GoalManager {
 public:
  // Throws std::invalid_argument on bad options or a null policy.
  GoalManager(const GoalManagerOptions& options, const TraversabilityOptions& traversability,
              const PathPlannerOptions& planner, const PathFollowerOptions& follower,
              std::unique_ptr<GoalPolicy> policy);

  // Starts (or resumes) exploring at the next update; the first update after
  // the first Start() records home.
  void Start();
  // Stops: drops the goal and commands zero velocity until Start().
  void Stop();

  // Advances the state machine and returns the command for this cycle.
  ExploreStatus Update(const ExploreInput& input);
  // The last resort (GoalManagerOptions::last_resort_retrace_m), for a robot
  // its caller found confined with no progress. With 'drive_back' (it still
  // stands where it was confined): true when the drive back began
  // (input.driven holds the way); false when the robot is idle, finished or
  // returning home, or no driven point is that far away. Without (it got out
  // by itself), or while a back-up or drive back is under way: true, counted,
  // and nothing else changes. False when off or used up.
  bool LastResort(const ExploreInput& input, bool drive_back = true);

  ExploreState state() const { return state_; }
  const ExploreCounters& counters() const { return counters_; }
  // Every goal issued so far, oldest first (not the way home).
  const std::vector<GoalRecord>& goal_log() const { return goal_log_; }
  const FailedGoalMemory& failed_goals() const { return failed_; }
  const GoalPolicy& policy() const { return *policy_; }

 private:
  struct Selection {
    std::optional<Eigen::Vector2d> goal;
    std::optional<PlannedPath> path;
    double score = std::numeric_limits<double>::quiet_NaN();
    // No candidate outside the blacklist (as opposed to: plans failed).
    bool none_left = true;
  };
  // Where searches start this cycle, with the path distances from there.
  struct Reach {
    std::optional<StartRegion> start;
    std::optional<PathDistanceField> field;
  };
  // Builds the planning map when the map changed (or none exists yet) and
  // lifts the blacklisting of goals whose surroundings changed.
  void RefreshMap(const ExploreInput& input);
  // Starts at the robot (leaving the band if it stands in it); when no
  // frontier point is reachable from there the robot is boxed in, and the
  // search escapes even from a traversable cell. The field is settled to
  // 'settle_m' at least, and further until it reaches a frontier point (or
  // every cell).
  Reach ReachFrom(const Eigen::Vector2d& robot, const std::vector<Eigen::Vector2d>& frontier,
                  double settle_m);
  // ReachFrom the robot, and the policy's candidates that are not
  // blacklisted, best first. The policy's work that needs no path distances
  // runs on another thread while ReachFrom computes them.
  //
  // In the museum the complete path distance field (millions of cells, at
  // every re-ranking, once per second while driving) took half of a run's
  // wall time, so the field is settled only as far as the use needs, for
  // policies whose scores fall with path cost (ScoreAbovePathCost; a
  // candidate beyond a path distance L scores below that bound minus L):
  // - kBestFirst (goal selection): candidates[0, sure) are the complete
  //   ranking's first ones, and MoreCandidates settles farther for more;
  // - kAgainstCurrentGoal (re-ranking while driving): the candidates that can
  //   score more than the current goal's score (its best candidate within
  //   goal_match_radius_m), and that score, are there.
  // The baselines get no field (they rank without path distances). The
  // results are those of the complete field, decision for decision.
  enum class RankFor { kBestFirst, kAgainstCurrentGoal };
  struct Ranking {
    Reach reach;
    std::vector<GoalCandidate> candidates;
    size_t sure = 0;
    // What ranking again needs (PolicyInput points into it: not movable).
    PolicyInput input;
    std::vector<Eigen::Vector2d> blacklisted;
    std::any prepared;
    std::optional<double> above_cost_m;  // set while the field may be partial
    Ranking() = default;
    Ranking(const Ranking&) = delete;
    Ranking& operator=(const Ranking&) = delete;
  };
  void ReachAndRank(const ExploreInput& input, const std::vector<Eigen::Vector2d>& frontier,
                    RankFor use, Ranking& ranking);
  // Ranks from the field as settled now (and updates sure).
  void RankSettled(Ranking& ranking);
  // Settles the field farther, to make the next candidate sure, and ranks
  // again; false when it was complete.
  bool MoreCandidates(Ranking& ranking);
  // The best score of the candidates within goal_match_radius_m of 'goal'.
  std::optional<double> ScoreNear(const std::vector<GoalCandidate>& ranked,
                                  const Eigen::Vector2d& goal) const;
  // Plans to the candidates in order (at most max_plan_attempts) and returns
  // the first with a plan that the latest scan does not contradict (scan
  // check), or else, with 'fall_back', the first with a plan; candidates
  // without one are blacklisted. candidate_at(i) is the i-th candidate, null
  // after the last.
  Selection PlanFirst(const std::function<const GoalCandidate*(size_t)>& candidate_at,
                      const ExploreInput& input, const StartRegion& start, bool fall_back);
  // The first extent of a partial path distance field (metres), and the
  // factor on the straight distance to the goal that the first extent of a
  // re-ranking allows for the path's detours (more is settled when needed).
  static constexpr double kFirstSettle_m = 2.0;
  static constexpr double kDetourFactor = 1.5;
  // Scores summed in another order may differ in the last bits.
  static constexpr double kScoreSlack = 1e-6;
  // stand_off_unknown_margin_m for a policy that keeps it, else 0.
  double StandOffUnknownMarginM() const;
  // The latest scan's returns in the global frame when the scan check is on
  // for the policy (scan_check_radius_m > 0 and a scan given); else none.
  std::vector<Eigen::Vector2d> CheckedReturns(const ExploreInput& input) const;
  // True when the part of 'path' the robot would drive (to its stand-off
  // point) passes within scan_check_radius_m of one of 'returns' (global).
  bool ContradictedByScan(const PlannedPath& path,
                          const std::vector<Eigen::Vector2d>& returns) const;
  // Returns the best goal that is not blacklisted and has a plan.
  Selection SelectAndPlan(const ExploreInput& input);
  // Anchors the goal and hands its path to the follower. A re-plan to the
  // same goal keeps the progress clock running. A new goal while driving
  // ends the current one as superseded; 'score' is the new goal's.
  void BeginDriving(const Eigen::Vector2d& goal, const PlannedPath& path, const ExploreInput& in,
                    ExploreState state, bool new_goal,
                    double score = std::numeric_limits<double>::quiet_NaN());
  // Drops the goal (or the way home); an issued goal still open in the log
  // ends with 'outcome'.
  void EndGoal(ExploreState next, GoalOutcome outcome);
  void CloseGoalRecord(GoalOutcome outcome);
  // PLANNING: select and plan when something changed.
  void Plan(const ExploreInput& input);
  // No goal left: after finish_after_empty_s (longer, turning on the spot,
  // when frontier points remain), return home or finish.
  void FinishOrGoHome(const ExploreInput& input, ExploreStatus& status);
  // DRIVING/RETURNING after a map change: keep the goal while it is still a
  // frontier, switch only for a clearly better one, re-plan the path.
  void Replan(const ExploreInput& input);
  void ReplanHome(const ExploreInput& input);
  // DRIVING/RETURNING: follow, watch progress.
  // Ends the current goal as failed (or the way home as finished).
  void FailGoal(const ExploreInput& in);
  // After backing up: fails the goal if the robot got stuck on it before,
  // otherwise ends it for a fresh selection.
  void EndStuckGoal(const ExploreInput& in);
  // True when the map shows an occupied cell behind 'pose' (rear half-plane)
  // within the robot radius of the segment back_up_look_behind_m behind it
  // and closer to it than any occupied cell is to the robot now.
  // Also true when the same segment leaves the recent trail (back_up_trail_m).
  bool BlockedBehind(const geometry::Rigid2d& pose) const;
  // Limits the backward 'command' by the recent scans (GuardBackward); true
  // when that stops it.
  bool GuardRear(const ExploreInput& in, VelocityCommand* command) const;
  // True when a centre on the segment back_up_look_behind_m behind 'pose' is
  // farther than back_up_trail_tolerance_m from trail_; false without a trail.
  bool OffTrail(const geometry::Rigid2d& pose) const;
  // Starts driving back along retrace_trail_ when it is long enough; false
  // otherwise.
  bool StartRetrace(const ExploreInput& in);
  // Follows 'way' (starting at the robot) as a retrace (Retrace), from now.
  void BeginDriveBack(const ExploreInput& in, std::vector<Eigen::Vector2d> way);
  // Follows the retrace in progress; ends it (as a back-up ends) at its end
  // or when the robot gets stuck on it.
  void Retrace(const ExploreInput& in, ExploreStatus& status);
  // Tracks where and when the robot last moved stuck_min_motion_m while
  // commanded 'forward' (moving_since_; reset when not forward); true once it
  // has been commanded forward without moving that far for stuck_timeout_s.
  bool StuckAfterMotion(bool forward, const ExploreInput& in);
  // True once moving_since_ is stuck_timeout_s old (a timeout of 0 never).
  bool StuckTimedOut(double time_s) const;
  // Checks a forward 'command' against the latest scan (options_.guard).
  void Guard(const ExploreInput& in, VelocityCommand* command,
             double clearance_m = std::numeric_limits<double>::infinity());
  // After a back-up or retrace that began at 'from': closes the passage
  // there and ends the goal (EndStuckGoal).
  void EndRecovery(const ExploreInput& in, const Eigen::Vector2d& from);
  void Drive(const ExploreInput& input, ExploreStatus& status);
  // Returns the distance from 'goal' to the nearest frontier point.
  static double DistanceToFrontier(const Eigen::Vector2d& goal,
                                   const std::vector<Eigen::Vector2d>& frontier);
  std::vector<Eigen::Vector2d> FrontierInBoundary(const std::vector<Eigen::Vector2d>& f) const;

  GoalManagerOptions options_;
  TraversabilityOptions traversability_;
  PathPlanner planner_;
  PathFollower follower_;
  std::unique_ptr<GoalPolicy> policy_;
  FailedGoalMemory failed_;
  // Reached goals, kept out of selection until the map around them changes.
  FailedGoalMemory visited_;
  // Where the robot got stuck: narrow passages closed there until the map
  // around them changes (close_stuck_passage_radius_m).
  FailedGoalMemory stuck_places_;
  // Goals the robot got stuck on once: the next time it fails them.
  std::vector<AnchoredPoint> stuck_goals_;

  ExploreState state_ = ExploreState::kIdle;
  bool started_once_ = false;
  std::optional<AnchoredPoint> home_;
  std::optional<AnchoredPoint> goal_;
  std::unique_ptr<PlanningMap> map_;
  bool map_dirty_ = true;
  // PLANNING selects only after a map change or a goal ended, not every cycle.
  bool need_selection_ = true;
  double last_replan_s_ = -1e300;
  double best_remaining_m_ = 0.0;
  double goal_frontier_reach_m_ = 0.0;
  double last_progress_s_ = 0.0;
  // Stuck detection: where and when the robot last moved while commanded
  // forward; and the back-up in progress, if any.
  std::optional<std::pair<double, Eigen::Vector2d>> moving_since_;
  std::optional<std::pair<double, Eigen::Vector2d>> backing_up_since_;
  // Where the robot drove recently other than backing up: the last
  // back_up_trail_m (trail_) and the last retrace_m (retrace_trail_, not
  // added to while retracing it).
  Trail trail_;
  Trail retrace_trail_;
  // Where the robot last got stuck, if ever.
  std::optional<Eigen::Vector2d> last_stuck_at_;
  // The retrace in progress, if any: when and where it began.
  std::optional<std::pair<double, Eigen::Vector2d>> retracing_since_;
  bool guard_stopped_ = false;
  std::optional<double> empty_since_s_;
  int frontier_left_ = 0;
  std::vector<Eigen::Vector2d> reachable_frontier_left_points_;
  int visited_frontier_left_ = 0;
  std::vector<Eigen::Vector2d> candidates_;
  bool returned_home_ = false;
  ExploreCounters counters_;
  std::vector<GoalRecord> goal_log_;
  double now_s_ = 0.0;  // the latest update's time
};

// True when 'p' lies inside the simple polygon (even-odd rule).
bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_GOAL_MANAGER_H_
