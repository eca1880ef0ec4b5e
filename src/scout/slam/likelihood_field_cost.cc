#include "scout/slam/likelihood_field_cost.h"

#include <cmath>
#include <cstdint>

#include "scout/grid/distance_transform.h"
#include "scout/grid/probability_values.h"

namespace scout::slam {

LikelihoodField::LikelihoodField(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                                 const PointCloud& points, double margin_m, double sigma_m,
                                 double occupied_probability) {
  const grid::MapLimits& g = grid.limits();
  if (points.empty()) {
    limits_ = grid::MapLimits(g.resolution(), g.origin(), 0, 0);
    return;
  }
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = pose * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const grid::CellIndex min_cell = g.CellContaining(lo - Eigen::Vector2d::Constant(margin_m));
  const grid::CellIndex max_cell = g.CellContaining(hi + Eigen::Vector2d::Constant(margin_m));
  const int width = max_cell.x - min_cell.x + 1;
  const int height = max_cell.y - min_cell.y + 1;
  limits_ = grid::MapLimits(g.resolution(),
                            g.origin() + g.resolution() * Eigen::Vector2d(min_cell.x, min_cell.y),
                            width, height);
  std::vector<uint8_t> is_site(static_cast<size_t>(width) * height, 0);
  const uint16_t threshold = grid::ProbabilityToValue(static_cast<float>(occupied_probability));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint16_t v = grid.value({min_cell.x + x, min_cell.y + y}) & grid::kMaxValue;
      is_site[static_cast<size_t>(y) * width + x] = v != grid::kUnknownValue && v > threshold;
    }
  }
  values_ = grid::SquaredDistanceToNearestSite(is_site, width, height);
  const double factor = -g.resolution() * g.resolution() / (2.0 * sigma_m * sigma_m);
  for (float& v : values_) v = std::isfinite(v) ? static_cast<float>(std::exp(factor * v)) : 0.0f;
}

}  // namespace scout::slam
