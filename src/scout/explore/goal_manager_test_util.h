#ifndef SCOUT_EXPLORE_GOAL_MANAGER_TEST_UTIL_H_
#define SCOUT_EXPLORE_GOAL_MANAGER_TEST_UTIL_H_

// Hand-built maps and inputs shared by the goal manager's tests.

#include <string_view>
#include <vector>

#include "scout/explore/goal_manager.h"
#include "scout/explore/test_maps.h"

namespace scout::explore::testing {

// What the exploration loop hands the goal manager at time 't'.
inline ExploreInput InputAt(double t, const Eigen::Vector2d& robot, const grid::OccupancyMap& map,
                            const std::vector<Eigen::Vector2d>& frontier, bool changed) {
  ExploreInput in;
  in.time_s = t;
  in.robot_pose = geometry::Rigid2d(robot, 0.0);
  in.map = &map;
  in.frontier = &frontier;
  in.map_changed = changed;
  return in;
}

// A walled room, known free for x <= 40, unknown beyond: one frontier column.
struct Room {
  MapBuilder b{60, 40};
  std::vector<Eigen::Vector2d> frontier;
  Room() {
    b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
    frontier = b.FrontierPoints();
  }
  ExploreInput Input(double t, const Eigen::Vector2d& robot, bool changed) const {
    return InputAt(t, robot, b.map(), frontier, changed);
  }
};

// The robots of these tests often stand still on purpose (a goal that makes
// no progress): the stuck recovery is off unless a test turns it on.
inline GoalManagerOptions NoStuckRecovery() {
  GoalManagerOptions o;
  o.stuck_timeout_s = 0.0;
  return o;
}

inline GoalManager MakeManager(const GoalManagerOptions& o = NoStuckRecovery(),
                               std::string_view policy = "scout") {
  return GoalManager(o, {}, {}, {}, MakeGoalPolicy(policy, {}));
}

// A wall at x = 20 whose door is 0.7 m wide: narrower than twice the 0.40 m
// inflation (as SLAM's wall noise makes a 0.9 m door), wider than the robot.
struct PinchedDoor {
  MapBuilder b{60, 40};
  std::vector<Eigen::Vector2d> frontier;
  PinchedDoor() {
    b.Wall(0, 0, 59, 39).Fill(1, 1, 58, 38, grid::CellState::kUnknown).Free(1, 1, 40, 38);
    b.Wall(20, 1, 20, 38).Free(20, 15, 20, 21);
    frontier = b.FrontierPoints();
  }
};

}  // namespace scout::explore::testing

#endif  // SCOUT_EXPLORE_GOAL_MANAGER_TEST_UTIL_H_
