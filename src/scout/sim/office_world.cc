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
  // The centre of the start cell, as for the museum and map worlds. Started
  // on a cell corner, the robot's submap grids share the world's cell borders,
  // where every wall's surface lies; each return then sits on a border and
  // the scan matcher's cell-centred interpolation pulls the estimate half a
  // cell (2.5 cm) off, a bias of the raster world that real walls lack.
  world.start = world.map.limits.CellCenter(world.map.limits.CellContaining(layout.start));
  return world;
}

}  // namespace scout::sim
