#include "scout/synthetic/scan_poses.h"

#include <cmath>

namespace scout::synthetic {
namespace {

// Segments shorter than this are skipped: their heading is meaningless.
constexpr double kMinSegmentM = 1e-9;

class ScanRecorder {
 public:
  ScanRecorder(const MotionOptions& options, int max_scans)
      : options_(options), max_scans_(max_scans) {}

  bool full() const { return max_scans_ > 0 && static_cast<int>(scans_.size()) >= max_scans_; }

  void Record(const Eigen::Vector2d& position, double heading_rad) {
    if (full()) return;
    scans_.push_back({geometry::Rigid2d(position, heading_rad), time_s_, travelled_m_});
  }

  // Turns on the spot at 'position' from 'heading' to 'target' (shortest way).
  void Turn(const Eigen::Vector2d& position, double* heading, double target) {
    const double total = geometry::NormalizeAngle(target - *heading);
    const double direction = total >= 0.0 ? 1.0 : -1.0;
    double turned = 0.0;
    while (!full()) {
      // Rotation still needed until the heading differs from the last scan's by the spacing.
      const double offset =
          direction * geometry::NormalizeAngle(*heading - scans_.back().pose.theta());
      const double needed = options_.scan_spacing_rad - offset;
      if (turned + needed > std::abs(total)) break;
      turned += needed;
      *heading += direction * needed;
      time_s_ += needed / options_.angular_speed_radps;
      Record(position, *heading);
    }
    time_s_ += (std::abs(total) - turned) / options_.angular_speed_radps;
    *heading = target;
  }

  // Drives straight from 'from' to 'to' facing their direction.
  void Drive(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double heading) {
    const double length = (to - from).norm();
    const Eigen::Vector2d direction = (to - from) / length;
    double driven = 0.0;
    while (!full()) {
      // Distance v along the segment at which |p(v) - last scan| reaches the spacing.
      const Eigen::Vector2d q = from + driven * direction - scans_.back().pose.translation();
      const double along = q.dot(direction);
      const double spacing = options_.scan_spacing_m;
      const double v =
          -along + std::sqrt(std::max(0.0, along * along - q.squaredNorm() + spacing * spacing));
      if (driven + v > length) break;
      driven += v;
      travelled_m_ += v;
      time_s_ += v / options_.linear_speed_mps;
      Record(from + driven * direction, heading);
    }
    travelled_m_ += length - driven;
    time_s_ += (length - driven) / options_.linear_speed_mps;
  }

  std::vector<ScanPose> Take() { return std::move(scans_); }

 private:
  MotionOptions options_;
  int max_scans_;
  double time_s_ = 0.0;
  double travelled_m_ = 0.0;
  std::vector<ScanPose> scans_;
};

}  // namespace

std::vector<ScanPose> SampleScanPoses(const std::vector<Eigen::Vector2d>& tour,
                                      const MotionOptions& options, int max_scans) {
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector2d& p : tour) {
    if (points.empty() || (p - points.back()).norm() > kMinSegmentM) points.push_back(p);
  }
  if (points.empty()) return {};
  double heading = 0.0;
  if (points.size() > 1) {
    const Eigen::Vector2d d = points[1] - points[0];
    heading = std::atan2(d.y(), d.x());
  }
  ScanRecorder recorder(options, max_scans);
  recorder.Record(points[0], heading);
  for (size_t i = 0; i + 1 < points.size() && !recorder.full(); ++i) {
    const Eigen::Vector2d d = points[i + 1] - points[i];
    recorder.Turn(points[i], &heading, std::atan2(d.y(), d.x()));
    recorder.Drive(points[i], points[i + 1], heading);
  }
  return recorder.Take();
}

}  // namespace scout::synthetic
