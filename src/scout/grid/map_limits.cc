#include "scout/grid/map_limits.h"

#include <stdexcept>
#include <string>

namespace scout::grid {

MapLimits::MapLimits(double resolution_m, const Eigen::Vector2d& origin, int width, int height)
    : resolution_(resolution_m), origin_(origin), width_(width), height_(height) {
  // Checked here so that every MapLimits in existence maps points to cells sanely:
  // a zero, negative or NaN resolution would turn CellContaining into garbage.
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw std::invalid_argument("MapLimits: resolution must be a positive finite number, got " +
                                std::to_string(resolution_m));
  }
  // A non-finite origin would poison every cell centre; rejected for the same reason.
  if (!origin.allFinite()) {
    throw std::invalid_argument("MapLimits: origin must be finite");
  }
  if (width < 0 || height < 0) {
    throw std::invalid_argument("MapLimits: width and height must be >= 0, got " +
                                std::to_string(width) + " x " + std::to_string(height));
  }
}

}  // namespace scout::grid
