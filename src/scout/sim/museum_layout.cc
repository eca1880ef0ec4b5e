// PlanMuseumLayout: halls, corridors, openings, pillars and exhibits.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/box_util.h"
#include "scout/sim/museum_world.h"
#include "scout/sim/random.h"
#include "scout/sim/world_options_check.h"

namespace scout::sim {
namespace {

void RequireMuseumOption(bool ok, const std::string& key, double value,
                         const std::string& expected) {
  RequireWorldOption(ok, "museum world", key, value, expected);
}

void Validate(const MuseumWorldOptions& o) {
  RequireMuseumOption(o.resolution_m > 0.0, "resolution_m", o.resolution_m, "> 0");
  RequireMuseumOption(o.wall_thickness_m >= o.resolution_m, "wall_thickness_m", o.wall_thickness_m,
                      ">= resolution_m");
  RequireMuseumOption(o.min_hall_size_m > 2.0 * o.wall_thickness_m, "min_hall_size_m",
                      o.min_hall_size_m, "> 2 * wall_thickness_m");
  RequireMuseumOption(o.max_hall_size_m >= o.min_hall_size_m, "max_hall_size_m", o.max_hall_size_m,
                      ">= min_hall_size_m");
  const double min_side_m = o.min_hall_size_m + 2.0 * o.wall_thickness_m;
  const std::string at_least =
      ">= " + FormatNumber(min_side_m) + " (min_hall_size_m + 2 * wall_thickness_m)";
  RequireMuseumOption(o.width_m >= min_side_m, "width_m", o.width_m, at_least);
  RequireMuseumOption(o.height_m >= min_side_m, "height_m", o.height_m, at_least);
  RequireMuseumOption(o.corridor_width_m > 0.0, "corridor_width_m", o.corridor_width_m, "> 0");
  RequireMuseumOption(o.corridor_probability >= 0.0 && o.corridor_probability <= 1.0,
                      "corridor_probability", o.corridor_probability, "in [0, 1]");
  RequireMuseumOption(o.min_opening_width_m > 0.0, "min_opening_width_m", o.min_opening_width_m,
                      "> 0");
  RequireMuseumOption(o.max_opening_width_m >= o.min_opening_width_m, "max_opening_width_m",
                      o.max_opening_width_m, ">= min_opening_width_m");
  RequireMuseumOption(o.max_openings_per_wall >= 1, "max_openings_per_wall",
                      o.max_openings_per_wall, ">= 1");
  RequireMuseumOption(o.pillar_hall_probability >= 0.0 && o.pillar_hall_probability <= 1.0,
                      "pillar_hall_probability", o.pillar_hall_probability, "in [0, 1]");
  RequireMuseumOption(o.pillar_size_m > 0.0 && o.pillar_size_m < o.pillar_spacing_m,
                      "pillar_size_m", o.pillar_size_m, "in (0, pillar_spacing_m)");
  RequireMuseumOption(o.min_exhibits_per_hall >= 0, "min_exhibits_per_hall",
                      o.min_exhibits_per_hall, ">= 0");
  RequireMuseumOption(o.max_exhibits_per_hall >= o.min_exhibits_per_hall, "max_exhibits_per_hall",
                      o.max_exhibits_per_hall, ">= min_exhibits_per_hall");
  RequireMuseumOption(o.min_exhibit_size_m > 0.0, "min_exhibit_size_m", o.min_exhibit_size_m,
                      "> 0");
  RequireMuseumOption(o.max_exhibit_size_m >= o.min_exhibit_size_m, "max_exhibit_size_m",
                      o.max_exhibit_size_m, ">= min_exhibit_size_m");
  RequireMuseumOption(o.exhibit_clearance_m >= 0.0, "exhibit_clearance_m", o.exhibit_clearance_m,
                      ">= 0");
  RequireMuseumOption(o.exhibit_attempts >= 1, "exhibit_attempts", o.exhibit_attempts, ">= 1");
}

// Cuts 1..max_openings_per_wall openings through the wall 'wall' (across)
// between two spaces sharing the clear extent 'span' (along the wall).
void AddOpenings(const Interval& span, const Interval& wall, bool along_x,
                 const MuseumWorldOptions& o, std::mt19937_64& rng, MuseumLayout* layout) {
  const int count = UniformInt(rng, 1, o.max_openings_per_wall);
  const double part = (span.length() - 2.0 * o.wall_thickness_m) / count;
  for (int i = 0; i < count; ++i) {
    const double part_lo = span.lo + o.wall_thickness_m + i * part;
    const double width =
        std::min(UniformReal(rng, o.min_opening_width_m, o.max_opening_width_m), part);
    const double start = UniformReal(rng, part_lo, part_lo + part - width);
    const Interval opening{start, start + width};
    layout->openings.push_back(along_x ? MakeBox(opening, wall) : MakeBox(wall, opening));
  }
}

bool OverlapsAny(const geometry::Box2d& box, const std::vector<geometry::Box2d>& others) {
  return std::any_of(others.begin(), others.end(),
                     [&](const geometry::Box2d& other) { return BoxesOverlap(box, other); });
}

void AddPillars(const geometry::Box2d& hall, const std::vector<geometry::Box2d>& keep_clear,
                const MuseumWorldOptions& o, MuseumLayout* layout) {
  const Eigen::Vector2d size = hall.max - hall.min;
  const int nx = static_cast<int>(std::floor(size.x() / o.pillar_spacing_m));
  const int ny = static_cast<int>(std::floor(size.y() / o.pillar_spacing_m));
  const Eigen::Vector2d first =
      hall.min + 0.5 * (size - Eigen::Vector2d(nx - 1, ny - 1) * o.pillar_spacing_m);
  const Eigen::Vector2d half = Eigen::Vector2d::Constant(0.5 * o.pillar_size_m);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Eigen::Vector2d centre = first + Eigen::Vector2d(i, j) * o.pillar_spacing_m;
      const geometry::Box2d pillar(centre - half, centre + half);
      if (!OverlapsAny(pillar, keep_clear)) layout->pillars.push_back(pillar);
    }
  }
}

void AddExhibits(const geometry::Box2d& hall, const std::vector<geometry::Box2d>& keep_clear,
                 const MuseumWorldOptions& o, std::mt19937_64& rng, MuseumLayout* layout) {
  const geometry::Box2d area = hall.Inflated(-o.exhibit_clearance_m);
  std::vector<geometry::Box2d> obstacles;
  for (const geometry::Box2d& pillar : layout->pillars) {
    if (BoxDistance(pillar, hall) == 0.0) obstacles.push_back(pillar);
  }
  const int count = UniformInt(rng, o.min_exhibits_per_hall, o.max_exhibits_per_hall);
  for (int i = 0; i < count; ++i) {
    for (int attempt = 0; attempt < o.exhibit_attempts; ++attempt) {
      const double width = UniformReal(rng, o.min_exhibit_size_m, o.max_exhibit_size_m);
      const double height = UniformReal(rng, o.min_exhibit_size_m, o.max_exhibit_size_m);
      const double x = UniformReal(rng, area.min.x(), area.max.x() - width);
      const double y = UniformReal(rng, area.min.y(), area.max.y() - height);
      const geometry::Box2d exhibit(Eigen::Vector2d(x, y), Eigen::Vector2d(x + width, y + height));
      if (exhibit.max.x() > area.max.x() || exhibit.max.y() > area.max.y()) continue;
      if (OverlapsAny(exhibit, keep_clear)) continue;
      const bool crowded =
          std::any_of(obstacles.begin(), obstacles.end(), [&](const geometry::Box2d& other) {
            return BoxDistance(exhibit, other) < o.exhibit_clearance_m;
          });
      if (crowded) continue;
      obstacles.push_back(exhibit);
      layout->exhibits.push_back(exhibit);
      break;
    }
  }
}

}  // namespace

MuseumLayout PlanMuseumLayout(uint64_t seed, const MuseumWorldOptions& o) {
  Validate(o);
  std::mt19937_64 rng(seed);
  const double t = o.wall_thickness_m;
  MuseumLayout layout;
  layout.building =
      geometry::Box2d(Eigen::Vector2d::Zero(), Eigen::Vector2d(o.width_m, o.height_m));
  const std::vector<Interval> columns =
      SplitIntoSpaces(t, o.width_m - t, t, o.min_hall_size_m, o.max_hall_size_m, rng);
  // A boundary between two rows of halls is either one wall or a corridor
  // with a wall on each side.
  std::vector<bool> corridor_above;
  const auto row_separator_m = [&] {
    corridor_above.push_back(Bernoulli(rng, o.corridor_probability));
    return corridor_above.back() ? o.corridor_width_m + 2.0 * t : t;
  };
  const std::vector<Interval> rows = SplitIntoSpaces(t, o.height_m - t, row_separator_m,
                                                     o.min_hall_size_m, o.max_hall_size_m, rng);
  corridor_above.resize(rows.size(), false);
  const Interval full_x{t, o.width_m - t};
  for (size_t r = 0; r + 1 < rows.size(); ++r) {
    if (corridor_above[r]) {
      layout.corridors.push_back(MakeBox(full_x, {rows[r].hi + t, rows[r + 1].lo - t}));
    }
  }
  for (const Interval& row : rows) {
    for (const Interval& column : columns) layout.halls.push_back(MakeBox(column, row));
  }

  size_t corridor_index = 0;
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c + 1 < columns.size(); ++c) {
      AddOpenings(rows[r], {columns[c].hi, columns[c + 1].lo}, false, o, rng, &layout);
    }
    if (r + 1 == rows.size()) continue;
    for (const Interval& column : columns) {
      if (!corridor_above[r]) {
        AddOpenings(column, {rows[r].hi, rows[r + 1].lo}, true, o, rng, &layout);
        continue;
      }
      const geometry::Box2d& corridor = layout.corridors[corridor_index];
      AddOpenings(column, {rows[r].hi, corridor.min.y()}, true, o, rng, &layout);
      AddOpenings(column, {corridor.max.y(), rows[r + 1].lo}, true, o, rng, &layout);
    }
    if (corridor_above[r]) ++corridor_index;
  }

  std::vector<geometry::Box2d> keep_clear;
  for (const geometry::Box2d& opening : layout.openings) {
    keep_clear.push_back(opening.Inflated(o.exhibit_clearance_m));
  }
  for (const geometry::Box2d& hall : layout.halls) {
    if (Bernoulli(rng, o.pillar_hall_probability)) AddPillars(hall, keep_clear, o, &layout);
    AddExhibits(hall, keep_clear, o, rng, &layout);
  }
  return layout;
}

}  // namespace scout::sim
