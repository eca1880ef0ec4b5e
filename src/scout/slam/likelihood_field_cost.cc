#include "scout/slam/likelihood_field_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"
#include "scout/grid/distance_transform.h"
#include "scout/grid/probability_values.h"

namespace scout::slam {

void Validate(const LikelihoodFieldOptions& options, const std::string& section) {
  if (!(options.sigma_m >= 0.0) || !std::isfinite(options.sigma_m)) {
    throw std::invalid_argument(section + "likelihood_field_sigma_m must be finite and >= 0, got " +
                                FormatNumber(options.sigma_m));
  }
  if (!(options.occupied_probability >= grid::kMinProbability - 1e-6 &&
        options.occupied_probability <= grid::kMaxProbability + 1e-6)) {
    throw std::invalid_argument(
        section + "likelihood_field_occupied_probability must be in [0.1, 0.9], got " +
        FormatNumber(options.occupied_probability));
  }
}

LikelihoodField::LikelihoodField(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                                 const PointCloud& points, double margin_m,
                                 const LikelihoodFieldOptions& options) {
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
  // Sites only where the window overlaps the grid; the grid's outside is unknown.
  std::vector<uint8_t> is_site(static_cast<size_t>(width) * height, 0);
  const uint16_t threshold =
      grid::ProbabilityToValue(static_cast<float>(options.occupied_probability));
  const int x_begin = std::max(0, -min_cell.x), x_end = std::min(width, g.width() - min_cell.x);
  const int y_begin = std::max(0, -min_cell.y), y_end = std::min(height, g.height() - min_cell.y);
  const std::vector<uint16_t>& grid_values = grid.values();
  for (int y = y_begin; y < y_end; ++y) {
    const uint16_t* grid_row =
        grid_values.data() + static_cast<size_t>(min_cell.y + y) * g.width() + min_cell.x;
    uint8_t* site_row = is_site.data() + static_cast<size_t>(y) * width;
    for (int x = x_begin; x < x_end; ++x) {
      const uint16_t v = grid_row[x] & grid::kMaxValue;
      site_row[x] = v != grid::kUnknownValue && v > threshold;
    }
  }
  values_ = grid::SquaredDistanceToNearestSite(is_site, width, height);
  // Squared distances between cell centres are whole numbers of cells², so
  // the values of the small ones are tabulated (until they round to 0 as
  // floats, or at most kMaxTabulated), the rest computed alike.
  constexpr int kMaxTabulated = 4096;
  const double factor =
      -g.resolution() * g.resolution() / (2.0 * options.sigma_m * options.sigma_m);
  const auto field_value = [factor](double squared_cells) {
    return static_cast<float>(std::exp(factor * squared_cells));
  };
  std::vector<float> by_squared_distance;
  for (int d2 = 0; d2 < kMaxTabulated && field_value(d2) != 0.0f; ++d2) {
    by_squared_distance.push_back(field_value(d2));
  }
  const bool tail_is_zero = by_squared_distance.size() < static_cast<size_t>(kMaxTabulated);
  const float tabulated = static_cast<float>(by_squared_distance.size());
  for (float& v : values_) {
    if (v < tabulated) {
      v = by_squared_distance[static_cast<size_t>(v)];
    } else {
      v = tail_is_zero || !std::isfinite(v) ? 0.0f : field_value(v);
    }
  }
}

}  // namespace scout::slam
