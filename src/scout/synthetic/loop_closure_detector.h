#ifndef SCOUT_SYNTHETIC_LOOP_CLOSURE_DETECTOR_H_
#define SCOUT_SYNTHETIC_LOOP_CLOSURE_DETECTOR_H_

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace scout::synthetic {

// Finds submaps the robot has come back to: a spatial hash of the true
// positions of the scans inserted into each submap, thinned out per submap.
class LoopClosureDetector {
 public:
  // Positions within 'radius_m' count as near; a submap keeps a position only
  // if it is at least 'sample_spacing_m' from the previous one it kept.
  LoopClosureDetector(double radius_m, double sample_spacing_m);

  // Records that a scan at 'position' was inserted into submap 'submap_id'.
  void Add(int submap_id, const Eigen::Vector2d& position);

  // Returns the smallest submap id <= 'max_id' with a kept position within
  // the radius of 'position', or -1.
  int OldestNear(const Eigen::Vector2d& position, int max_id) const;

 private:
  struct Entry {
    Eigen::Vector2d position;
    int submap_id;
  };
  int64_t KeyOf(int64_t cell_x, int64_t cell_y) const;

  double radius_m_;
  double sample_spacing_m_;
  std::unordered_map<int64_t, std::vector<Entry>> buckets_;  // cells of size radius_m
  std::vector<Eigen::Vector2d> last_kept_;                   // per submap id
  std::vector<bool> has_kept_;
};

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_LOOP_CLOSURE_DETECTOR_H_
