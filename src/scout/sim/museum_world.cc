#include "scout/sim/museum_world.h"

#include "scout/sim/world_painter.h"

namespace scout::sim {

grid::OccupancyMap RenderMuseumLayout(const MuseumLayout& layout, double resolution_m) {
  grid::OccupancyMap map = MakeFilledMap(layout.building, resolution_m, grid::CellState::kOccupied);
  for (const auto* spaces : {&layout.halls, &layout.corridors, &layout.openings}) {
    for (const geometry::Box2d& box : *spaces) FillBox(box, grid::CellState::kFree, &map);
  }
  for (const auto* obstacles : {&layout.pillars, &layout.exhibits}) {
    for (const geometry::Box2d& box : *obstacles) FillBox(box, grid::CellState::kOccupied, &map);
  }
  return map;
}

World GenerateMuseumWorld(uint64_t seed, const MuseumWorldOptions& options) {
  World world;
  world.name = "museum";
  world.map = RenderMuseumLayout(PlanMuseumLayout(seed, options), options.resolution_m);
  world.start = ChooseStartPosition(world.map, "museum world");
  return world;
}

}  // namespace scout::sim
