#include "scout/sim/office_world.h"

#include "scout/sim/world_painter.h"

namespace scout::sim {

grid::OccupancyMap RenderOfficeLayout(const OfficeLayout& layout, double resolution_m) {
  grid::OccupancyMap map = MakeFilledMap(layout.building, resolution_m, grid::CellState::kOccupied);
  for (const geometry::Box2d& corridor : layout.corridors) {
    FillBox(corridor, grid::CellState::kFree, &map);
  }
  for (const OfficeRoom& room : layout.rooms) {
    FillBox(room.interior, grid::CellState::kFree, &map);
    FillBox(room.doorway, grid::CellState::kFree, &map);
  }
  for (const geometry::Box2d& piece : layout.furniture) {
    FillBox(piece, grid::CellState::kOccupied, &map);
  }
  return map;
}

World GenerateOfficeWorld(uint64_t seed, const OfficeWorldOptions& options) {
  const OfficeLayout layout = PlanOfficeLayout(seed, options);
  World world;
  world.name = "office";
  world.map = RenderOfficeLayout(layout, options.resolution_m);
  world.start = layout.start;
  return world;
}

}  // namespace scout::sim
