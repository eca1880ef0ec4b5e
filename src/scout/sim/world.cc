#include "scout/sim/world.h"

#include <cstdint>
#include <vector>

#include "scout/common/error.h"
#include "scout/grid/map_io.h"
#include "scout/sim/clearance.h"

namespace scout::sim {
namespace {

// Returns a label per cell: -1 for non-free cells, else the index of its
// 8-connected free component; 'sizes' receives the cell count per component.
std::vector<int> LabelFreeComponents(const grid::OccupancyMap& map, std::vector<int64_t>* sizes) {
  const grid::MapLimits& limits = map.limits;
  std::vector<int> label(map.cells.size(), -1);
  std::vector<int64_t> stack;
  for (int64_t seed = 0; seed < limits.num_cells(); ++seed) {
    if (map.cells[seed] != grid::CellState::kFree || label[seed] >= 0) continue;
    const int component = static_cast<int>(sizes->size());
    sizes->push_back(0);
    label[seed] = component;
    stack.push_back(seed);
    while (!stack.empty()) {
      const grid::CellIndex cell = limits.CellOfFlatIndex(stack.back());
      stack.pop_back();
      ++sizes->back();
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const grid::CellIndex next{cell.x + dx, cell.y + dy};
          if (!limits.Contains(next)) continue;
          const int64_t flat = limits.FlatIndex(next);
          if (map.cells[flat] != grid::CellState::kFree || label[flat] >= 0) continue;
          label[flat] = component;
          stack.push_back(flat);
        }
      }
    }
  }
  return label;
}

}  // namespace

Eigen::Vector2d ChooseStartPosition(const grid::OccupancyMap& map, const std::string& what) {
  std::vector<int64_t> sizes;
  const std::vector<int> label = LabelFreeComponents(map, &sizes);
  if (sizes.empty()) throw InputError(what + ": the map has no free cell to start in");
  int largest = 0;
  for (int c = 1; c < static_cast<int>(sizes.size()); ++c) {
    if (sizes[c] > sizes[largest]) largest = c;
  }
  const std::vector<float> clearance = ComputeClearance(map);
  int64_t best = -1;
  for (int64_t i = 0; i < map.limits.num_cells(); ++i) {
    if (label[i] == largest && (best < 0 || clearance[i] > clearance[best])) best = i;
  }
  return map.limits.CellCenter(map.limits.CellOfFlatIndex(best));
}

std::string MapWorldName(const std::filesystem::path& yaml) {
  // map_saver writes map.yaml by default, so that stem names nothing; the directory
  // holding it (e.g. hbrs-c069-lab/map.yaml) usually does.
  const std::string stem = yaml.stem().string();
  if (stem != "map") return stem;
  const std::string directory = std::filesystem::absolute(yaml).parent_path().filename().string();
  return directory.empty() ? stem : directory;
}

World LoadMapWorld(const std::filesystem::path& yaml) {
  World world;
  world.name = MapWorldName(yaml);
  world.map = grid::ReadMapServerMap(yaml);
  world.start = ChooseStartPosition(world.map, "map '" + yaml.string() + "'");
  return world;
}

}  // namespace scout::sim
