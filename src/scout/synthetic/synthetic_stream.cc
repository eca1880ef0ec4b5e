#include "scout/synthetic/synthetic_stream.h"

#include <deque>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/random.h"
#include "scout/synthetic/scan_poses.h"

namespace scout::synthetic {
namespace {

using geometry::Rigid2d;

// Independent random streams derived from the seed.
constexpr uint64_t kLidarStream = 1;
constexpr uint64_t kCorrectionStream = 2;

void RequireStreamOption(bool ok, const std::string& key, double value,
                         const std::string& expected) {
  if (!ok) {
    throw InputError("synthetic." + key + " = " + FormatNumber(value) + ": expected " + expected);
  }
}

// A submap receiving scans.
struct ActiveSubmap {
  int id = 0;
  Rigid2d true_pose;   // submap frame -> world
  Rigid2d local_pose;  // submap frame -> local SLAM frame
  grid::ProbabilityGrid grid;
  std::vector<Eigen::Vector2d> scan_origins;
};

std::vector<Eigen::Vector2d> Transformed(const Rigid2d& transform,
                                         const std::vector<Eigen::Vector2d>& points) {
  std::vector<Eigen::Vector2d> result;
  result.reserve(points.size());
  for (const Eigen::Vector2d& p : points) result.push_back(transform * p);
  return result;
}

}  // namespace

void Validate(const SyntheticStreamOptions& o) {
  // As slam.local.submaps.resolution_m.
  RequireStreamOption(o.resolution_m >= 0.01 && o.resolution_m <= 1.0, "resolution_m",
                      o.resolution_m, "in [0.01, 1] (m)");
  RequireStreamOption(o.scans_per_submap >= 1, "scans_per_submap", o.scans_per_submap, ">= 1");
  RequireStreamOption(o.scan_spacing_m > 0.0, "scan_spacing_m", o.scan_spacing_m, "> 0");
  RequireStreamOption(o.scan_spacing_rad > 0.0, "scan_spacing_rad", o.scan_spacing_rad, "> 0");
  RequireStreamOption(o.linear_speed_mps > 0.0, "linear_speed_mps", o.linear_speed_mps, "> 0");
  RequireStreamOption(o.angular_speed_radps > 0.0, "angular_speed_radps", o.angular_speed_radps,
                      "> 0");
  RequireStreamOption(o.optimize_every_n_scans >= 1, "optimize_every_n_scans",
                      o.optimize_every_n_scans, ">= 1");
  RequireStreamOption(o.max_scans >= 0, "max_scans", o.max_scans, ">= 0");
  try {
    sensor::Validate(o.range_filter);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("synthetic.") + e.what());
  }
  // The parts' own checks name their keys relative to their part.
  try {
    Validate(o.tour);
    Validate(o.corrections);
    sim::Lidar{o.lidar};
  } catch (const InputError& e) {
    throw InputError(std::string("synthetic.") + e.what());
  }
}

SyntheticEventStream::SyntheticEventStream(const sim::World& world,
                                           const SyntheticStreamOptions& options, uint64_t seed)
    : world_(world), options_(options), seed_(seed) {
  Validate(options_);
}

StreamStats SyntheticEventStream::Run(const std::function<void(const events::SubmapEvent&)>& sink) {
  const MotionOptions motion{options_.scan_spacing_m, options_.scan_spacing_rad,
                             options_.linear_speed_mps, options_.angular_speed_radps};
  const std::vector<ScanPose> scans =
      SampleScanPoses(PlanTour(world_, options_.tour), motion, options_.max_scans);
  const sim::Lidar lidar(options_.lidar);
  const grid::RangeDataInserter inserter(options_.insertion);
  std::mt19937_64 lidar_rng(sim::DeriveSeed(seed_, kLidarStream));
  CorrectionModel corrections(options_.corrections, sim::DeriveSeed(seed_, kCorrectionStream));
  const int scans_per_submap = options_.scans_per_submap;
  // The submap origin lies at the centre of cell (0, 0).
  const grid::MapLimits initial_limits(
      options_.resolution_m, Eigen::Vector2d::Constant(-0.5 * options_.resolution_m), 0, 0);

  true_submap_poses_.clear();
  true_scan_poses_.clear();
  StreamStats stats;
  std::deque<ActiveSubmap> active;
  for (size_t k = 0; k < scans.size(); ++k) {
    const Rigid2d& pose = scans[k].pose;
    true_scan_poses_.push_back(pose);
    if (k > 0) corrections.Move(scans[k - 1].pose, pose);
    if (k % scans_per_submap == 0) {
      ActiveSubmap submap;
      submap.id = static_cast<int>(true_submap_poses_.size());
      submap.true_pose = pose;
      submap.local_pose = corrections.AddSubmap(pose, scans[k].travelled_m);
      submap.grid = grid::ProbabilityGrid(initial_limits);
      true_submap_poses_.push_back(pose);
      active.push_back(std::move(submap));
    }
    const sensor::RangeData range_data = sensor::ToRangeData(
        lidar.Scan(world_, pose, scans[k].time_s, lidar_rng), options_.range_filter);
    std::vector<int> inserted_into;
    for (ActiveSubmap& submap : active) {
      const Rigid2d submap_from_sensor = submap.true_pose.inverse() * pose;
      const Eigen::Vector2d origin = submap_from_sensor.translation();
      inserter.Insert(origin, Transformed(submap_from_sensor, range_data.returns),
                      Transformed(submap_from_sensor, range_data.misses), &submap.grid);
      submap.scan_origins.push_back(origin);
      inserted_into.push_back(submap.id);
      events::SubmapChanged changed;
      changed.id = submap.id;
      changed.grid = std::make_shared<const grid::ProbabilityGrid>(submap.grid);
      changed.local_pose = submap.local_pose;
      changed.scan_origins = submap.scan_origins;
      changed.finished = static_cast<int>(submap.scan_origins.size()) == 2 * scans_per_submap;
      sink(changed);
    }
    if (static_cast<int>(active.front().scan_origins.size()) == 2 * scans_per_submap) {
      active.pop_front();
    }
    corrections.AddScan(pose.translation(), scans[k].travelled_m, inserted_into);
    if ((k + 1) % options_.optimize_every_n_scans == 0) {
      if (corrections.Optimize()) ++stats.loop_closures;
      ++stats.optimizations;
      sink(events::Optimized{corrections.global_poses()});
    }
  }
  stats.scans = static_cast<int>(scans.size());
  stats.submaps = static_cast<int>(true_submap_poses_.size());
  stats.trajectory_length_m = scans.empty() ? 0.0 : scans.back().travelled_m;
  return stats;
}

}  // namespace scout::synthetic
