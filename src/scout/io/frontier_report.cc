#include "scout/io/frontier_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scout/common/atomic_file.h"
#include "scout/grid/image.h"
#include "scout/grid/submap_fusion.h"

namespace scout::io {

void WriteFrontierCsv(const frontier::FrontierEngine& engine, const std::filesystem::path& path) {
  std::ostringstream csv;
  csv << "round,strategy,queried_points,queried_submaps,time_us,tp,fp,tn,fn,local_points\n";
  for (const frontier::StrategyRound& r : engine.rounds()) {
    csv << r.round << ',' << r.strategy << ',' << r.cost.queried_points << ','
        << r.cost.queried_submaps << ',' << static_cast<int64_t>(std::llround(r.cost.time_us))
        << ',' << r.confusion.tp << ',' << r.confusion.fp << ',' << r.confusion.tn << ','
        << r.confusion.fn << ',' << r.local_points << '\n';
  }
  WriteTextFileAtomically(path, csv.str());
}

nlohmann::json FrontierSummary(const frontier::FrontierEngine& engine) {
  nlohmann::json strategies = nlohmann::json::object();
  for (const frontier::StrategyTotals& t : engine.Totals()) {
    nlohmann::json s;
    s["queried_points"] = t.queried_points;
    s["queried_submaps"] = t.queried_submaps;
    s["time_ms"] = t.time_ms;
    // Without the reference nothing was scored: no confusion figures at all
    // rather than the empty matrix's.
    if (engine.evaluating()) {
      s["accuracy"] = t.confusion.accuracy();
      s["precision"] = t.confusion.precision();
      s["recall"] = t.confusion.recall();
      s["tp"] = t.confusion.tp;
      s["fp"] = t.confusion.fp;
      s["tn"] = t.confusion.tn;
      s["fn"] = t.confusion.fn;
    }
    s["P"] = std::isnan(t.performance_p) ? nlohmann::json() : nlohmann::json(t.performance_p);
    s["grid_change_queried_points"] = t.grid_change_queried_points;
    s["grid_change_time_ms"] = t.grid_change_time_ms;
    strategies[t.strategy] = s;
  }
  return {{"strategies", strategies}};
}

void WriteFrontierPicture(const frontier::FrontierEngine& engine, const std::string& strategy,
                          const std::filesystem::path& path, int max_side_px) {
  const frontier::SubmapCatalog& catalog = engine.catalog();
  std::vector<grid::PlacedGrid> placed;
  geometry::Box2d bounds;
  for (int i = 0; i < catalog.size(); ++i) {
    placed.push_back({catalog.submap(i).grid.get(), catalog.submap(i).global_pose});
    bounds.Extend(catalog.submap(i).global_box.min);
    bounds.Extend(catalog.submap(i).global_box.max);
  }
  double resolution = 0.05;
  if (!bounds.empty()) {
    const double side = std::max(bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y());
    resolution = std::max(resolution, side / max_side_px);
  }
  const grid::OccupancyMap fused = grid::FuseSubmaps(placed, resolution);
  const grid::MapLimits& limits = fused.limits;
  grid::Image image;
  image.width = std::max(limits.width(), 1);
  image.height = std::max(limits.height(), 1);
  image.channels = 3;
  image.pixels.assign(static_cast<size_t>(image.width) * image.height * 3, 205);
  // Image rows run top-down; map rows bottom-up.
  const auto pixel = [&](const grid::CellIndex& c) {
    return image.at(c.x, image.height - 1 - c.y);
  };
  for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
    const grid::CellState s = fused.cells[flat];
    if (s == grid::CellState::kUnknown) continue;
    uint8_t* px = pixel(limits.CellOfFlatIndex(flat));
    const uint8_t v = s == grid::CellState::kFree ? 255 : 0;
    px[0] = px[1] = px[2] = v;
  }
  // Tint the known area of the submaps re-queried last round.
  for (const int id : engine.LastRoundSubmaps(strategy)) {
    const frontier::SubmapRecord& r = catalog.submap(id);
    const grid::MapLimits& sl = r.grid->limits();
    for (int y = 0; y < sl.height(); ++y) {
      for (int x = 0; x < sl.width(); ++x) {
        if (r.grid->State({x, y}) != grid::CellState::kFree) continue;
        const grid::CellIndex c = limits.CellContaining(r.global_pose * sl.CellCenter({x, y}));
        if (!limits.Contains(c)) continue;
        uint8_t* px = pixel(c);
        if (px[0] == 255 && px[1] == 255) {
          px[1] = 190;
          px[2] = 190;
        }
      }
    }
  }
  for (const Eigen::Vector2d& g : engine.GlobalFrontier(strategy)) {
    const grid::CellIndex c = limits.CellContaining(g);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const grid::CellIndex n{c.x + dx, c.y + dy};
        if (!limits.Contains(n)) continue;
        uint8_t* px = pixel(n);
        px[0] = 20;
        px[1] = 60;
        px[2] = 230;
      }
    }
  }
  grid::WriteImage(image, path);
}

}  // namespace scout::io
