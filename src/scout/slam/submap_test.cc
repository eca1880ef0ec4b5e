#include "scout/slam/submap.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <stdexcept>

#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

// A scan of the room from 'pose', in the local frame.
struct LocalScan {
  PointCloud returns;
  PointCloud misses;
};
LocalScan ScanAt(const Rigid2d& pose) {
  const sensor::RangeData data = sensor::ToRangeData(testing::CastScan(testing::Room(), pose), {});
  return {TransformPointCloud(data.returns, pose), TransformPointCloud(data.misses, pose)};
}

TEST(ActiveSubmapsTest, NumbersDenselyAndFinishesAfterTwiceNumRangeData) {
  ActiveSubmaps active(SubmapOptions{});  // 70 scans per submap
  const LocalScan scan = ScanAt(Rigid2d(0.1, 0.2, 0.0));
  std::vector<std::pair<int, events::SubmapId>> created;   // (scan index, id)
  std::vector<std::pair<int, events::SubmapId>> finished;  // (scan index, id)
  for (int i = 0; i < 300; ++i) {
    const ActiveSubmaps::Insertion insertion =
        active.InsertRangeData({0.1, 0.2}, scan.returns, scan.misses);
    for (const events::SubmapId id : insertion.created) created.push_back({i, id});
    for (const events::SubmapId id : insertion.finished) finished.push_back({i, id});
    ASSERT_EQ(insertion.submaps.size(), i < 70 ? 1u : 2u) << "scan " << i;
    // Every scan goes into the newest submap.
    EXPECT_EQ(insertion.submaps.back()->id(), i / 70);
  }
  const std::vector<std::pair<int, events::SubmapId>> expected_created = {
      {0, 0}, {70, 1}, {140, 2}, {210, 3}, {280, 4}};
  const std::vector<std::pair<int, events::SubmapId>> expected_finished = {
      {139, 0}, {209, 1}, {279, 2}};
  EXPECT_EQ(created, expected_created);
  EXPECT_EQ(finished, expected_finished);
  ASSERT_EQ(active.submaps().size(), 2u);
  EXPECT_EQ(active.submaps()[0]->num_range_data(), 90);  // submap 3: scans 210..299
  EXPECT_EQ(active.submaps()[1]->num_range_data(), 20);  // submap 4: scans 280..299
  EXPECT_EQ(active.num_submaps_created(), 5);
}

TEST(ActiveSubmapsTest, StartsTheNextSubmapAfterMaxTravelWhenScansAreSparse) {
  SubmapOptions options;  // 70 scans or 15 m
  options.max_travel_m = 15.0;
  ActiveSubmaps active(options);
  std::vector<int> created_at, finished_at;  // scan indices
  for (int i = 0; i < 60; ++i) {
    // One scan per metre along x: 15 m of travel after 16 scans.
    const Rigid2d pose(0.1 + 1.0 * i, 0.2, 0.0);
    const LocalScan scan = ScanAt(Rigid2d(0.1, 0.2, 0.0));
    const ActiveSubmaps::Insertion insertion = active.InsertRangeData(
        pose.translation(), TransformPointCloud(scan.returns, Rigid2d(1.0 * i, 0.0, 0.0)),
        TransformPointCloud(scan.misses, Rigid2d(1.0 * i, 0.0, 0.0)));
    if (!insertion.created.empty()) created_at.push_back(i);
    if (!insertion.finished.empty()) finished_at.push_back(i);
  }
  EXPECT_EQ(created_at, (std::vector<int>{0, 16, 32, 48}));
  // The older one finishes with the scan that makes the newer half full.
  EXPECT_EQ(finished_at, (std::vector<int>{31, 47}));
  EXPECT_NEAR(active.submaps().front()->travel_m(), 27.0, 1e-9);  // scans 32..59

  // Dense scans never reach the travel limit: 70 scans per submap as before.
  ActiveSubmaps dense(options);
  const LocalScan scan = ScanAt(Rigid2d(0.1, 0.2, 0.0));
  for (int i = 0; i < 141; ++i) {
    const ActiveSubmaps::Insertion insertion =
        dense.InsertRangeData({0.1 + 0.1 * i, 0.2}, scan.returns, scan.misses);
    if (i == 70) {
      EXPECT_EQ(insertion.created, std::vector<events::SubmapId>{1});
    }
    if (i == 139) {
      EXPECT_EQ(insertion.finished, std::vector<events::SubmapId>{0});
    }
  }
}

TEST(SubmapTest, FramesGrowthAndOrigins) {
  const grid::RangeDataInserter inserter({});
  Submap submap(3, {1.0, 2.0}, 0.05);
  EXPECT_EQ(submap.grid()->limits().num_cells(), 0);
  const Rigid2d pose(1.0, 2.0, 0.3);
  const LocalScan scan = ScanAt(pose);
  submap.InsertRangeData(pose.translation(), scan.returns, scan.misses, inserter);
  submap.InsertRangeData({1.5, 2.0}, scan.returns, scan.misses, inserter);
  EXPECT_EQ(submap.num_range_data(), 2);
  EXPECT_EQ(submap.local_pose().theta(), 0.0);
  ASSERT_EQ(submap.scan_origins().size(), 2u);
  EXPECT_NEAR(submap.scan_origins()[0].norm(), 0.0, 1e-12);
  EXPECT_NEAR(submap.scan_origins()[1].x(), 0.5, 1e-12);
  // A return of the scan is occupied in the submap frame.
  const auto grid = submap.grid();
  const grid::CellIndex wall =
      grid->limits().CellContaining(submap.local_pose().inverse() * scan.returns[180]);
  EXPECT_GT(grid->GetProbability(wall), 0.5f);
  const events::SubmapChanged event = submap.ToEvent();
  EXPECT_EQ(event.id, 3);
  EXPECT_EQ(event.grid, grid);
  submap.Finish();
  EXPECT_THROW(submap.InsertRangeData({0.0, 0.0}, scan.returns, scan.misses, inserter),
               std::logic_error);
}

TEST(SubmapTest, SnapshotsStayImmutableAndCopiesOnlyWhenHeld) {
  const grid::RangeDataInserter inserter({});
  Submap submap(0, {0.0, 0.0}, 0.05);
  const LocalScan first = ScanAt(Rigid2d(0.0, 0.0, 0.0));
  const LocalScan second = ScanAt(Rigid2d(-2.0, 1.0, 0.0));
  submap.InsertRangeData({0.0, 0.0}, first.returns, first.misses, inserter);
  const std::shared_ptr<const grid::ProbabilityGrid> held = submap.grid();
  const std::vector<uint16_t> values_before = held->values();
  const auto start = std::chrono::steady_clock::now();
  submap.InsertRangeData({-2.0, 1.0}, second.returns, second.misses, inserter);
  const double with_copy_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(held->values(), values_before);  // the held snapshot did not change
  EXPECT_NE(submap.grid()->values(), values_before);
  EXPECT_EQ(submap.num_grid_copies(), 1);
  // Nobody holds a snapshot now: insertion writes in place.
  const auto start2 = std::chrono::steady_clock::now();
  submap.InsertRangeData({0.0, 0.0}, first.returns, first.misses, inserter);
  const double in_place_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start2).count();
  EXPECT_EQ(submap.num_grid_copies(), 1);
  std::cout << "Insertion into " << submap.grid()->limits().num_cells()
            << "-cell grid: " << with_copy_ms << " ms with a held snapshot, " << in_place_ms
            << " ms in place\n";
}

TEST(SubmapTest, RejectsInvalidOptions) {
  SubmapOptions options;
  options.num_range_data = 0;
  EXPECT_THROW(ActiveSubmaps{options}, std::invalid_argument);
  options = {};
  options.insertion.hit_probability = 0.4;
  EXPECT_THROW(ActiveSubmaps{options}, std::invalid_argument);
  options = {};
  options.resolution_m = 0.0;
  EXPECT_THROW(ActiveSubmaps{options}, std::invalid_argument);
  options = {};
  options.max_travel_m = -1.0;
  EXPECT_THROW(ActiveSubmaps{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
