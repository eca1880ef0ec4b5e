#ifndef SCOUT_IO_MAP_PICTURE_H_
#define SCOUT_IO_MAP_PICTURE_H_

#include <cstdint>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"
#include "scout/grid/probability_grid.h"
#include "scout/io/trajectory.h"

namespace scout::io {

// Submap grids with their global poses (grid frame -> map frame).
using GlobalSubmaps =
    std::vector<std::pair<geometry::Rigid2d, std::shared_ptr<const grid::ProbabilityGrid>>>;

// Writes a PNG picture of the submaps fused by grid::FuseSubmaps: free white,
// occupied black, unknown grey; over it 'trajectory' as a polyline whose
// colour runs from blue (start) to red (end), a green disc at the first pose
// and an orange one at the last. The picture covers the submaps and the
// trajectory, at the finest submap resolution (0.05 m without submaps)
// coarsened so that neither side exceeds 'max_side_px'; its top row is the
// map's max-y row. Written through a temporary file and rename. Throws
// std::invalid_argument unless max_side_px >= 2, InputError when the
// directory is not writable.
void WriteMapPicture(const GlobalSubmaps& submaps, const std::vector<StampedPose>& trajectory,
                     const std::filesystem::path& path, int max_side_px = 3000);

// What an exploration run draws over its map picture, like the paper's first
// figure; everything in the picture's frame.
struct MapOverlay {
  // Submaps whose known free cells are tinted red: where frontier detection
  // ran in the last optimisation round.
  GlobalSubmaps highlighted_submaps;
  // Global frontier points: blue.
  std::vector<Eigen::Vector2d> frontier;
  // Navigation points the robot was sent to: small dark-green dots.
  std::vector<Eigen::Vector2d> navigation_points;
  // The latest selection's navigation points: larger magenta discs.
  std::vector<Eigen::Vector2d> candidates;
  // The exploration boundary polygon (closed; empty: none): an orange line.
  std::vector<Eigen::Vector2d> boundary;
  // Blacklisted goals (failed, not to be chosen again unless the map around
  // them changes): dark red crosses outlined in white, over the trajectory.
  std::vector<Eigen::Vector2d> blacklisted_goals;
};

// WriteMapPicture with 'overlay' drawn under the trajectory (the candidates
// and blacklisted goals over it).
void WriteMapPicture(const GlobalSubmaps& submaps, const std::vector<StampedPose>& trajectory,
                     const MapOverlay& overlay, const std::filesystem::path& path,
                     int max_side_px = 3000);

// Writes a PNG picture of what an exploration run's coverage counted, over
// the true world: per cell of 'world', 'coverage_mask' holds 0 (not
// reachable), 1 (reachable, not mapped free) or 2 (reachable and mapped free;
// exploration::GroundTruth::CoverageMask). Mapped cells are white, unmapped
// ones magenta, walls black, free space the robot cannot reach light grey and
// unknown space grey; over it the 'truth' trajectory as in WriteMapPicture.
// Blocks of cells are drawn as one pixel when a side exceeds 'max_side_px'
// (an unmapped cell wins its block, so small misses stay visible). Throws
// std::invalid_argument when the mask does not match the world or
// max_side_px < 2, InputError when the directory is not writable.
void WriteCoveragePicture(const grid::OccupancyMap& world,
                          const std::vector<uint8_t>& coverage_mask,
                          const std::vector<StampedPose>& truth, const std::filesystem::path& path,
                          int max_side_px = 3000);

// At most this many cells in the map WriteMapServerMap writes: an 820 m
// square at 5 cm. Only submaps a diverged SLAM has thrown far apart need more.
inline constexpr int64_t kMaxGlobalMapCells = int64_t{1} << 28;

// Returns the resolution of the map WriteMapServerMap writes: the finest
// submap resolution (0.05 m without submaps), doubled as often as needed to
// keep the map within kMaxGlobalMapCells.
double GlobalMapResolution(const GlobalSubmaps& submaps);

// Returns the submaps fused by grid::FuseSubmaps at GlobalMapResolution: the
// map WriteMapServerMap writes; no cells when nothing is mapped.
grid::OccupancyMap FuseGlobalSubmaps(const GlobalSubmaps& submaps);

// Writes the fused submaps at the finest submap resolution as a ROS
// map_server map ('yaml_path' plus a PGM beside it, see grid/map_io.h); with
// nothing mapped yet, one unknown cell at the origin. Throws InputError when
// the directory is not writable.
void WriteMapServerMap(const GlobalSubmaps& submaps, const std::filesystem::path& yaml_path);

}  // namespace scout::io

#endif  // SCOUT_IO_MAP_PICTURE_H_
