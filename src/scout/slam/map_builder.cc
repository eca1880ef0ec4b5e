#include "scout/slam/map_builder.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace scout::slam {

void Validate(const SlamOptions& options) {
  Validate(options.local);
  Validate(options.pose_graph);
  if (options.submap_event_every_n_insertions < 1) {
    throw std::invalid_argument(
        "slam option 'submap_event_every_n_insertions': expected >= 1, got " +
        std::to_string(options.submap_event_every_n_insertions));
  }
}

MapBuilder::MapBuilder(const SlamOptions& options, EventSink sink)
    : options_((Validate(options), options)),
      sink_(std::move(sink)),
      local_(options.local),
      pose_graph_(std::make_unique<PoseGraph>(options.pose_graph,
                                              [this](const std::vector<geometry::Rigid2d>& poses) {
                                                std::lock_guard<std::mutex> lock(pending_mutex_);
                                                pending_.push_back(events::Optimized{poses});
                                              })) {}

MapBuilder::~MapBuilder() {
  // Stop the worker before the members its callback touches go away.
  pose_graph_.reset();
}

void MapBuilder::AddOdometry(const sensor::Odometry& odometry) {
  // Ignored odometry also gives no odometry constraints.
  if (!options_.local.use_odometry) return;
  local_.AddOdometry(odometry);
  odometry_.AddOdometry(odometry);
}

bool MapBuilder::AddScan(const sensor::LaserScan& scan) {
  ++num_scans_;
  DrainEvents();
  std::optional<InsertionResult> insertion = local_.AddScan(scan);
  if (!insertion) return false;

  std::vector<InsertedSubmap> inserted;
  for (events::SubmapChanged& changed : insertion->insertion_submaps) {
    inserted.push_back({changed.id, changed.local_pose, changed.grid, changed.finished});
    const int count = ++insertions_per_submap_[changed.id];
    if (changed.finished) insertions_per_submap_.erase(changed.id);
    if (count == 1 || changed.finished || count % options_.submap_event_every_n_insertions == 0) {
      Emit(std::move(changed));
    }
  }
  const std::optional<geometry::Rigid2d> odometry_pose = odometry_.OdometryAt(insertion->time_s);
  odometry_.AddPose(insertion->time_s, insertion->local_pose);
  pose_graph_->AddNode(insertion->time_s, insertion->local_pose, insertion->filtered_points,
                       inserted, odometry_pose);
  DrainEvents();
  return true;
}

void MapBuilder::DrainEvents() {
  while (true) {
    events::Optimized next;
    {
      std::lock_guard<std::mutex> lock(pending_mutex_);
      if (pending_.empty()) return;
      next = std::move(pending_.front());
      pending_.pop_front();
    }
    Emit(std::move(next));  // outside the lock: the sink may take its time
  }
}

void MapBuilder::Finish() {
  pose_graph_->RunFinalOptimization();
  DrainEvents();
}

void MapBuilder::Emit(events::SubmapEvent event) {
  if (std::holds_alternative<events::Optimized>(event)) {
    ++num_optimized_events_;
  } else {
    ++num_submap_events_;
  }
  if (sink_) sink_(std::move(event));
}

std::vector<TimedPose> MapBuilder::GetTrajectory() const { return pose_graph_->GetNodePoses(); }

std::optional<TimedPose> MapBuilder::GetNewestNode() const {
  return pose_graph_->GetNewestNodePose();
}

std::vector<SubmapState> MapBuilder::GetSubmaps() const { return pose_graph_->GetSubmaps(); }

std::vector<Constraint> MapBuilder::GetConstraints() const { return pose_graph_->GetConstraints(); }

std::vector<LoopClosureRecord> MapBuilder::GetLoopClosureLog() const {
  return pose_graph_->GetLoopClosureLog();
}

SlamStats MapBuilder::GetStats() const {
  const PoseGraphStats graph = pose_graph_->GetStats();
  SlamStats stats;
  stats.num_nodes = graph.num_nodes;
  stats.num_submaps = graph.num_submaps;
  stats.num_optimizations = graph.num_optimizations;
  stats.num_loop_closures = graph.num_loop_closures;
  stats.num_rejected_loop_closures = graph.num_rejected_loop_closures;
  stats.num_gated_loop_closures = graph.num_gated_loop_closures;
  stats.num_loop_closure_searches = graph.num_searches;
  stats.num_searches_without_match = graph.num_searches_without_match;
  stats.num_ambiguous_matches = graph.num_ambiguous_matches;
  stats.num_wide_ambiguous_matches = graph.num_wide_ambiguous_matches;
  stats.num_matches_seeing_through = graph.num_matches_seeing_through;
  stats.num_pairs_without_overlap = graph.num_pairs_without_overlap;
  stats.num_near_matches = graph.num_near_matches;
  stats.total_solve_time_s = graph.total_solve_time_s;
  stats.num_scans = num_scans_;
  stats.num_submap_events = num_submap_events_;
  stats.num_optimized_events = num_optimized_events_;
  return stats;
}

}  // namespace scout::slam
