#include "scout/io/revisit_consistency.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "scout/geometry/rigid_transform.h"
#include "scout/io/scan_pairing.h"

namespace scout::io {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("revisit consistency: " + what);
}

}  // namespace

std::vector<std::vector<int>> FindRevisits(const std::vector<geometry::Rigid2d>& poses,
                                           const std::vector<double>& times_s,
                                           const RevisitOptions& options) {
  Require(poses.size() == times_s.size(),
          std::to_string(poses.size()) + " poses but " + std::to_string(times_s.size()) + " times");
  Require(options.min_separation_s >= 0.0, "min_separation_s must be >= 0");
  Require(options.max_distance_m > 0.0, "max_distance_m must be > 0");
  Require(options.max_turn_deg >= 0.0, "max_turn_deg must be >= 0");
  Require(options.max_earlier_scans >= 1, "max_earlier_scans must be >= 1");
  // Poses hashed into cells of max_distance_m: the candidates of a pose lie
  // in its cell's 3 x 3 block, so the search stays linear in the scans (a
  // museum replay has tens of thousands).
  const double cell_m = options.max_distance_m;
  const auto key = [&](int64_t cx, int64_t cy) { return (cx << 32) ^ (cy & 0xffffffff); };
  const auto cell_of = [&](const Eigen::Vector2d& p) {
    return std::pair<int64_t, int64_t>(static_cast<int64_t>(std::floor(p.x() / cell_m)),
                                       static_cast<int64_t>(std::floor(p.y() / cell_m)));
  };
  std::unordered_map<int64_t, std::vector<int>> cells;
  for (size_t i = 0; i < poses.size(); ++i) {
    const auto [cx, cy] = cell_of(poses[i].translation());
    cells[key(cx, cy)].push_back(static_cast<int>(i));
  }
  const double max_turn_rad = options.max_turn_deg * std::numbers::pi / 180.0;
  const double max_distance_sq = options.max_distance_m * options.max_distance_m;
  std::vector<std::vector<int>> revisits(poses.size());
  std::vector<std::pair<double, int>> found;
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Vector2d& p = poses[i].translation();
    const auto [cx, cy] = cell_of(p);
    found.clear();
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (const int j : it->second) {
          if (times_s[j] > times_s[i] - options.min_separation_s) continue;
          const double d_sq = (poses[j].translation() - p).squaredNorm();
          if (d_sq > max_distance_sq) continue;
          if (std::abs(geometry::NormalizeAngle(poses[j].theta() - poses[i].theta())) >
              max_turn_rad) {
            continue;
          }
          found.emplace_back(d_sq, j);
        }
      }
    }
    std::sort(found.begin(), found.end());
    const size_t keep = std::min(found.size(), static_cast<size_t>(options.max_earlier_scans));
    for (size_t k = 0; k < keep; ++k) revisits[i].push_back(found[k].second);
  }
  return revisits;
}

std::vector<std::vector<int>> MergeRevisits(const std::vector<std::vector<int>>& a,
                                            const std::vector<std::vector<int>>& b) {
  Require(a.size() == b.size(), "revisit lists of " + std::to_string(a.size()) + " and " +
                                    std::to_string(b.size()) + " scans");
  std::vector<std::vector<int>> merged(a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    merged[i] = a[i];
    merged[i].insert(merged[i].end(), b[i].begin(), b[i].end());
    std::sort(merged[i].begin(), merged[i].end());
    merged[i].erase(std::unique(merged[i].begin(), merged[i].end()), merged[i].end());
  }
  return merged;
}

RevisitConsistency MeasureRevisitConsistency(
    const std::vector<std::vector<Eigen::Vector2d>>& points,
    const std::vector<geometry::Rigid2d>& poses, const std::vector<std::vector<int>>& revisits,
    double max_distance_m) {
  Require(points.size() == poses.size() && points.size() == revisits.size(),
          std::to_string(points.size()) + " scans, " + std::to_string(poses.size()) +
              " poses and " + std::to_string(revisits.size()) + " revisit lists");
  Require(max_distance_m > 0.0, "max_distance_m must be > 0");
  // Each scan's returns in the world frame, placed once: a scan is the
  // earlier visit of up to max_earlier_scans later ones.
  const std::vector<std::vector<Eigen::Vector2d>> world = PlaceScans(points, poses);
  RevisitConsistency result;
  double sum_of_means = 0.0;
  int64_t returns = 0, paired = 0, scans_with_pairs = 0;
  std::vector<size_t> earlier;
  for (size_t i = 0; i < revisits.size(); ++i) {
    if (revisits[i].empty()) continue;
    earlier.clear();
    for (const int j : revisits[i]) {
      Require(j >= 0 && static_cast<size_t>(j) < points.size(),
              "scan " + std::to_string(i) + " revisits scan " + std::to_string(j) +
                  ", which does not exist");
      earlier.push_back(static_cast<size_t>(j));
    }
    ++result.scans;
    returns += static_cast<int64_t>(points[i].size());
    const ScanPairing pairing = PairWithNearest(world, earlier, i, max_distance_m);
    paired += pairing.pairs;
    if (pairing.pairs == 0) continue;
    sum_of_means += pairing.sum_m / pairing.pairs;
    ++scans_with_pairs;
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  result.mean_distance_m = scans_with_pairs > 0 ? sum_of_means / scans_with_pairs : kNaN;
  result.paired_fraction = returns > 0 ? static_cast<double>(paired) / returns : kNaN;
  return result;
}

}  // namespace scout::io
