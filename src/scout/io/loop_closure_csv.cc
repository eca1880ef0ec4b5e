#include "scout/io/loop_closure_csv.h"

#include <Eigen/Core>
#include <cmath>
#include <cstdio>

#include "scout/common/atomic_file.h"

namespace scout::io {
namespace {

// 'value' printed with 'format', or "" when it is not finite (no gate, no
// reference).
std::string FixedOrEmpty(double value, const char* format) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace

MatchDisagreement MatchError(const geometry::Rigid2d& match, const geometry::Rigid2d& submap_pose,
                             const geometry::Rigid2d& node_pose) {
  const geometry::Rigid2d error = match.inverse() * (submap_pose.inverse() * node_pose);
  return {error.translation().norm(), geometry::NormalizeAngle(error.theta()) * 180.0 / M_PI};
}

geometry::Rigid2d ReferenceSubmapPose(const slam::LoopClosureRecord& record,
                                      const geometry::Rigid2d& reference_first_node) {
  return reference_first_node * record.first_node_in_submap.inverse();
}

std::string OutcomeName(slam::LoopClosureOutcome outcome) {
  switch (outcome) {
    case slam::LoopClosureOutcome::kAccepted:
      return "accepted";
    case slam::LoopClosureOutcome::kGated:
      return "gated";
    case slam::LoopClosureOutcome::kDropped:
      return "dropped";
    case slam::LoopClosureOutcome::kNoMatch:
      return "no_match";
    case slam::LoopClosureOutcome::kFar:
      return "low_score_far_from_estimate";
    case slam::LoopClosureOutcome::kAmbiguous:
      return "ambiguous";
    case slam::LoopClosureOutcome::kWideAmbiguous:
      return "wide_ambiguous";
    case slam::LoopClosureOutcome::kSeeingThrough:
      return "seeing_through";
  }
  return "unknown";
}

void WriteLoopClosureCsv(const std::vector<slam::LoopClosureRecord>& records,
                         const std::vector<StampedPose>& trajectory, const GlobalSubmaps& submaps,
                         const std::vector<std::optional<geometry::Rigid2d>>& reference_poses,
                         const std::filesystem::path& path) {
  std::string text =
      "node,node_time_s,submap,outcome,near_match,score,min_score,search_window_m,match_x_m,"
      "match_y_m,match_theta_rad,innovation_m,gate_window_m,final_error_m,final_error_deg,"
      "reference_error_m,reference_error_deg,estimate_reference_error_m\n";
  const auto reference = [&](int node_id) -> const std::optional<geometry::Rigid2d>* {
    if (node_id < 0 || node_id >= static_cast<int>(reference_poses.size())) return nullptr;
    return reference_poses[node_id] ? &reference_poses[node_id] : nullptr;
  };
  char line[640];
  for (const slam::LoopClosureRecord& r : records) {
    const StampedPose& node = trajectory.at(r.node_id);
    const geometry::Rigid2d& submap_pose = submaps.at(r.submap_id).first;
    MatchDisagreement final_error{NAN, NAN};
    MatchDisagreement reference_error{NAN, NAN};
    MatchDisagreement estimate_reference_error{NAN, NAN};
    // Without a match (no_match) its columns are empty.
    double innovation_m = NAN;
    Eigen::Vector3d match(NAN, NAN, NAN);
    if (r.has_match) {
      match = {r.match.x(), r.match.y(), r.match.theta()};
      final_error = MatchError(r.match, submap_pose, node.pose);
      innovation_m = (r.match.translation() - r.estimate.translation()).norm();
    }
    const auto* node_reference = reference(r.node_id);
    const auto* first_reference = reference(r.submap_first_node_id);
    if (node_reference != nullptr && first_reference != nullptr) {
      const geometry::Rigid2d reference_submap = ReferenceSubmapPose(r, **first_reference);
      if (r.has_match) reference_error = MatchError(r.match, reference_submap, **node_reference);
      estimate_reference_error = MatchError(r.estimate, reference_submap, **node_reference);
    }
    std::snprintf(
        line, sizeof(line), "%d,%.6f,%d,%s,%d,%s,%.4f,%.3f,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n",
        r.node_id, node.time_s, r.submap_id, OutcomeName(r.outcome).c_str(), r.near_match ? 1 : 0,
        FixedOrEmpty(r.score, "%.4f").c_str(), r.min_score, r.search_window_m,
        FixedOrEmpty(match.x(), "%.4f").c_str(), FixedOrEmpty(match.y(), "%.4f").c_str(),
        FixedOrEmpty(match.z(), "%.6f").c_str(), FixedOrEmpty(innovation_m, "%.4f").c_str(),
        FixedOrEmpty(r.gate_window_m, "%.4f").c_str(),
        FixedOrEmpty(final_error.translation_m, "%.4f").c_str(),
        FixedOrEmpty(final_error.rotation_deg, "%.3f").c_str(),
        FixedOrEmpty(reference_error.translation_m, "%.4f").c_str(),
        FixedOrEmpty(reference_error.rotation_deg, "%.3f").c_str(),
        FixedOrEmpty(estimate_reference_error.translation_m, "%.4f").c_str());
    text += line;
  }
  WriteTextFileAtomically(path, text);
}

}  // namespace scout::io
