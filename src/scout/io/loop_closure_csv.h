#ifndef SCOUT_IO_LOOP_CLOSURE_CSV_H_
#define SCOUT_IO_LOOP_CLOSURE_CSV_H_

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/io/map_picture.h"
#include "scout/io/trajectory.h"
#include "scout/slam/pose_graph_types.h"

namespace scout::io {

// A loop closure's disagreement with some set of poses: how far the node
// lies from where the match put it in the submap frame.
struct MatchDisagreement {
  double translation_m = 0.0;
  double rotation_deg = 0.0;  // signed, (-180, 180]
};

// How far 'match' (node frame -> submap frame) is from the same relative
// pose under 'node_pose' and 'submap_pose' (both in one frame).
MatchDisagreement MatchError(const geometry::Rigid2d& match, const geometry::Rigid2d& submap_pose,
                             const geometry::Rigid2d& node_pose);

// The submap frame under a reference trajectory: where the reference puts
// the submap's first node, moved back by that node's pose in the submap
// frame (local SLAM's). With it, MatchError checks a closure against the
// reference independently of the SLAM estimate.
geometry::Rigid2d ReferenceSubmapPose(const slam::LoopClosureRecord& record,
                                      const geometry::Rigid2d& reference_first_node);

// "accepted", "gated", "dropped", "no_match", "low_score_far_from_estimate",
// "ambiguous", "wide_ambiguous" or "seeing_through".
std::string OutcomeName(slam::LoopClosureOutcome outcome);

// Writes one row per record, that is per loop-closure search (through a
// temporary file and rename):
//   node, node_time_s, submap, outcome, near_match, score, min_score,
//   search_window_m, match_x_m, match_y_m, match_theta_rad, innovation_m,
//   gate_window_m, final_error_m, final_error_deg, reference_error_m,
//   reference_error_deg, estimate_reference_error_m
// near_match is 1 for a closure taken below min_score as a near match; score
// is the match's branch-and-bound score, min_score what the submap asks for,
// search_window_m the half width of the translation window. The match
// columns, innovation_m, score and the match's errors are empty for a search
// that ended without a match (no_match; an ambiguous search gives its best).
// innovation_m is |match - estimate at search time|; gate_window_m is empty
// without a gate;
// final_error_* compare the match with the final graph ('trajectory' by node
// id, 'submaps' by submap id, in one frame); reference_error_* with
// 'reference_poses' (by node id, in any one frame), empty where the reference
// lacks the node or the submap's first node, or is empty itself.
// estimate_reference_error_m compares the graph's estimate at search time
// with the reference the same way: a search whose window is smaller than it
// could not reach the reference's pose.
// A reference error holds the match's own error and local SLAM's drift
// within the submap, between its first node and the part the node matched:
// a submap made in a fast turn can put a right match a few degrees off.
// Throws InputError when the file cannot be written, std::out_of_range when
// a record names a node or submap beyond the poses.
void WriteLoopClosureCsv(const std::vector<slam::LoopClosureRecord>& records,
                         const std::vector<StampedPose>& trajectory, const GlobalSubmaps& submaps,
                         const std::vector<std::optional<geometry::Rigid2d>>& reference_poses,
                         const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_LOOP_CLOSURE_CSV_H_
