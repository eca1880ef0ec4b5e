#include "scout/slam/submap.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"

namespace scout::slam {

void Validate(const SubmapOptions& options) {
  // Finer cells than 1 cm are below any 2D lidar's noise and make submaps of
  // millions of cells; cells of more than 1 m cannot be matched against.
  if (!(options.resolution_m >= 0.01 && options.resolution_m <= 1.0)) {
    throw std::invalid_argument("submaps.resolution_m must be in [0.01, 1] (m), got " +
                                FormatNumber(options.resolution_m));
  }
  if (options.num_range_data < 1) {
    throw std::invalid_argument("submaps.num_range_data must be >= 1, got " +
                                std::to_string(options.num_range_data));
  }
  if (!(options.max_travel_m >= 0.0) || std::isinf(options.max_travel_m)) {
    throw std::invalid_argument("submaps.max_travel_m must be finite and >= 0, got " +
                                FormatNumber(options.max_travel_m));
  }
  // The inserter names hit_probability / miss_probability itself.
  grid::RangeDataInserter inserter(options.insertion);
}

Submap::Submap(events::SubmapId id, const Eigen::Vector2d& origin, double resolution_m)
    : id_(id), local_pose_(origin, 0.0) {
  if (!(resolution_m > 0.0)) {
    throw std::invalid_argument("Submap: resolution_m must be > 0, got " +
                                std::to_string(resolution_m));
  }
  // An empty grid on the lattice through the submap origin; the first
  // insertion grows it to the scan's extent.
  grid_ = std::make_shared<grid::ProbabilityGrid>(
      grid::MapLimits(resolution_m, Eigen::Vector2d::Zero(), 0, 0));
}

void Submap::InsertRangeData(const Eigen::Vector2d& origin, const PointCloud& returns,
                             const PointCloud& misses, const grid::RangeDataInserter& inserter) {
  if (finished_) {
    throw std::logic_error("Submap::InsertRangeData: submap " + std::to_string(id_) +
                           " is finished");
  }
  // Someone still holds the last snapshot: write into a private copy so it
  // stays immutable. Only this submap hands out references, and it does so
  // from the inserting thread, so use_count() == 1 cannot become stale.
  if (grid_.use_count() > 1) {
    grid_ = std::make_shared<grid::ProbabilityGrid>(*grid_);
    ++num_grid_copies_;
  }
  const geometry::Rigid2d to_submap = local_pose_.inverse();
  const Eigen::Vector2d origin_in_submap = to_submap * origin;
  inserter.Insert(origin_in_submap, TransformPointCloud(returns, to_submap),
                  TransformPointCloud(misses, to_submap), grid_.get());
  if (!scan_origins_.empty()) travel_m_ += (origin_in_submap - scan_origins_.back()).norm();
  scan_origins_.push_back(origin_in_submap);
}

events::SubmapChanged Submap::ToEvent() const {
  return events::SubmapChanged{id_, grid_, local_pose_, scan_origins_, finished_};
}

ActiveSubmaps::ActiveSubmaps(const SubmapOptions& options)
    : options_(options), inserter_((Validate(options), options.insertion)) {}

ActiveSubmaps::Insertion ActiveSubmaps::InsertRangeData(const Eigen::Vector2d& origin,
                                                        const PointCloud& returns,
                                                        const PointCloud& misses) {
  Insertion insertion;
  if (submaps_.empty() || HalfFull(*submaps_.back())) {
    // The older submap was finished by the previous insertion, which made
    // the newer one half full.
    if (submaps_.size() == 2) submaps_.erase(submaps_.begin());
    submaps_.push_back(std::make_shared<Submap>(next_id_, origin, options_.resolution_m));
    insertion.created.push_back(next_id_++);
  }
  for (const std::shared_ptr<Submap>& submap : submaps_) {
    submap->InsertRangeData(origin, returns, misses, inserter_);
  }
  if (submaps_.size() == 2 && HalfFull(*submaps_.back())) {
    submaps_.front()->Finish();
    insertion.finished.push_back(submaps_.front()->id());
  }
  insertion.submaps.assign(submaps_.begin(), submaps_.end());
  return insertion;
}

bool ActiveSubmaps::HalfFull(const Submap& submap) const {
  return submap.num_range_data() >= options_.num_range_data ||
         (options_.max_travel_m > 0.0 && submap.travel_m() >= options_.max_travel_m);
}

}  // namespace scout::slam
