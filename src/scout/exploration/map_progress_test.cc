#include "scout/exploration/map_progress.h"

#include <gtest/gtest.h>

namespace scout::exploration {
namespace {

TEST(MapProgressTest, ScansThatMapNewSpaceAreProgress) {
  MapProgress progress(1.0);
  progress.Measure(2.0, 10.0, 0);
  EXPECT_EQ(progress.last_progress_s(), 2.0);
  progress.Measure(4.0, 10.5, 0);  // less than the minimum gain
  EXPECT_EQ(progress.last_progress_s(), 2.0);
  progress.Measure(6.0, 11.2, 0);
  EXPECT_EQ(progress.last_progress_s(), 6.0);
  EXPECT_DOUBLE_EQ(progress.mapped_by_scans_m2(), 11.2);
}

TEST(MapProgressTest, AnOptimisationThatShrinksTheMapDoesNotHideNewSpace) {
  MapProgress progress(1.0);
  progress.Measure(2.0, 100.0, 0);
  // A loop closure moves submaps onto each other: 30 m^2 less free area.
  progress.Measure(4.0, 70.0, 1);
  EXPECT_DOUBLE_EQ(progress.mapped_by_scans_m2(), 100.0);
  // The robot maps 5 m^2 more: below the old peak of the fused map, but new.
  progress.Measure(6.0, 75.0, 1);
  EXPECT_EQ(progress.last_progress_s(), 6.0);
  EXPECT_DOUBLE_EQ(progress.mapped_by_scans_m2(), 105.0);
}

TEST(MapProgressTest, OptimisationsAloneAreNoProgress) {
  MapProgress progress(1.0);
  progress.Measure(2.0, 100.0, 0);
  // A stalled robot: each optimisation moves the map back and forth.
  double t = 2.0;
  for (int i = 1; i <= 10; ++i) {
    t += 2.0;
    progress.Measure(t, i % 2 == 1 ? 140.0 : 90.0, i);
  }
  EXPECT_EQ(progress.last_progress_s(), 2.0);
  // Scans that only re-map what an optimisation took away count as what they
  // add, so a small gain after a drop is no progress either.
  progress.Measure(t + 2.0, 90.5, 10);
  EXPECT_EQ(progress.last_progress_s(), 2.0);
}

}  // namespace
}  // namespace scout::exploration
