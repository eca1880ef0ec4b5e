#include "scout/io/plan_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "scout/grid/image.h"

namespace scout::io {
namespace {

constexpr int kMarginCells = 40;
// A long plan across a large map would make a picture of tens of megapixels:
// fewer pixels per cell keep its larger side near 2400 pixels at most.
constexpr int kMaxSidePx = 2400;
using Rgb = std::array<uint8_t, 3>;

}  // namespace

void WritePlanPicture(const grid::OccupancyMap& map, const PlannedGoal& planned,
                      const std::filesystem::path& path) {
  const grid::MapLimits& limits = map.limits;
  if (limits.num_cells() == 0) throw std::invalid_argument("WritePlanPicture: empty map");
  std::vector<Eigen::Vector2d> points = planned.path;
  points.insert(points.end(), {planned.robot, planned.goal, planned.target});
  int x0 = limits.width() - 1, y0 = limits.height() - 1, x1 = 0, y1 = 0;
  for (const Eigen::Vector2d& p : points) {
    const grid::CellIndex c = limits.CellContaining(p);
    x0 = std::min(x0, c.x);
    y0 = std::min(y0, c.y);
    x1 = std::max(x1, c.x);
    y1 = std::max(y1, c.y);
  }
  // Points off the map still get the map's nearest part drawn.
  x0 = std::clamp(x0 - kMarginCells, 0, limits.width() - 1);
  y0 = std::clamp(y0 - kMarginCells, 0, limits.height() - 1);
  x1 = std::clamp(x1 + kMarginCells, x0, limits.width() - 1);
  y1 = std::clamp(y1 + kMarginCells, y0, limits.height() - 1);

  const int pixels_per_cell = std::clamp(kMaxSidePx / std::max(x1 - x0 + 1, y1 - y0 + 1), 1, 4);
  grid::Image image;
  image.width = (x1 - x0 + 1) * pixels_per_cell;
  image.height = (y1 - y0 + 1) * pixels_per_cell;
  image.channels = 3;
  image.pixels.assign(static_cast<size_t>(image.width) * image.height * 3, 0);
  const auto paint = [&](int x, int y, const Rgb& rgb) {
    if (x < x0 || x > x1 || y < y0 || y > y1) return;
    for (int dy = 0; dy < pixels_per_cell; ++dy) {
      for (int dx = 0; dx < pixels_per_cell; ++dx) {
        uint8_t* px = image.at((x - x0) * pixels_per_cell + dx, (y1 - y) * pixels_per_cell + dy);
        std::copy(rgb.begin(), rgb.end(), px);
      }
    }
  };
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const grid::CellState state = map.at({x, y});
      paint(x, y,
            state == grid::CellState::kFree       ? Rgb{255, 255, 255}
            : state == grid::CellState::kOccupied ? Rgb{0, 0, 0}
                                                  : Rgb{200, 200, 200});
    }
  }
  const auto mark = [&](const Eigen::Vector2d& p, const Rgb& rgb, int radius_cells) {
    const grid::CellIndex c = limits.CellContaining(p);
    for (int dy = -radius_cells; dy <= radius_cells; ++dy) {
      for (int dx = -radius_cells; dx <= radius_cells; ++dx) paint(c.x + dx, c.y + dy, rgb);
    }
  };
  // Half-cell steps along each segment leave no cell of the line out.
  const double step_m = 0.5 * limits.resolution();
  for (size_t i = 1; i < planned.path.size(); ++i) {
    const Eigen::Vector2d a = planned.path[i - 1], b = planned.path[i];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_m)));
    for (int k = 0; k <= n; ++k) mark(a + (b - a) * (static_cast<double>(k) / n), {0, 90, 255}, 0);
  }
  // Returns beyond the path's box are left out rather than enlarging it.
  for (const Eigen::Vector2d& p : planned.scan) mark(p, {220, 0, 220}, 0);
  mark(planned.robot, {0, 170, 0}, 2);
  mark(planned.target, {255, 150, 0}, 1);
  mark(planned.goal, {230, 0, 0}, 1);
  grid::WriteImage(image, path);
}

}  // namespace scout::io
