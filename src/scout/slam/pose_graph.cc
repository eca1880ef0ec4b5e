#include "scout/slam/pose_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "scout/common/format.h"
#include "scout/common/parallel.h"
#include "scout/slam/submap_chain.h"

namespace scout::slam {
namespace {

void RequirePositivePoseGraphOption(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("'slam.pose_graph.") + key +
                                "': expected a positive finite number, got " + FormatNumber(value));
  }
}

bool Contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

bool SameConstraint(const Constraint& a, const Constraint& b) {
  return a.submap_id == b.submap_id && a.node_id == b.node_id && a.kind == b.kind &&
         a.relative_pose.translation() == b.relative_pose.translation() &&
         a.relative_pose.theta() == b.relative_pose.theta();
}

bool Contains(const std::vector<Constraint>& list, const Constraint& c) {
  return std::any_of(list.begin(), list.end(),
                     [&](const Constraint& o) { return SameConstraint(o, c); });
}

}  // namespace

void Validate(const PoseGraphOptions& options) {
  if (options.optimize_every_n_nodes < 0) {
    throw std::invalid_argument("'slam.pose_graph.optimize_every_n_nodes': expected >= 0, got " +
                                std::to_string(options.optimize_every_n_nodes));
  }
  if (!(options.optimize_every_travel_m >= 0.0) || std::isinf(options.optimize_every_travel_m)) {
    throw std::invalid_argument(
        "'slam.pose_graph.optimize_every_travel_m': expected a finite value >= 0, got " +
        FormatNumber(options.optimize_every_travel_m));
  }
  if (options.synchronous_solve_delay_nodes < 0) {
    throw std::invalid_argument(
        "'slam.pose_graph.synchronous_solve_delay_nodes': expected >= 0, got " +
        std::to_string(options.synchronous_solve_delay_nodes));
  }
  if (options.skip_neighbour_submaps < 0) {
    throw std::invalid_argument("'slam.pose_graph.skip_neighbour_submaps': expected >= 0, got " +
                                std::to_string(options.skip_neighbour_submaps));
  }
  RequirePositivePoseGraphOption("intra_submap_translation_weight",
                                 options.intra_submap_translation_weight);
  if (!(options.loop_closure_chain_travel_m >= 0.0) ||
      !std::isfinite(options.loop_closure_chain_travel_m)) {
    throw std::invalid_argument(
        "'slam.pose_graph.loop_closure_chain_travel_m': expected a finite value >= 0, got " +
        FormatNumber(options.loop_closure_chain_travel_m));
  }
  RequirePositivePoseGraphOption("outlier_translation_m", options.outlier_translation_m);
  RequirePositivePoseGraphOption("outlier_rotation_deg", options.outlier_rotation_deg);
  if (options.max_outlier_rounds < 0) {
    throw std::invalid_argument("'slam.pose_graph.max_outlier_rounds': expected >= 0, got " +
                                std::to_string(options.max_outlier_rounds));
  }
  RequirePositivePoseGraphOption("intra_submap_rotation_weight",
                                 options.intra_submap_rotation_weight);
  Validate(options.loop_closure_voxel_filter);
  Validate(options.constraint_builder);
  Validate(options.optimization_problem);
}

PoseGraph::PoseGraph(const PoseGraphOptions& options, OptimizationCallback callback)
    : options_((Validate(options), options)),
      callback_(std::move(callback)),
      optimization_problem_(options.optimization_problem),
      constraint_builder_(options.constraint_builder),
      work_queue_(options.synchronous) {}

PoseGraph::~PoseGraph() = default;

int PoseGraph::AddNode(double time_s, const geometry::Rigid2d& local_pose, const PointCloud& points,
                       const std::vector<InsertedSubmap>& insertion_submaps,
                       std::optional<geometry::Rigid2d> odometry_pose) {
  if (pending_solve_) {
    int next_node_id = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      next_node_id = static_cast<int>(nodes_.size());
    }
    ApplyPendingSolve(/*force=*/false, next_node_id);
  }
  auto thinned = std::make_shared<const PointCloud>(
      AdaptiveVoxelFilter(points, options_.loop_closure_voxel_filter));
  int node_id = 0;
  std::vector<int> newly_finished;
  bool optimize = false;
  int prefix_nodes = 0, prefix_submaps = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const InsertedSubmap& inserted : insertion_submaps) {
      if (inserted.grid == nullptr) {
        throw std::invalid_argument("PoseGraph::AddNode: submap " + std::to_string(inserted.id) +
                                    " comes without a grid");
      }
      if (inserted.id < 0 || inserted.id > static_cast<int>(submaps_.size())) {
        throw std::invalid_argument("PoseGraph::AddNode: submap id " + std::to_string(inserted.id) +
                                    " skips ids (next new id is " +
                                    std::to_string(submaps_.size()) + ")");
      }
    }
    node_id = static_cast<int>(nodes_.size());
    Node node;
    node.data = {time_s, local_pose, local_to_global_ * local_pose, odometry_pose};
    node.points = std::move(thinned);
    if (!nodes_.empty()) {
      const Node& previous = nodes_.back();
      node.travel_m = previous.travel_m +
                      (local_pose.translation() - previous.data.local_pose.translation()).norm();
    }
    for (const InsertedSubmap& inserted : insertion_submaps) {
      if (inserted.id == static_cast<int>(submaps_.size())) {
        // A new submap starts where local SLAM put it, seen through the
        // latest correction of local drift.
        Submap submap;
        submap.state.local_pose = inserted.local_pose;
        submap.state.global_pose = local_to_global_ * inserted.local_pose;
        submaps_.push_back(std::move(submap));
      }
      Submap& submap = submaps_[inserted.id];
      submap.state.grid = inserted.grid;
      submap.node_ids.push_back(node_id);
      if (inserted.finished && !submap.state.finished) {
        submap.state.finished = true;
        newly_finished.push_back(inserted.id);
      }
      node.submap_ids.push_back(inserted.id);
      constraints_.push_back({inserted.id, node_id, submap.state.local_pose.inverse() * local_pose,
                              options_.intra_submap_translation_weight,
                              options_.intra_submap_rotation_weight, ConstraintKind::kIntraSubmap});
    }
    const double node_travel_m = node.travel_m;
    nodes_.push_back(std::move(node));
    stats_.num_nodes = static_cast<int>(nodes_.size());
    stats_.num_submaps = static_cast<int>(submaps_.size());
    ++nodes_since_optimization_;
    if ((options_.optimize_every_n_nodes > 0 &&
         nodes_since_optimization_ >= options_.optimize_every_n_nodes) ||
        (options_.optimize_every_travel_m > 0.0 &&
         node_travel_m - travel_at_optimization_m_ >= options_.optimize_every_travel_m)) {
      nodes_since_optimization_ = 0;
      travel_at_optimization_m_ = node_travel_m;
      optimize = true;
      // The solve covers exactly what exists now, however late it runs, so
      // background results equal synchronous ones.
      prefix_nodes = static_cast<int>(nodes_.size());
      prefix_submaps = static_cast<int>(submaps_.size());
    }
  }
  work_queue_.Schedule(
      [this, node_id, newly_finished] { ComputeConstraints(node_id, newly_finished); });
  if (optimize) {
    if (options_.synchronous && options_.synchronous_solve_delay_nodes > 0) {
      StartSolve(prefix_nodes, prefix_submaps, node_id);
    } else {
      work_queue_.Schedule(
          [this, prefix_nodes, prefix_submaps] { Optimize(prefix_nodes, prefix_submaps); });
    }
  }
  return node_id;
}

void PoseGraph::ComputeConstraints(int node_id, const std::vector<int>& newly_finished) {
  std::vector<int> node_submaps;
  int num_submaps = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    node_submaps = nodes_[node_id].submap_ids;
    num_submaps = static_cast<int>(submaps_.size());
  }
  // Only submaps registered by earlier steps count as finished here, so the
  // set is the same whether this step runs late (background) or at once.
  std::vector<int> finished_before;
  for (int submap_id = 0; submap_id < num_submaps; ++submap_id) {
    if (constraint_builder_.HasSubmap(submap_id) && !Contains(node_submaps, submap_id) &&
        !IsNeighbour(node_submaps, submap_id)) {
      finished_before.push_back(submap_id);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  for (int submap_id : finished_before) pairs.emplace_back(node_id, submap_id);
  SearchPairs(pairs);

  // A submap that just finished is searched against every older node; newer
  // nodes will meet it in their own step above.
  for (int submap_id : newly_finished) {
    std::shared_ptr<const grid::ProbabilityGrid> grid;
    std::vector<int> candidates;
    std::vector<SubmapScan> own_scans;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const Submap& submap = submaps_[submap_id];
      grid = submap.state.grid;
      const std::vector<int>& members = submap.node_ids;
      for (int member : members) {
        own_scans.push_back({submap.state.local_pose.inverse() * nodes_[member].data.local_pose,
                             nodes_[member].points});
      }
      for (int other = 0; other <= node_id; ++other) {
        const std::vector<int>& other_submaps = nodes_[other].submap_ids;
        if (!Contains(members, other) && !IsNeighbour(other_submaps, submap_id)) {
          candidates.push_back(other);
        }
      }
    }
    constraint_builder_.AddFinishedSubmap(submap_id, std::move(grid), own_scans);
    pairs.clear();
    for (int other : candidates) pairs.emplace_back(other, submap_id);
    SearchPairs(pairs);
  }
}

bool PoseGraph::IsNeighbour(const std::vector<int>& node_submaps, int submap_id) const {
  for (int id : node_submaps) {
    if (std::abs(id - submap_id) <= options_.skip_neighbour_submaps) return true;
  }
  return false;
}

void PoseGraph::SearchPairs(const std::vector<std::pair<int, int>>& pairs) {
  struct Search {
    int node_id = 0;
    int submap_id = 0;
    geometry::Rigid2d initial_relative_pose;
    std::shared_ptr<const PointCloud> points;
    double travel_m = 0.0;
    double max_innovation_m = std::numeric_limits<double>::infinity();
  };
  // The pairs share their node (a new node against the finished submaps) or
  // their submap (a finished submap against older nodes): one shortest-chain
  // search from that end gives the chain to every other.
  const auto same_node = [&] {
    return std::all_of(pairs.begin(), pairs.end(),
                       [&](const auto& p) { return p.first == pairs.front().first; });
  };
  const auto same_submap = [&] {
    return std::all_of(pairs.begin(), pairs.end(),
                       [&](const auto& p) { return p.second == pairs.front().second; });
  };
  enum class Chain { kNone, kFromNode, kFromSubmap } chain_from = Chain::kNone;
  std::vector<double> chain_m;
  const bool use_chains =
      options_.search_windows_through_loop_closures || options_.gate_loop_closures_by_chain;
  if (use_chains && !pairs.empty()) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<int, double>> sources;
    if (same_node()) {
      const Node& node = nodes_[pairs.front().first];
      for (int a : node.submap_ids) {
        sources.emplace_back(a, std::abs(node.travel_m - SubmapStartTravel(a)));
      }
      chain_from = Chain::kFromNode;
    } else if (same_submap()) {
      sources.emplace_back(pairs.front().second, 0.0);
      chain_from = Chain::kFromSubmap;
    }
    if (chain_from != Chain::kNone) chain_m = ChainTravel(sources);
  }
  std::vector<Search> chosen;
  for (const auto& [node_id, submap_id] : pairs) {
    Search s;
    s.node_id = node_id;
    s.submap_id = submap_id;
    double node_travel_m = 0.0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      s.initial_relative_pose =
          submaps_[submap_id].state.global_pose.inverse() * nodes_[node_id].data.global_pose;
      s.points = nodes_[node_id].points;
      // Trajectory between the node and the nearest of the submap's nodes
      // (inserted consecutively, so their travel is an interval).
      const std::vector<int>& members = submaps_[submap_id].node_ids;
      node_travel_m = nodes_[node_id].travel_m;
      const double first_m = nodes_[members.front()].travel_m;
      const double last_m = nodes_[members.back()].travel_m;
      s.travel_m = std::max({0.0, first_m - node_travel_m, node_travel_m - last_m});
      double chain_travel_m = s.travel_m;
      if (chain_from == Chain::kFromNode) {
        chain_travel_m = std::min(chain_travel_m, chain_m[submap_id]);
      } else if (chain_from == Chain::kFromSubmap) {
        for (int a : nodes_[node_id].submap_ids) {
          chain_travel_m =
              std::min(chain_travel_m, chain_m[a] + std::abs(node_travel_m - SubmapStartTravel(a)));
        }
      }
      if (options_.search_windows_through_loop_closures) s.travel_m = chain_travel_m;
      if (options_.gate_loop_closures_by_chain && chain_from != Chain::kNone) {
        s.max_innovation_m = constraint_builder_.SearchWindow(chain_travel_m);
      }
    }
    if (constraint_builder_.ShouldSearch(submap_id, s.initial_relative_pose, *s.points,
                                         node_travel_m)) {
      chosen.push_back(std::move(s));
    }
  }
  // Each branch-and-bound search takes milliseconds and they are independent:
  // with a finished submap, every older node nearby is searched at once.
  std::vector<std::optional<Constraint>> found(chosen.size());
  std::vector<ConstraintBuilder::SearchReport> reports(chosen.size());
  common::ParallelFor(static_cast<int64_t>(chosen.size()), 1, [&](int64_t begin, int64_t end) {
    for (int64_t i = begin; i < end; ++i) {
      const Search& s = chosen[i];
      found[i] = constraint_builder_.Search(s.submap_id, s.node_id, s.initial_relative_pose,
                                            *s.points, s.travel_m, s.max_innovation_m, &reports[i]);
    }
  });
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < chosen.size(); ++i) {
    ++stats_.num_searches;
    const Search& s = chosen[i];
    const Submap& submap = submaps_[s.submap_id];
    const ConstraintBuilder::SearchReport& report = reports[i];
    LoopClosureRecord record;
    record.node_id = s.node_id;
    record.submap_id = s.submap_id;
    record.outcome = report.outcome;
    record.has_match = report.match.has_value();
    if (report.match) record.match = *report.match;
    record.score = report.score;
    record.min_score = report.min_score;
    record.search_window_m = report.search_window_m;
    record.near_match = report.near;
    record.estimate = s.initial_relative_pose;
    record.gate_window_m = s.max_innovation_m;
    record.submap_first_node_id = submap.node_ids.front();
    record.first_node_in_submap =
        submap.state.local_pose.inverse() * nodes_[submap.node_ids.front()].data.local_pose;
    loop_closure_log_.push_back(record);
    if (found[i]) {
      constraints_.push_back(*found[i]);
      AddLoopLink(*found[i]);
      ++stats_.num_loop_closures;
    }
  }
}

double PoseGraph::SubmapStartTravel(int submap_id) const {
  return nodes_[submaps_[submap_id].node_ids.front()].travel_m;
}

void PoseGraph::AddLoopLink(const Constraint& closure) {
  const Node& node = nodes_[closure.node_id];
  for (int a : node.submap_ids) {
    const double travel_m =
        std::abs(node.travel_m - SubmapStartTravel(a)) + options_.loop_closure_chain_travel_m;
    const int high = std::max(a, closure.submap_id);
    if (loop_links_.size() <= static_cast<size_t>(high)) loop_links_.resize(high + 1);
    loop_links_[a].push_back({closure.submap_id, travel_m});
    loop_links_[closure.submap_id].push_back({a, travel_m});
  }
}

std::vector<double> PoseGraph::ChainTravel(
    const std::vector<std::pair<int, double>>& sources) const {
  std::vector<double> start_travel_m(submaps_.size());
  for (size_t i = 0; i < submaps_.size(); ++i) start_travel_m[i] = SubmapStartTravel(i);
  return ShortestChainTravel(start_travel_m, loop_links_, sources);
}

void PoseGraph::Optimize(int num_nodes, int num_submaps) {
  if (num_nodes == 0 || num_submaps == 0) return;
  ApplySolve(num_nodes, num_submaps, Solve(SnapshotForSolve(num_nodes, num_submaps)));
}

PoseGraph::SolveInput PoseGraph::SnapshotForSolve(int num_nodes, int num_submaps) const {
  SolveInput input;
  input.num_nodes = num_nodes;
  input.num_submaps = num_submaps;
  std::lock_guard<std::mutex> lock(mutex_);
  input.nodes.reserve(num_nodes);
  for (int i = 0; i < num_nodes; ++i) input.nodes.push_back(nodes_[i].data);
  for (int i = 0; i < num_submaps; ++i) input.submap_poses.push_back(submaps_[i].state.global_pose);
  for (const Constraint& c : constraints_) {
    if (c.node_id < num_nodes && c.submap_id < num_submaps) input.constraints.push_back(c);
  }
  return input;
}

PoseGraph::SolveOutput PoseGraph::Solve(SolveInput input) const {
  SolveOutput output;
  std::vector<Constraint>& constraints = input.constraints;
  output.result = optimization_problem_.Solve(input.nodes, input.submap_poses, constraints);
  for (int round = 0; round < options_.max_outlier_rounds; ++round) {
    const std::vector<size_t> outliers =
        LoopClosureOutliers(output.result, constraints, options_.outlier_translation_m,
                            options_.outlier_rotation_deg * M_PI / 180.0);
    if (outliers.empty()) break;
    for (size_t i : outliers) output.rejected.push_back(constraints[i]);
    std::erase_if(constraints, [&](const Constraint& c) { return Contains(output.rejected, c); });
    output.result = optimization_problem_.Solve(input.nodes, input.submap_poses, constraints);
  }
  return output;
}

void PoseGraph::ApplySolve(int num_nodes, int num_submaps, const SolveOutput& output) {
  const OptimizationResult& result = output.result;
  const std::vector<Constraint>& rejected = output.rejected;
  std::vector<geometry::Rigid2d> all_submap_poses;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (int i = 0; i < num_nodes; ++i) nodes_[i].data.global_pose = result.node_global_poses[i];
    for (int i = 0; i < num_submaps; ++i) {
      submaps_[i].state.global_pose = result.submap_global_poses[i];
    }
    // Everything added after the snapshot hangs off the last solved node by
    // local SLAM's (rigid) relative poses: move it with that node.
    const Node& last = nodes_[num_nodes - 1];
    local_to_global_ = last.data.global_pose * last.data.local_pose.inverse();
    for (size_t i = num_nodes; i < nodes_.size(); ++i) {
      nodes_[i].data.global_pose = local_to_global_ * nodes_[i].data.local_pose;
    }
    for (size_t i = num_submaps; i < submaps_.size(); ++i) {
      submaps_[i].state.global_pose = local_to_global_ * submaps_[i].state.local_pose;
    }
    if (!rejected.empty()) {
      std::erase_if(constraints_, [&](const Constraint& c) { return Contains(rejected, c); });
      for (LoopClosureRecord& r : loop_closure_log_) {
        if (r.outcome != LoopClosureOutcome::kAccepted) continue;
        const bool dropped =
            std::any_of(rejected.begin(), rejected.end(), [&](const Constraint& c) {
              return c.node_id == r.node_id && c.submap_id == r.submap_id &&
                     c.relative_pose.translation() == r.match.translation() &&
                     c.relative_pose.theta() == r.match.theta();
            });
        if (dropped) r.outcome = LoopClosureOutcome::kDropped;
      }
      loop_links_.clear();
      for (const Constraint& c : constraints_) {
        if (c.kind == ConstraintKind::kInterSubmap) AddLoopLink(c);
      }
    }
    stats_.num_rejected_loop_closures += static_cast<int>(rejected.size());
    stats_.num_loop_closures -= static_cast<int>(rejected.size());
    ++stats_.num_optimizations;
    stats_.last_solve_time_s = result.summary.solve_time_s;
    stats_.total_solve_time_s += result.summary.solve_time_s;
    for (const Submap& s : submaps_) all_submap_poses.push_back(s.state.global_pose);
  }
  if (callback_) callback_(all_submap_poses);
}

void PoseGraph::StartSolve(int num_nodes, int num_submaps, int node_id) {
  ApplyPendingSolve(/*force=*/true, node_id + 1);
  if (num_nodes == 0 || num_submaps == 0) return;
  PendingSolve pending;
  pending.num_nodes = num_nodes;
  pending.num_submaps = num_submaps;
  pending.apply_before_node = node_id + 1 + options_.synchronous_solve_delay_nodes;
  pending.output = std::async(std::launch::async,
                              [this, input = SnapshotForSolve(num_nodes, num_submaps)]() mutable {
                                return Solve(std::move(input));
                              });
  pending_solve_ = std::move(pending);
}

void PoseGraph::ApplyPendingSolve(bool force, int next_node_id) {
  if (!pending_solve_ || (!force && next_node_id < pending_solve_->apply_before_node)) return;
  PendingSolve pending = std::move(*pending_solve_);
  pending_solve_.reset();
  ApplySolve(pending.num_nodes, pending.num_submaps, pending.output.get());
}

void PoseGraph::RunFinalOptimization() {
  int num_nodes = 0, num_submaps = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    num_nodes = static_cast<int>(nodes_.size());
    num_submaps = static_cast<int>(submaps_.size());
    nodes_since_optimization_ = 0;
    if (!nodes_.empty()) travel_at_optimization_m_ = nodes_.back().travel_m;
  }
  ApplyPendingSolve(/*force=*/true, num_nodes);
  work_queue_.Schedule([this, num_nodes, num_submaps] { Optimize(num_nodes, num_submaps); });
  work_queue_.WaitUntilIdle();
}

void PoseGraph::WaitForPendingWork() {
  work_queue_.WaitUntilIdle();
  if (pending_solve_) ApplyPendingSolve(/*force=*/true, 0);
}

std::vector<TimedPose> PoseGraph::GetNodePoses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<TimedPose> poses;
  poses.reserve(nodes_.size());
  for (const Node& n : nodes_) poses.push_back({n.data.time_s, n.data.global_pose});
  return poses;
}

std::optional<TimedPose> PoseGraph::GetNewestNodePose() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (nodes_.empty()) return std::nullopt;
  return TimedPose{nodes_.back().data.time_s, nodes_.back().data.global_pose};
}

std::vector<geometry::Rigid2d> PoseGraph::GetSubmapGlobalPoses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<geometry::Rigid2d> poses;
  for (const Submap& s : submaps_) poses.push_back(s.state.global_pose);
  return poses;
}

std::vector<SubmapState> PoseGraph::GetSubmaps() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<SubmapState> states;
  for (const Submap& s : submaps_) states.push_back(s.state);
  return states;
}

std::vector<Constraint> PoseGraph::GetConstraints() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return constraints_;
}

std::vector<LoopClosureRecord> PoseGraph::GetLoopClosureLog() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return loop_closure_log_;
}

geometry::Rigid2d PoseGraph::GetLocalToGlobal() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return local_to_global_;
}

PoseGraphStats PoseGraph::GetStats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  PoseGraphStats stats = stats_;
  // Atomic counters: safe to read while a queued step searches.
  stats.num_gated_loop_closures = constraint_builder_.num_gated();
  stats.num_searches_without_match = constraint_builder_.num_without_match();
  stats.num_ambiguous_matches = constraint_builder_.num_ambiguous();
  stats.num_wide_ambiguous_matches = constraint_builder_.num_wide_ambiguous();
  stats.num_matches_seeing_through = constraint_builder_.num_seeing_through();
  stats.num_pairs_without_overlap = constraint_builder_.num_without_overlap();
  stats.num_near_matches = constraint_builder_.num_near_matches();
  return stats;
}

}  // namespace scout::slam
