#ifndef SCOUT_SIM_OFFICE_FURNITURE_H_
#define SCOUT_SIM_OFFICE_FURNITURE_H_

#include <random>
#include <vector>

#include "scout/geometry/box.h"
#include "scout/sim/office_world.h"

namespace scout::sim {

// Returns furniture boxes for 'room', drawn from 'rng'. Every piece is either
// flush against one or two adjacent walls or at least narrow_gap_m from each
// wall, at least narrow_gap_m from every other piece, and clear of the doorway
// by door_clearance_m. So every free pocket of the room opens through a gap of
// at least narrow_gap_m: the room stays connected for the bare robot.
std::vector<geometry::Box2d> FurnishRoom(const OfficeRoom& room, const OfficeWorldOptions& options,
                                         std::mt19937_64& rng);

}  // namespace scout::sim

#endif  // SCOUT_SIM_OFFICE_FURNITURE_H_
