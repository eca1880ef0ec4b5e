#include "scout/explore/mean_shift.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scout/explore/option_check.h"

namespace scout::explore {

void Validate(const MeanShiftOptions& o) {
  CheckAtLeast("mean_shift", "bandwidth_m", o.bandwidth_m, 0.0, /*strict=*/true);
  CheckAtLeast("mean_shift", "seed_bin_m", o.seed_bin_m, 0.0);
  CheckAtLeast("mean_shift", "convergence_m", o.convergence_m, 0.0, /*strict=*/true);
  CheckAtLeast("mean_shift", "max_iterations", o.max_iterations, 1.0);
}

namespace {

int64_t Key(int64_t ix, int64_t iy) { return (ix << 32) ^ (iy & 0xffffffff); }

// Points bucketed in square cells of side 'cell_m' for radius queries with
// radius <= cell_m (only the 3x3 block around a position can hold neighbours).
// Each bucket's points are stored together, in index order, so a query
// reads them in sequence (mean-shift's queries were a tenth of a museum run's
// goal selection); visit(i, point) sees them in the order of the buckets
// below, and within a bucket by index.
class HashGrid {
 public:
  HashGrid(const std::vector<Eigen::Vector2d>& points, double cell_m) : cell_m_(cell_m) {
    std::vector<std::pair<int64_t, int>> keyed;
    keyed.reserve(points.size());
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
      keyed.push_back({KeyOf(points[i]), i});
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t k = 0; k < keyed.size(); ++k) {
      if (k == 0 || keyed[k].first != keyed[k - 1].first) {
        buckets_[keyed[k].first] = {static_cast<int>(k), static_cast<int>(k)};
      }
      ++buckets_[keyed[k].first].second;
      index_.push_back(keyed[k].second);
      points_.push_back(points[keyed[k].second]);
    }
  }
  template <typename Visit>
  void ForEachWithin(const Eigen::Vector2d& p, double radius_m, Visit&& visit) const {
    const int64_t cx = Floor(p.x()), cy = Floor(p.y());
    const double r2 = radius_m * radius_m;
    for (int64_t y = cy - 1; y <= cy + 1; ++y) {
      for (int64_t x = cx - 1; x <= cx + 1; ++x) {
        const auto it = buckets_.find(Key(x, y));
        if (it == buckets_.end()) continue;
        for (int k = it->second.first; k < it->second.second; ++k) {
          if ((points_[k] - p).squaredNorm() <= r2) visit(index_[k], points_[k]);
        }
      }
    }
  }

 private:
  int64_t Floor(double v) const { return static_cast<int64_t>(std::floor(v / cell_m_)); }
  int64_t KeyOf(const Eigen::Vector2d& p) const { return Key(Floor(p.x()), Floor(p.y())); }

  double cell_m_;
  std::unordered_map<int64_t, std::pair<int, int>> buckets_;  // key -> [begin, end) below
  std::vector<int> index_;                                    // by bucket, then index
  std::vector<Eigen::Vector2d> points_;                       // points_[k] = input[index_[k]]
};

// A position bit for bit, for remembering where a seed's shifts went.
struct PositionKey {
  uint64_t x, y;
  bool operator==(const PositionKey&) const = default;
};
struct PositionKeyHash {
  size_t operator()(const PositionKey& k) const {
    return std::hash<uint64_t>()(k.x * 0x9e3779b97f4a7c15ULL ^ k.y);
  }
};
PositionKey KeyOf(const Eigen::Vector2d& p) {
  return {std::bit_cast<uint64_t>(p.x()), std::bit_cast<uint64_t>(p.y())};
}

std::vector<Eigen::Vector2d> Seeds(const std::vector<Eigen::Vector2d>& points, double bin_m) {
  if (bin_m <= 0.0) return points;
  struct Bin {
    int64_t ix, iy;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
  };
  std::unordered_map<int64_t, Bin> bins;
  for (const Eigen::Vector2d& p : points) {
    const int64_t ix = static_cast<int64_t>(std::floor(p.x() / bin_m));
    const int64_t iy = static_cast<int64_t>(std::floor(p.y() / bin_m));
    Bin& b = bins.try_emplace(Key(ix, iy), Bin{ix, iy}).first->second;
    b.sum += p, ++b.n;
  }
  std::vector<const Bin*> ordered;
  for (const auto& [key, bin] : bins) ordered.push_back(&bin);
  // Hash order is not portable; sort for deterministic output.
  std::sort(ordered.begin(), ordered.end(), [](const Bin* a, const Bin* b) {
    return a->iy != b->iy ? a->iy < b->iy : a->ix < b->ix;
  });
  std::vector<Eigen::Vector2d> seeds;
  for (const Bin* b : ordered) seeds.push_back(b->sum / b->n);
  return seeds;
}

}  // namespace

MeanShiftClusters MeanShift(const std::vector<Eigen::Vector2d>& points,
                            const MeanShiftOptions& options) {
  Validate(options);
  MeanShiftClusters out;
  if (points.empty()) return out;
  const double h = options.bandwidth_m;
  const HashGrid grid(points, h);

  // Shift every seed to its mode; remember how many points support the mode.
  // Seeds of one basin soon step onto the same positions, bit for bit (the
  // same points in the kernel give the same mean), and from there on their
  // shifts are the same: on the half-explored museum frontier of
  // scout_explore_bench (21,700 points) two thirds of the shifts repeated one
  // that another seed had made (fewer on a run's frontier: docs/EXPERIMENTS.md).
  // A position from which a seed went on shifting is remembered with where
  // that ended and after how many more shifts, and a later seed stepping onto
  // it takes that end when its own shift budget would have lasted as long; so
  // the modes and supports are exactly those of shifting every seed to the end.
  struct Mode {
    Eigen::Vector2d position;
    int support;
  };
  struct Continuation {
    Mode end;
    int iterations;  // shifts after the position, the one that ended it included
  };
  std::unordered_map<PositionKey, Continuation, PositionKeyHash> continuations;
  std::vector<std::pair<PositionKey, int>> path;  // positions left, at which iteration
  std::vector<Mode> modes;
  for (Eigen::Vector2d x : Seeds(points, options.seed_bin_m)) {
    int support = 0;
    path.clear();
    bool ended = false;  // by convergence or an empty kernel, not by the budget
    int last = options.max_iterations - 1;
    std::optional<Continuation> taken;
    for (int it = 0; it < options.max_iterations; ++it) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      int n = 0;
      grid.ForEachWithin(x, h, [&](int, const Eigen::Vector2d& q) { sum += q, ++n; });
      if (n == 0) {
        ended = true, last = it;
        break;
      }
      const Eigen::Vector2d next = sum / n;
      const double shift = (next - x).norm();
      x = next, support = n;
      if (shift < options.convergence_m) {
        ended = true, last = it;
        break;
      }
      const PositionKey key = KeyOf(x);
      const auto known = continuations.find(key);
      if (known != continuations.end() && it + known->second.iterations < options.max_iterations) {
        taken = known->second;
        ended = true, last = it + known->second.iterations;
        break;
      }
      path.push_back({key, it});
    }
    const Mode end = taken ? taken->end : Mode{x, support};
    if (ended) {
      for (const auto& [key, it] : path)
        continuations.try_emplace(key, Continuation{end, last - it});
    }
    modes.push_back(end);
  }

  // Denser modes absorb the modes within one bandwidth (stable: ties keep seed order).
  std::stable_sort(modes.begin(), modes.end(),
                   [](const Mode& a, const Mode& b) { return a.support > b.support; });
  for (const Mode& m : modes) {
    bool near_kept = false;
    for (const Eigen::Vector2d& c : out.centres) {
      if ((c - m.position).squaredNorm() < h * h) {
        near_kept = true;
        break;
      }
    }
    if (!near_kept) out.centres.push_back(m.position);
  }

  // Nearest centre per point: centres are >= h apart, so one found within h in
  // the 3x3 block is the nearest; otherwise scan all centres.
  const HashGrid centre_grid(out.centres, h);
  out.label.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    const auto consider = [&](int c) {
      const double d2 = (out.centres[c] - points[i]).squaredNorm();
      if (d2 < best_d2 || (d2 == best_d2 && c < best)) best_d2 = d2, best = c;
    };
    centre_grid.ForEachWithin(points[i], h, [&](int c, const Eigen::Vector2d&) { consider(c); });
    if (best < 0) {
      for (int c = 0; c < static_cast<int>(out.centres.size()); ++c) consider(c);
    }
    out.label[i] = best;
  }
  return out;
}

}  // namespace scout::explore
