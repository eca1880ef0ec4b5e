#include "scout/io/map_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "scout/common/error.h"
#include "scout/geometry/box.h"
#include "scout/grid/image.h"
#include "scout/grid/map_io.h"
#include "scout/grid/submap_fusion.h"

namespace scout::io {
namespace {

constexpr double kDefaultResolutionM = 0.05;
constexpr uint8_t kUnknownGrey = 205;  // the map_server shade of unknown
using Rgb = std::array<uint8_t, 3>;
constexpr Rgb kStartColour = {20, 170, 40};
constexpr Rgb kEndColour = {255, 170, 0};
constexpr Rgb kMarkOutline = {0, 0, 0};
constexpr Rgb kPathStartColour = {20, 80, 255};
constexpr Rgb kPathEndColour = {230, 40, 40};
// The coverage picture's cells, by priority (an unmapped cell wins its block).
constexpr Rgb kUnmappedColour = {235, 0, 200};
constexpr Rgb kMappedColour = {255, 255, 255};
constexpr Rgb kWallColour = {0, 0, 0};
constexpr Rgb kUnreachableColour = {228, 228, 228};
constexpr Rgb kUnknownColour = {kUnknownGrey, kUnknownGrey, kUnknownGrey};
// The exploration overlay (WriteFrontierPicture's tint and blue).
constexpr Rgb kHighlightColour = {255, 190, 190};
constexpr Rgb kFrontierColour = {20, 60, 230};
constexpr Rgb kNavigationPointColour = {0, 110, 40};
constexpr Rgb kCandidateColour = {200, 0, 200};
constexpr Rgb kBoundaryColour = {240, 120, 0};
constexpr Rgb kBlacklistedColour = {150, 0, 0};
constexpr Rgb kCrossOutline = {255, 255, 255};

std::vector<grid::PlacedGrid> Placed(const GlobalSubmaps& submaps) {
  std::vector<grid::PlacedGrid> placed;
  for (const auto& [pose, grid] : submaps) {
    if (grid != nullptr) placed.push_back({grid.get(), pose});
  }
  return placed;
}

double FinestResolution(const std::vector<grid::PlacedGrid>& placed) {
  double resolution = 0.0;
  for (const grid::PlacedGrid& s : placed) {
    const double r = s.grid->limits().resolution();
    resolution = resolution == 0.0 ? r : std::min(resolution, r);
  }
  return resolution == 0.0 ? kDefaultResolutionM : resolution;
}

// An RGB canvas over map cells, with rows flipped to image order.
class Canvas {
 public:
  explicit Canvas(const grid::MapLimits& limits) : limits_(limits) {
    image_.width = std::max(limits.width(), 1);
    image_.height = std::max(limits.height(), 1);
    image_.channels = 3;
    image_.pixels.assign(static_cast<size_t>(image_.width) * image_.height * 3, kUnknownGrey);
  }
  const grid::MapLimits& limits() const { return limits_; }
  const grid::Image& image() const { return image_; }

  bool IsWhite(const grid::CellIndex& c) const {
    if (!limits_.Contains(c)) return false;
    const uint8_t* px = image_.at(c.x, image_.height - 1 - c.y);
    return px[0] == 255 && px[1] == 255 && px[2] == 255;
  }
  void Set(const grid::CellIndex& c, const Rgb& rgb) {
    if (!limits_.Contains(c)) return;
    std::copy(rgb.begin(), rgb.end(), image_.at(c.x, image_.height - 1 - c.y));
  }
  // A filled square of half side 'radius' cells, so that a line stays visible
  // on pictures thousands of pixels wide.
  void Stamp(const grid::CellIndex& c, int radius, const Rgb& rgb) {
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) Set({c.x + dx, c.y + dy}, rgb);
    }
  }
  void Disc(const grid::CellIndex& c, int radius, const Rgb& rgb) {
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy <= radius * radius) Set({c.x + dx, c.y + dy}, rgb);
      }
    }
  }
  // Bresenham line from 'from' to 'to' (both inclusive).
  void Line(grid::CellIndex from, const grid::CellIndex& to, int radius, const Rgb& rgb) {
    const int dx = std::abs(to.x - from.x), sx = from.x < to.x ? 1 : -1;
    const int dy = -std::abs(to.y - from.y), sy = from.y < to.y ? 1 : -1;
    int error = dx + dy;
    while (true) {
      Stamp(from, radius, rgb);
      if (from == to) return;
      const int e2 = 2 * error;
      if (e2 >= dy) {
        error += dy;
        from.x += sx;
      }
      if (e2 <= dx) {
        error += dx;
        from.y += sy;
      }
    }
  }

 private:
  grid::MapLimits limits_;
  grid::Image image_;
};

Rgb Blend(const Rgb& from, const Rgb& to, double f) {
  Rgb out;
  for (int k = 0; k < 3; ++k)
    out[k] = static_cast<uint8_t>(std::lround(from[k] + f * (to[k] - from[k])));
  return out;
}

void DrawTrajectory(const std::vector<StampedPose>& trajectory, Canvas& canvas) {
  if (trajectory.empty()) return;
  const int side = std::max(canvas.limits().width(), canvas.limits().height());
  const int line_radius = side >= 600 ? 1 : 0;
  const int mark_radius = std::max(3, side / 150);
  // The canvas covers the trajectory; clamping only moves a pose lying exactly
  // on the max edge into the last cell.
  const auto cell = [&](size_t k) {
    const grid::CellIndex c = canvas.limits().CellContaining(trajectory[k].pose.translation());
    return grid::CellIndex{std::clamp(c.x, 0, canvas.limits().width() - 1),
                           std::clamp(c.y, 0, canvas.limits().height() - 1)};
  };
  for (size_t k = 1; k < trajectory.size(); ++k) {
    const double f = static_cast<double>(k) / (trajectory.size() - 1);
    canvas.Line(cell(k - 1), cell(k), line_radius, Blend(kPathStartColour, kPathEndColour, f));
  }
  // Outlined, so that the marks stand out on the path and on free space alike.
  canvas.Disc(cell(trajectory.size() - 1), mark_radius + 1, kMarkOutline);
  canvas.Disc(cell(trajectory.size() - 1), mark_radius, kEndColour);
  canvas.Disc(cell(0), mark_radius + 1, kMarkOutline);
  canvas.Disc(cell(0), mark_radius, kStartColour);
}

// Clips the segment a-b to 'box' (Liang-Barsky); false when none of it lies
// inside.
bool ClipToBox(const geometry::Box2d& box, Eigen::Vector2d* a, Eigen::Vector2d* b) {
  const Eigen::Vector2d d = *b - *a;
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    const double p[2] = {-d[k], d[k]};
    const double q[2] = {(*a)[k] - box.min[k], box.max[k] - (*a)[k]};
    for (int side = 0; side < 2; ++side) {
      if (p[side] == 0.0) {
        if (q[side] < 0.0) return false;
        continue;
      }
      const double t = q[side] / p[side];
      if (p[side] < 0.0) {
        t0 = std::max(t0, t);
      } else {
        t1 = std::min(t1, t);
      }
    }
  }
  if (t0 > t1) return false;
  const Eigen::Vector2d start = *a;
  *a = start + t0 * d;
  *b = start + t1 * d;
  return true;
}

void DrawOverlayUnderTrajectory(const MapOverlay& overlay, Canvas& canvas) {
  const grid::MapLimits& limits = canvas.limits();
  for (const auto& [pose, grid] : overlay.highlighted_submaps) {
    if (grid == nullptr) continue;
    const grid::MapLimits& sl = grid->limits();
    for (int y = 0; y < sl.height(); ++y) {
      for (int x = 0; x < sl.width(); ++x) {
        if (grid->State({x, y}) != grid::CellState::kFree) continue;
        const grid::CellIndex c = limits.CellContaining(pose * sl.CellCenter({x, y}));
        if (canvas.IsWhite(c)) canvas.Set(c, kHighlightColour);
      }
    }
  }
  const int side = std::max(limits.width(), limits.height());
  const int dot = side >= 1000 ? 1 : 0;
  for (const Eigen::Vector2d& p : overlay.frontier) {
    canvas.Stamp(limits.CellContaining(p), dot, kFrontierColour);
  }
  for (const Eigen::Vector2d& p : overlay.navigation_points) {
    canvas.Disc(limits.CellContaining(p), dot + 1, kNavigationPointColour);
  }
  // Edges are clipped to the picture first: a boundary far larger than the
  // map would otherwise be walked cell by cell far outside it.
  const geometry::Box2d box{
      limits.origin(),
      limits.origin() + limits.resolution() * Eigen::Vector2d(limits.width(), limits.height())};
  for (size_t i = 0; i < overlay.boundary.size(); ++i) {
    Eigen::Vector2d a = overlay.boundary[i];
    Eigen::Vector2d b = overlay.boundary[(i + 1) % overlay.boundary.size()];
    if (ClipToBox(box, &a, &b)) {
      canvas.Line(limits.CellContaining(a), limits.CellContaining(b), dot, kBoundaryColour);
    }
  }
}

void DrawCandidates(const MapOverlay& overlay, Canvas& canvas) {
  const int radius = std::max(2, std::max(canvas.limits().width(), canvas.limits().height()) / 250);
  for (const Eigen::Vector2d& p : overlay.candidates) {
    const grid::CellIndex c = canvas.limits().CellContaining(p);
    canvas.Disc(c, radius + 1, kMarkOutline);
    canvas.Disc(c, radius, kCandidateColour);
  }
}

// A cross as large as a candidate disc, so both stay visible on a large map.
void DrawBlacklistedGoals(const MapOverlay& overlay, Canvas& canvas) {
  const int arm = std::max(3, std::max(canvas.limits().width(), canvas.limits().height()) / 130);
  const int width = arm >= 6 ? 1 : 0;
  for (const Eigen::Vector2d& p : overlay.blacklisted_goals) {
    const grid::CellIndex c = canvas.limits().CellContaining(p);
    // Both outlines first, so the second stroke's outline does not cut the first.
    for (const auto& [rgb, radius] :
         {std::pair{kCrossOutline, width + 1}, std::pair{kBlacklistedColour, width}}) {
      canvas.Line({c.x - arm, c.y - arm}, {c.x + arm, c.y + arm}, radius, rgb);
      canvas.Line({c.x - arm, c.y + arm}, {c.x + arm, c.y - arm}, radius, rgb);
    }
  }
}

}  // namespace

void WriteMapPicture(const GlobalSubmaps& submaps, const std::vector<StampedPose>& trajectory,
                     const std::filesystem::path& path, int max_side_px) {
  WriteMapPicture(submaps, trajectory, MapOverlay{}, path, max_side_px);
}

void WriteMapPicture(const GlobalSubmaps& submaps, const std::vector<StampedPose>& trajectory,
                     const MapOverlay& overlay, const std::filesystem::path& path,
                     int max_side_px) {
  if (max_side_px < 2) throw std::invalid_argument("WriteMapPicture: max_side_px must be >= 2");
  const std::vector<grid::PlacedGrid> placed = Placed(submaps);
  geometry::Box2d bounds;
  for (const grid::PlacedGrid& s : placed) {
    const geometry::Box2d b = geometry::TransformBox(s.global_pose, s.grid->limits().Bounds());
    if (b.empty()) continue;
    bounds.Extend(b.min);
    bounds.Extend(b.max);
  }
  for (const StampedPose& s : trajectory) bounds.Extend(s.pose.translation());
  double resolution = FinestResolution(placed);
  if (!bounds.empty()) {
    // Aligning the origin to the resolution adds up to one cell per side.
    const double side = std::max(bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y());
    resolution = std::max(resolution, side / (max_side_px - 1));
  }
  const grid::OccupancyMap fused = grid::FuseSubmaps(placed, resolution);
  grid::MapLimits limits;
  if (!bounds.empty()) {
    // The same lattice as FuseSubmaps, so fused cells map to canvas cells by
    // an integer shift.
    const Eigen::Vector2d origin(std::floor(bounds.min.x() / resolution) * resolution,
                                 std::floor(bounds.min.y() / resolution) * resolution);
    const int width =
        std::max(1, static_cast<int>(std::ceil((bounds.max.x() - origin.x()) / resolution)));
    const int height =
        std::max(1, static_cast<int>(std::ceil((bounds.max.y() - origin.y()) / resolution)));
    limits = grid::MapLimits(resolution, origin, width, height);
  }
  Canvas canvas(limits);
  for (int64_t flat = 0; flat < fused.limits.num_cells(); ++flat) {
    const grid::CellState s = fused.cells[flat];
    if (s == grid::CellState::kUnknown) continue;
    const grid::CellIndex c =
        limits.CellContaining(fused.limits.CellCenter(fused.limits.CellOfFlatIndex(flat)));
    const uint8_t v = s == grid::CellState::kFree ? 255 : 0;
    canvas.Set(c, {v, v, v});
  }
  DrawOverlayUnderTrajectory(overlay, canvas);
  DrawTrajectory(trajectory, canvas);
  DrawCandidates(overlay, canvas);
  DrawBlacklistedGoals(overlay, canvas);
  grid::WriteImage(canvas.image(), path);
}

void WriteCoveragePicture(const grid::OccupancyMap& world,
                          const std::vector<uint8_t>& coverage_mask,
                          const std::vector<StampedPose>& truth, const std::filesystem::path& path,
                          int max_side_px) {
  const grid::MapLimits& w = world.limits;
  if (max_side_px < 2 || coverage_mask.size() != static_cast<size_t>(w.num_cells()) ||
      world.cells.size() != coverage_mask.size()) {
    throw std::invalid_argument(
        "WriteCoveragePicture: the mask must have a value per world cell and max_side_px >= 2");
  }
  // 'block' world cells a side per pixel.
  const int side = std::max(w.width(), w.height());
  const int block = std::max(1, (side + max_side_px - 1) / max_side_px);
  const grid::MapLimits limits(w.resolution() * block, w.origin(),
                               std::max(1, (w.width() + block - 1) / block),
                               std::max(1, (w.height() + block - 1) / block));
  Canvas canvas(limits);
  // Higher rank wins a block.
  const auto rank = [&](int64_t flat) {
    if (coverage_mask[flat] == 1) return 4;
    if (coverage_mask[flat] == 2) return 3;
    if (world.cells[flat] == grid::CellState::kOccupied) return 2;
    return world.cells[flat] == grid::CellState::kFree ? 1 : 0;
  };
  constexpr std::array<Rgb, 5> kColourOfRank = {kUnknownColour, kUnreachableColour, kWallColour,
                                                kMappedColour, kUnmappedColour};
  std::vector<int> best(static_cast<size_t>(limits.num_cells()), 0);
  for (int y = 0; y < w.height(); ++y) {
    for (int x = 0; x < w.width(); ++x) {
      int& b = best[static_cast<size_t>(y / block) * limits.width() + x / block];
      b = std::max(b, rank(static_cast<int64_t>(y) * w.width() + x));
    }
  }
  for (int y = 0; y < limits.height(); ++y) {
    for (int x = 0; x < limits.width(); ++x) {
      canvas.Set({x, y}, kColourOfRank[best[static_cast<size_t>(y) * limits.width() + x]]);
    }
  }
  DrawTrajectory(truth, canvas);
  grid::WriteImage(canvas.image(), path);
}

double GlobalMapResolution(const GlobalSubmaps& submaps) {
  const std::vector<grid::PlacedGrid> placed = Placed(submaps);
  return grid::ResolutionWithin(placed, FinestResolution(placed), kMaxGlobalMapCells);
}

grid::OccupancyMap FuseGlobalSubmaps(const GlobalSubmaps& submaps) {
  return grid::FuseSubmaps(Placed(submaps), GlobalMapResolution(submaps));
}

void WriteMapServerMap(const GlobalSubmaps& submaps, const std::filesystem::path& yaml_path) {
  grid::OccupancyMap fused = FuseGlobalSubmaps(submaps);
  const double resolution = FinestResolution(Placed(submaps));
  if (fused.limits.num_cells() == 0) {
    // Nothing mapped yet (a run stopped before its first scan saw anything):
    // a map_server map has at least one cell, so the map is one unknown cell
    // at the origin rather than no map at all.
    fused.limits = grid::MapLimits(resolution, Eigen::Vector2d::Zero(), 1, 1);
    fused.cells.assign(1, grid::CellState::kUnknown);
  }
  grid::WriteMapServerMap(fused, yaml_path);
}

}  // namespace scout::io
