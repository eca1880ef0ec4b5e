#include <gtest/gtest.h>

#include <cmath>

#include "scout/common/error.h"
#include "scout/sim/clearance.h"
#include "scout/sim/office_world.h"
#include "scout/synthetic/scan_poses.h"
#include "scout/synthetic/tour_planner.h"

namespace scout::synthetic {
namespace {

// A small office (20 m x 20 m, rooms of 3-4 m) to keep the tests fast.
sim::OfficeWorldOptions SmallOffice() {
  sim::OfficeWorldOptions options;
  options.width_m = 20.0;
  options.height_m = 20.0;
  options.min_room_size_m = 3.0;
  options.max_room_size_m = 4.0;
  return options;
}

bool InsideAny(const Eigen::Vector2d& p, const geometry::Box2d& box) { return box.Contains(p); }

TEST(PlanTour, StaysClearOfObstaclesAndReturnsToStart) {
  const sim::World world = sim::GenerateOfficeWorld(3, SmallOffice());
  const TourOptions options;
  const std::vector<Eigen::Vector2d> tour = PlanTour(world, options);
  ASSERT_GT(tour.size(), 100u);
  EXPECT_EQ(tour.front(), world.start);
  EXPECT_LT((tour.back() - world.start).norm(), 0.1);
  const std::vector<float> clearance = sim::ComputeClearance(world.map);
  const grid::MapLimits& limits = world.map.limits;
  for (const Eigen::Vector2d& p : tour) {
    ASSERT_GE(clearance[limits.FlatIndex(limits.CellContaining(p))], options.min_pose_clearance_m)
        << p.transpose();
  }
}

TEST(PlanTour, VisitsRoomsButNeverSqueezesThroughNarrowGaps) {
  const sim::OfficeWorldOptions world_options = SmallOffice();
  const sim::OfficeLayout layout = sim::PlanOfficeLayout(4, world_options);
  sim::World world;
  world.name = "office";
  world.map = sim::RenderOfficeLayout(layout, world_options.resolution_m);
  world.start = layout.start;
  const std::vector<Eigen::Vector2d> tour = PlanTour(world, TourOptions{});
  int open_rooms = 0, visited = 0;
  for (const sim::OfficeRoom& room : layout.rooms) {
    // Inside the room, beyond the doorway.
    const geometry::Box2d inside = room.interior.Inflated(-0.3);
    bool entered = false;
    for (const Eigen::Vector2d& p : tour) entered = entered || InsideAny(p, inside);
    if (room.door_ajar) {
      EXPECT_FALSE(entered);
    } else {
      ++open_rooms;
      visited += entered ? 1 : 0;
    }
  }
  EXPECT_GE(visited, 0.75 * open_rooms) << visited << " of " << open_rooms;
}

TEST(PlanTour, StartInsideAWallIsAnInputError) {
  sim::World world = sim::GenerateOfficeWorld(3, SmallOffice());
  world.start = Eigen::Vector2d(0.05, 0.05);
  EXPECT_THROW(PlanTour(world, TourOptions{}), InputError);
}

TEST(SampleScanPoses, TakesAScanPerSpacingOfTravelOrTurn) {
  const std::vector<Eigen::Vector2d> tour = {{0, 0}, {10, 0}, {10, 10}};
  const MotionOptions options;
  const std::vector<ScanPose> scans = SampleScanPoses(tour, options, 0);
  // 1 at the start, 50 along x, 90 turning, 50 along y (give or take the last).
  EXPECT_NEAR(static_cast<double>(scans.size()), 191.0, 2.0);
  EXPECT_EQ(scans.front().pose.translation(), Eigen::Vector2d(0, 0));
  EXPECT_NEAR(scans.back().travelled_m, 20.0, 0.21);
  for (size_t i = 1; i < scans.size(); ++i) {
    const double moved = (scans[i].pose.translation() - scans[i - 1].pose.translation()).norm();
    const double turned =
        std::abs(geometry::NormalizeAngle(scans[i].pose.theta() - scans[i - 1].pose.theta()));
    // Exactly one of the two thresholds is reached, the other not exceeded.
    EXPECT_NEAR(std::max(moved / options.scan_spacing_m, turned / options.scan_spacing_rad), 1.0,
                1e-6);
    EXPECT_GT(scans[i].time_s, scans[i - 1].time_s);
  }
}

TEST(SampleScanPoses, StopsAtMaxScans) {
  const std::vector<Eigen::Vector2d> tour = {{0, 0}, {10, 0}};
  EXPECT_EQ(SampleScanPoses(tour, MotionOptions{}, 7).size(), 7u);
}

}  // namespace
}  // namespace scout::synthetic
