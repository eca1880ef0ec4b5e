#include "scout/io/scan_pairing.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>

namespace scout::io {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::point<double, 2, bg::cs::cartesian>;

}  // namespace

std::vector<std::vector<Eigen::Vector2d>> PlaceScans(
    const std::vector<std::vector<Eigen::Vector2d>>& points,
    const std::vector<geometry::Rigid2d>& poses) {
  std::vector<std::vector<Eigen::Vector2d>> placed(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    placed[i].reserve(points[i].size());
    for (const Eigen::Vector2d& p : points[i]) placed[i].push_back(poses[i] * p);
  }
  return placed;
}

ScanPairing PairWithNearest(const std::vector<std::vector<Eigen::Vector2d>>& placed,
                            const std::vector<size_t>& others, size_t scan, double max_distance_m) {
  std::vector<BgPoint> earlier;
  for (const size_t k : others) {
    for (const Eigen::Vector2d& p : placed[k]) earlier.emplace_back(p.x(), p.y());
  }
  ScanPairing result;
  if (earlier.empty()) return result;
  const bgi::rtree<BgPoint, bgi::rstar<16>> tree(earlier);  // packed: built in one go
  const double max_distance_sq = max_distance_m * max_distance_m;
  for (const Eigen::Vector2d& p : placed[scan]) {
    const BgPoint q(p.x(), p.y());
    for (auto it = tree.qbegin(bgi::nearest(q, 1)); it != tree.qend(); ++it) {
      const double d_sq = bg::comparable_distance(q, *it);
      if (d_sq <= max_distance_sq) {
        result.sum_m += std::sqrt(d_sq);
        ++result.pairs;
      }
    }
  }
  return result;
}

}  // namespace scout::io
