#ifndef SCOUT_SIM_MUSEUM_WORLD_H_
#define SCOUT_SIM_MUSEUM_WORLD_H_

#include <cstdint>
#include <vector>

#include "scout/geometry/box.h"
#include "scout/sim/world.h"

namespace scout::sim {

// A generated museum-scale building (ALGORITHMS §8): a grid of big halls
// connected by wide openings, some rows of halls separated by long corridors,
// pillars and exhibit blocks inside the halls.
struct MuseumWorldOptions {
  // Outer extent of the building, including its exterior walls.
  double width_m = 160.0;
  double height_m = 100.0;
  double resolution_m = 0.05;
  // Clear extent of a hall along x and y (halls next to a corridor lose
  // half the corridor width to it).
  double min_hall_size_m = 15.0;
  double max_hall_size_m = 30.0;
  double wall_thickness_m = 0.3;
  // Clear width of a corridor between two rows of halls.
  double corridor_width_m = 4.0;
  // Probability that two neighbouring rows of halls are separated by a
  // corridor rather than by one shared wall.
  double corridor_probability = 0.5;
  // Clear width of an opening between two halls or a hall and a corridor.
  double min_opening_width_m = 3.0;
  double max_opening_width_m = 8.0;
  // Every wall between two connected spaces has 1 to this many openings.
  int max_openings_per_wall = 2;
  // Probability that a hall has a regular grid of square pillars.
  double pillar_hall_probability = 0.4;
  double pillar_size_m = 0.8;
  double pillar_spacing_m = 6.0;
  // Exhibit blocks (axis-aligned boxes) per hall, and their side lengths.
  int min_exhibits_per_hall = 1;
  int max_exhibits_per_hall = 5;
  double min_exhibit_size_m = 1.0;
  double max_exhibit_size_m = 5.0;
  // Free space kept around every exhibit (to walls, pillars, other exhibits)
  // and in front of every opening.
  double exhibit_clearance_m = 2.0;
  // Rejection-sampling attempts per exhibit before it is skipped.
  int exhibit_attempts = 50;
};

// The geometry of a generated museum, metres, world frame.
struct MuseumLayout {
  geometry::Box2d building;
  std::vector<geometry::Box2d> halls;      // clear floors
  std::vector<geometry::Box2d> corridors;  // clear floors
  std::vector<geometry::Box2d> openings;   // cut through walls
  std::vector<geometry::Box2d> pillars;
  std::vector<geometry::Box2d> exhibits;
};

// Returns the layout for 'seed' (deterministic). Throws InputError naming the
// option if the options are inconsistent.
MuseumLayout PlanMuseumLayout(uint64_t seed, const MuseumWorldOptions& options = {});

// Returns the occupancy map of 'layout': walls everywhere except halls,
// corridors and openings; pillars and exhibits occupied.
grid::OccupancyMap RenderMuseumLayout(const MuseumLayout& layout, double resolution_m);

// Returns the world "museum" for 'seed', starting at ChooseStartPosition.
World GenerateMuseumWorld(uint64_t seed, const MuseumWorldOptions& options = {});

}  // namespace scout::sim

#endif  // SCOUT_SIM_MUSEUM_WORLD_H_
