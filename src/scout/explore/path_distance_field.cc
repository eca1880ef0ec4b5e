#include "scout/explore/path_distance_field.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace scout::explore {
namespace {

uint64_t NextId() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

}  // namespace

PathDistanceField::PathDistanceField(const PlanningMap& map, const Eigen::Vector2d& robot)
    : PathDistanceField(map, StartRegion(map, robot)) {}

PathDistanceField::PathDistanceField(const PlanningMap& map, const StartRegion& start,
                                     double settle_m)
    : id_(NextId()),
      limits_(map.limits()),
      res_(static_cast<float>(limits_.resolution())),
      distance_cells_(static_cast<size_t>(padded_width()) * (limits_.height() + 2), kUnreachable) {
  float nearest = kUnreachable;
  for (const StartSeed& seed : start.seeds()) {
    if (seed.distance_m < nearest) nearest = seed.distance_m, start_ = seed.cell;
  }
  if (start.empty()) return;

  // Dijkstra in cell units over the traversability codes padded by one
  // closed cell; kSettled marks cells whose distance is final. Distances stay
  // in cell units (at() scales them): a final pass over every cell of a
  // museum-sized map cost as much as a tenth of the search.
  const int w = limits_.width(), h = limits_.height();
  const int64_t pw = padded_width();
  code_.assign(distance_cells_.size(), 0);
  const std::vector<uint8_t>& codes = map.traversability_codes();
  for (int y = 0; y < h; ++y) {
    std::memcpy(&code_[(y + 1) * pw + 1], &codes[int64_t{y} * w], w);
  }
  // Entering a cell costs the step length times its factor (by code); the
  // products are formed once, as the search adds them.
  static_assert(PlanningMap::kNarrow == 2);
  const float narrow = static_cast<float>(map.options().narrow_cost_factor);
  const float diagonal = static_cast<float>(M_SQRT2);
  straight_cost_[2] = narrow;
  diagonal_cost_[1] = diagonal;
  diagonal_cost_[2] = diagonal * narrow;
  // Dial's bucket queue with buckets one cell wide: every step costs at least
  // one cell, so a cell popped from bucket k can only improve cells in later
  // buckets, and bucket k is final when its turn comes: exact, and O(cells).
  // A cell's distance is the least of its settled neighbours' distance plus
  // the step, whatever order they were settled in (so a search run in parts
  // ends with the same distances). The ring spans the dearest step (a narrow
  // diagonal) and the seeds' own distances (an escape path).
  float farthest_seed = 0.0f;
  for (const StartSeed& seed : start.seeds()) {
    farthest_seed = std::max(farthest_seed, seed.distance_m / res_);
  }
  const int64_t ring =
      static_cast<int64_t>(std::ceil(farthest_seed + float(M_SQRT2) * map.MaxStepFactor())) + 2;
  bucket_.resize(ring);
  float* const d = distance_cells_.data();
  for (const StartSeed& seed : start.seeds()) {
    const uint32_t s = static_cast<uint32_t>(Padded(seed.cell));
    const float ds = seed.distance_m / res_;
    if (ds < d[s]) {
      d[s] = ds;
      bucket_[static_cast<int64_t>(ds) % ring].push_back(s);
      ++pending_;
    }
  }
  settled_cells_ = 0.0f;
  SettleUpTo(settle_m);
}

void PathDistanceField::SettleUpTo(double settle_m) {
  if (complete()) return;
  // The buckets through the one holding settle_m: every cell within it, and
  // perhaps some beyond, are then settled.
  const double last = std::floor(settle_m / res_);
  Run(last >= double(std::numeric_limits<int64_t>::max() / 2)
          ? std::numeric_limits<int64_t>::max()
          : static_cast<int64_t>(std::max(last, -1.0)));
}

void PathDistanceField::Run(int64_t last_bucket) {
  const int64_t pw = padded_width();
  const int64_t ring = static_cast<int64_t>(bucket_.size());
  constexpr uint8_t kSettled = 0x80;
  uint8_t* const code = code_.data();
  float* const d = distance_cells_.data();
  std::vector<std::vector<uint32_t>>& bucket = bucket_;
  const float* const straight_cost = straight_cost_;
  const float* const diagonal_cost = diagonal_cost_;
  int64_t pending = pending_;
  int64_t k = next_bucket_;
  // slot == k % ring, kept without a division: a pushed distance lies in
  // [k + 1, k + ring), so its slot is slot + offset, wrapped once.
  for (int64_t slot = k % ring; pending > 0 && k <= last_bucket;
       ++k, slot = slot + 1 == ring ? 0 : slot + 1) {
    std::vector<uint32_t>& current = bucket[slot];
    // Written out for the eight neighbours: the loops and the relaxation as
    // a call cost a third of the search.
    const auto relax = [&](int64_t v, float dv) __attribute__((always_inline)) {
      if (dv < d[v]) {
        d[v] = dv;
        int64_t to = slot + (static_cast<int64_t>(dv) - k);
        if (to >= ring) to -= ring;
        bucket[to].push_back(static_cast<uint32_t>(v));
        ++pending;
      }
    };
    const auto straight = [&](int64_t v, float du) __attribute__((always_inline)) {
      const uint8_t cv = code[v];
      if (cv != 0 && !(cv & kSettled)) relax(v, du + straight_cost[cv]);
      return (cv & 3) != 0;  // traversable, settled or not
    };
    const auto diagonal = [&](int64_t v, float du) __attribute__((always_inline)) {
      const uint8_t cv = code[v];
      if (cv != 0 && !(cv & kSettled)) relax(v, du + diagonal_cost[cv]);
    };
    for (size_t i = 0; i < current.size(); ++i) {
      const int64_t u = current[i];
      --pending;
      if (code[u] & kSettled) continue;
      code[u] |= kSettled;
      const float du = d[u];
      const bool east = straight(u + 1, du);
      const bool west = straight(u - 1, du);
      const bool north = straight(u + pw, du);
      const bool south = straight(u - pw, du);
      // A diagonal step passes between two orthogonal cells: both open.
      if (east && north) diagonal(u + pw + 1, du);
      if (east && south) diagonal(u - pw + 1, du);
      if (west && north) diagonal(u + pw - 1, du);
      if (west && south) diagonal(u - pw - 1, du);
    }
    current.clear();
  }
  pending_ = pending;
  next_bucket_ = k;
  if (pending == 0) {
    // Ended: every reachable cell is settled; the state is no longer needed.
    settled_cells_ = kUnreachable;
    code_ = {};
    bucket_ = {};
  } else {
    settled_cells_ = static_cast<float>(k);
  }
}

std::optional<PathDistanceField::Reached> PathDistanceField::NearestReached(
    const Eigen::Vector2d& p, double radius_m) const {
  // ForEachCellWithin rather than CellsWithin: this runs for every frontier
  // point.
  std::optional<Reached> best;
  ForEachCellWithin(limits_, p, radius_m, [&](const grid::CellIndex& c) {
    const float dist = Settled(distance_cells_[Padded(c)]);
    if (std::isfinite(dist) && (!best || dist < best->distance_m)) best = Reached{dist, c};
  });
  return best;
}

}  // namespace scout::explore
