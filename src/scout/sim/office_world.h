#ifndef SCOUT_SIM_OFFICE_WORLD_H_
#define SCOUT_SIM_OFFICE_WORLD_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "scout/geometry/box.h"
#include "scout/sim/world.h"

namespace scout::sim {

// A generated office floor (ALGORITHMS §8): a corridor loop with rooms on both
// sides (outer rooms along the exterior walls, inner rooms in the block the
// loop encloses), one door per room onto the corridor, furniture in the rooms,
// and some gaps narrower than the inflated robot (doors left ajar).
struct OfficeWorldOptions {
  // Outer extent of the building, including its exterior walls.
  double width_m = 40.0;
  double height_m = 30.0;
  double resolution_m = 0.05;
  // Clear width of the corridor loop.
  double corridor_width_m = 2.0;
  // Clear extent of a room along the corridor, and clear depth of outer rooms.
  // Inner rooms take half the depth of the enclosed block; corner rooms extend
  // to the building corner.
  double min_room_size_m = 3.0;
  double max_room_size_m = 6.0;
  // Clear width of a doorway.
  double min_door_width_m = 0.9;
  double max_door_width_m = 1.2;
  double wall_thickness_m = 0.15;
  // Clear width of a door left ajar, and the smallest gap between two pieces of
  // furniture or a piece and a wall (pieces closer to a wall are pushed flush
  // against it). 0.5 m fits the bare robot (0.40 m across) but not the robot
  // inflated by its safety margin (2 x 0.40 m).
  double narrow_gap_m = 0.5;
  // Fraction of rooms whose door is ajar; at least one room always is.
  double ajar_door_fraction = 0.15;
  // Furniture (desks, tables, chairs, posts: axis-aligned boxes) per room.
  int min_furniture_per_room = 2;
  int max_furniture_per_room = 6;
  // Side lengths of a piece of furniture, drawn independently per side.
  double min_furniture_size_m = 0.25;
  double max_furniture_size_m = 1.6;
  // Depth inside a room, in front of its door, that stays free of furniture.
  double door_clearance_m = 1.2;
  // Rejection-sampling attempts per piece of furniture before it is skipped.
  int furniture_attempts = 50;
};

struct OfficeRoom {
  // Clear floor of the room (before furniture).
  geometry::Box2d interior;
  // The opening cut through the wall between the room and the corridor.
  geometry::Box2d doorway;
  // True if the door is ajar: the doorway is only narrow_gap_m wide.
  bool door_ajar = false;
};

// The geometry of a generated office, metres, world frame.
struct OfficeLayout {
  geometry::Box2d building;
  // Four clear corridor bars (bottom, top, left, right) forming the loop.
  std::vector<geometry::Box2d> corridors;
  std::vector<OfficeRoom> rooms;
  std::vector<geometry::Box2d> furniture;
  // The centre of the bottom corridor bar.
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
};

// Returns the layout for 'seed' (deterministic). Throws InputError naming the
// option if the options are inconsistent or the building is too small.
OfficeLayout PlanOfficeLayout(uint64_t seed, const OfficeWorldOptions& options = {});

// Returns the occupancy map of 'layout': everything is wall except the
// corridors, room interiors and doorways, which are free, and furniture.
grid::OccupancyMap RenderOfficeLayout(const OfficeLayout& layout, double resolution_m);

// Returns the world "office" for 'seed': PlanOfficeLayout rendered.
World GenerateOfficeWorld(uint64_t seed, const OfficeWorldOptions& options = {});

}  // namespace scout::sim

#endif  // SCOUT_SIM_OFFICE_WORLD_H_
