// PlanOfficeLayout: corridor loop, rooms, doors and furniture of an office.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/box_util.h"
#include "scout/sim/office_furniture.h"
#include "scout/sim/office_world.h"
#include "scout/sim/random.h"
#include "scout/sim/world_options_check.h"

namespace scout::sim {
namespace {

void RequireOfficeOption(bool ok, const std::string& key, double value,
                         const std::string& expected) {
  RequireWorldOption(ok, "office world", key, value, expected);
}

void Validate(const OfficeWorldOptions& o) {
  RequireOfficeOption(o.resolution_m > 0.0, "resolution_m", o.resolution_m, "> 0");
  RequireOfficeOption(o.wall_thickness_m >= o.resolution_m, "wall_thickness_m", o.wall_thickness_m,
                      ">= resolution_m");
  RequireOfficeOption(o.corridor_width_m > 0.0, "corridor_width_m", o.corridor_width_m, "> 0");
  RequireOfficeOption(o.min_room_size_m > 0.0, "min_room_size_m", o.min_room_size_m, "> 0");
  RequireOfficeOption(o.max_room_size_m >= o.min_room_size_m, "max_room_size_m", o.max_room_size_m,
                      ">= min_room_size_m");
  RequireOfficeOption(o.min_door_width_m > 0.0, "min_door_width_m", o.min_door_width_m, "> 0");
  RequireOfficeOption(o.max_door_width_m >= o.min_door_width_m &&
                          o.max_door_width_m + 2.0 * o.wall_thickness_m <= o.min_room_size_m,
                      "max_door_width_m", o.max_door_width_m,
                      ">= min_door_width_m and fitting a room of min_room_size_m");
  RequireOfficeOption(o.narrow_gap_m > 0.0 && o.narrow_gap_m < o.min_door_width_m, "narrow_gap_m",
                      o.narrow_gap_m, "in (0, min_door_width_m)");
  RequireOfficeOption(o.ajar_door_fraction >= 0.0 && o.ajar_door_fraction <= 1.0,
                      "ajar_door_fraction", o.ajar_door_fraction, "in [0, 1]");
  RequireOfficeOption(o.min_furniture_per_room >= 0, "min_furniture_per_room",
                      o.min_furniture_per_room, ">= 0");
  RequireOfficeOption(o.max_furniture_per_room >= o.min_furniture_per_room,
                      "max_furniture_per_room", o.max_furniture_per_room,
                      ">= min_furniture_per_room");
  RequireOfficeOption(o.min_furniture_size_m > 0.0, "min_furniture_size_m", o.min_furniture_size_m,
                      "> 0");
  RequireOfficeOption(o.max_furniture_size_m >= o.min_furniture_size_m, "max_furniture_size_m",
                      o.max_furniture_size_m, ">= min_furniture_size_m");
  RequireOfficeOption(o.door_clearance_m >= 0.0, "door_clearance_m", o.door_clearance_m, ">= 0");
  RequireOfficeOption(o.furniture_attempts >= 1, "furniture_attempts", o.furniture_attempts,
                      ">= 1");
  const double t = o.wall_thickness_m;
  const double c = o.corridor_width_m;
  const double min_width = 6 * t + 2 * c + 2 * o.max_room_size_m + o.min_room_size_m;
  RequireOfficeOption(o.width_m >= min_width, "width_m", o.width_m,
                      ">= " + FormatNumber(min_width) + " for these room and corridor sizes");
  const double min_height = 7 * t + 2 * c + 2 * o.max_room_size_m + 2 * o.min_room_size_m;
  RequireOfficeOption(o.height_m >= min_height, "height_m", o.height_m,
                      ">= " + FormatNumber(min_height) + " for these room and corridor sizes");
}

// The clear intervals of the plan along one axis: rooms, corridor, inner block,
// corridor, rooms, separated by walls.
struct AxisPlan {
  Interval low_rooms, low_corridor, inner, high_corridor, high_rooms;
};

AxisPlan PlanAxis(double extent_m, double low_depth_m, double high_depth_m,
                  const OfficeWorldOptions& o) {
  const double t = o.wall_thickness_m;
  const double c = o.corridor_width_m;
  AxisPlan plan;
  plan.low_rooms = {t, t + low_depth_m};
  plan.low_corridor = {plan.low_rooms.hi + t, plan.low_rooms.hi + t + c};
  plan.high_rooms = {extent_m - t - high_depth_m, extent_m - t};
  plan.high_corridor = {plan.high_rooms.lo - t - c, plan.high_rooms.lo - t};
  plan.inner = {plan.low_corridor.hi + t, plan.high_corridor.lo - t};
  return plan;
}

// One row of rooms along a wall facing a corridor bar.
struct RoomRow {
  std::vector<Interval> spaces;  // clear extent of each room along the wall
  Interval depth;                // clear extent of the rooms across the wall
  Interval wall;                 // the wall between the rooms and the corridor
  Interval corridor_span;        // clear extent of the corridor bar along the wall
  bool along_x = true;           // the wall runs along x
};

void AddRooms(const RoomRow& row, const OfficeWorldOptions& o, std::mt19937_64& rng,
              std::vector<OfficeRoom>* rooms, std::vector<bool>* along_x) {
  const double t = o.wall_thickness_m;
  for (const Interval& space : row.spaces) {
    const Interval usable{std::max(space.lo, row.corridor_span.lo) + t,
                          std::min(space.hi, row.corridor_span.hi) - t};
    const double width =
        std::min(UniformReal(rng, o.min_door_width_m, o.max_door_width_m), usable.length());
    const double start = UniformReal(rng, usable.lo, usable.hi - width);
    const Interval door{start, start + width};
    OfficeRoom room;
    room.interior = row.along_x ? MakeBox(space, row.depth) : MakeBox(row.depth, space);
    room.doorway = row.along_x ? MakeBox(door, row.wall) : MakeBox(row.wall, door);
    rooms->push_back(room);
    along_x->push_back(row.along_x);
  }
}

// Leaves the door of some rooms ajar: only narrow_gap_m of the doorway stays open.
void SetDoorsAjar(const std::vector<bool>& along_x, const OfficeWorldOptions& o,
                  std::mt19937_64& rng, std::vector<OfficeRoom>* rooms) {
  const int n = static_cast<int>(rooms->size());
  const int count = std::clamp(static_cast<int>(std::lround(o.ajar_door_fraction * n)), 1, n);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  for (int i = 0; i < count; ++i) {
    std::swap(order[i], order[UniformInt(rng, i, n - 1)]);
    OfficeRoom& room = (*rooms)[order[i]];
    room.door_ajar = true;
    const int axis = along_x[order[i]] ? 0 : 1;
    room.doorway.max[axis] = room.doorway.min[axis] + o.narrow_gap_m;
  }
}

}  // namespace

OfficeLayout PlanOfficeLayout(uint64_t seed, const OfficeWorldOptions& o) {
  Validate(o);
  std::mt19937_64 rng(seed);
  const auto depth = [&] { return UniformReal(rng, o.min_room_size_m, o.max_room_size_m); };
  const double bottom = depth(), top = depth(), left = depth(), right = depth();
  const AxisPlan x = PlanAxis(o.width_m, left, right, o);
  const AxisPlan y = PlanAxis(o.height_m, bottom, top, o);
  const double t = o.wall_thickness_m;

  OfficeLayout layout;
  layout.building =
      geometry::Box2d(Eigen::Vector2d::Zero(), Eigen::Vector2d(o.width_m, o.height_m));
  const Interval loop_x{x.low_corridor.lo, x.high_corridor.hi};
  const Interval loop_y{y.low_corridor.lo, y.high_corridor.hi};
  layout.corridors = {MakeBox(loop_x, y.low_corridor), MakeBox(loop_x, y.high_corridor),
                      MakeBox(x.low_corridor, loop_y), MakeBox(x.high_corridor, loop_y)};
  layout.start = layout.corridors[0].Center();

  const auto split = [&](const Interval& span) {
    return SplitIntoSpaces(span.lo, span.hi, t, o.min_room_size_m, o.max_room_size_m, rng);
  };
  // Outer rows along x span the corridor and extend into the building corners.
  const auto corner_rooms = [&](std::vector<Interval> spaces) {
    spaces.front().lo = t;
    spaces.back().hi = o.width_m - t;
    return spaces;
  };
  const double mid = 0.5 * (y.inner.lo + y.inner.hi);
  const Interval inner_low{y.inner.lo, mid - 0.5 * t};
  const Interval inner_high{mid + 0.5 * t, y.inner.hi};
  const std::vector<RoomRow> rows = {
      {corner_rooms(split(loop_x)), y.low_rooms, {y.low_rooms.hi, y.low_corridor.lo}, loop_x, true},
      {corner_rooms(split(loop_x)),
       y.high_rooms,
       {y.high_corridor.hi, y.high_rooms.lo},
       loop_x,
       true},
      {split(loop_y), x.low_rooms, {x.low_rooms.hi, x.low_corridor.lo}, loop_y, false},
      {split(loop_y), x.high_rooms, {x.high_corridor.hi, x.high_rooms.lo}, loop_y, false},
      {split(x.inner), inner_low, {y.low_corridor.hi, inner_low.lo}, loop_x, true},
      {split(x.inner), inner_high, {inner_high.hi, y.high_corridor.lo}, loop_x, true},
  };
  std::vector<bool> along_x;
  for (const RoomRow& row : rows) AddRooms(row, o, rng, &layout.rooms, &along_x);
  SetDoorsAjar(along_x, o, rng, &layout.rooms);
  for (const OfficeRoom& room : layout.rooms) {
    const std::vector<geometry::Box2d> pieces = FurnishRoom(room, o, rng);
    layout.furniture.insert(layout.furniture.end(), pieces.begin(), pieces.end());
  }
  return layout;
}

}  // namespace scout::sim
