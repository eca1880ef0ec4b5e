#include "scout/exploration/map_progress.h"

namespace scout::exploration {

void MapProgress::Measure(double t_s, double map_free_m2, int num_optimizations) {
  // The first measurement is all gain: the map before it was empty.
  const bool by_scans = !measured_ || num_optimizations == previous_optimizations_;
  if (by_scans) mapped_by_scans_m2_ += map_free_m2 - previous_free_m2_;
  measured_ = true;
  previous_free_m2_ = map_free_m2;
  previous_optimizations_ = num_optimizations;
  if (mapped_by_scans_m2_ >= best_m2_ + min_gain_m2_) {
    best_m2_ = mapped_by_scans_m2_;
    last_progress_s_ = t_s;
  }
}

}  // namespace scout::exploration
