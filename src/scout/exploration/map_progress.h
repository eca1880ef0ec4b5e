#ifndef SCOUT_EXPLORATION_MAP_PROGRESS_H_
#define SCOUT_EXPLORATION_MAP_PROGRESS_H_

namespace scout::exploration {

// Whether exploration still maps new space, judged from the robot's own map
// (the truth is for scoring only). What counts is the free area the fused map
// gains between two measurements with no pose-graph optimisation between
// them: an optimisation moves submaps and can shrink or grow the fused free
// area by tens of square metres at once (museum seed 2: 96 m^2 below its
// peak), which is neither new space nor its loss. Compared with the fused
// area's peak, this sees a robot still mapping after such a drop (museum seed
// 1 ended no_progress at 98.7 % coverage while mapping 108 m^2 in its last
// 300 s), and a stalled robot whose map changes only by optimisations still
// gains nothing.
class MapProgress {
 public:
  // Progress is a gain of at least 'min_gain_m2' over the best so far.
  explicit MapProgress(double min_gain_m2) : min_gain_m2_(min_gain_m2) {}

  // Records the fused map's free area 'map_free_m2' at simulated time 't_s',
  // after 'num_optimizations' optimisations so far.
  void Measure(double t_s, double map_free_m2, int num_optimizations);

  // The simulated time of the last progress (0 before any).
  double last_progress_s() const { return last_progress_s_; }
  // Free area mapped by scans so far: the sum of the changes between
  // measurements without an optimisation between them.
  double mapped_by_scans_m2() const { return mapped_by_scans_m2_; }

 private:
  double min_gain_m2_;
  bool measured_ = false;
  double previous_free_m2_ = 0.0;
  int previous_optimizations_ = 0;
  double mapped_by_scans_m2_ = 0.0;
  double best_m2_ = 0.0;
  double last_progress_s_ = 0.0;
};

}  // namespace scout::exploration

#endif  // SCOUT_EXPLORATION_MAP_PROGRESS_H_
