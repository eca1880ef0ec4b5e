#include "scout/frontier/exact_strategy.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "scout/frontier/stopwatch.h"

namespace scout::frontier {
namespace {

// Absorbs the float rounding of stored positions and margins (values of a few
// metres keep ~1e-6 m in float); real margins are multiples of millimetres.
constexpr double kSafety_m = 1e-5;

Eigen::Vector2d RefOf(const auto& e) { return {e.ref_x_m, e.ref_y_m}; }

bool SameBox(const geometry::Box2d& a, const geometry::Box2d& b) {
  return a.min == b.min && a.max == b.max;
}

}  // namespace

geometry::Rigid2d ExactStrategy::Relative(int i, int j) const {
  return catalog_.submap(j).global_pose_inverse * catalog_.submap(i).global_pose;
}

void ExactStrategy::Observe(int i, uint32_t k, int j, bool objects) {
  int32_t& witness = witness_[i][k];
  if (objects) {
    if (witness == kNoWitness || witness == kLost) {
      witness = j;
      is_frontier_[i][k] = 0;
    }
  } else if (witness == j) {
    witness = kLost;
    lost_.push_back(k);
  }
}

void ExactStrategy::ResolveLost(int i) {
  if (lost_.empty()) return;
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  const double slack = catalog_.options().exact_slack_m;
  std::vector<uint32_t> lost;
  lost.swap(lost_);
  for (const uint32_t k : lost) {
    // Another watch may have objected since the point was queued.
    if (witness_[i][k] != kLost) continue;
    const Eigen::Vector2d& p = points[k];
    const Eigen::Vector2d global = catalog_.GlobalPosition(i, p);
    for (Watch& w : watches_[i]) {
      const SubmapRecord& submap_j = catalog_.submap(w.j);
      // Outside j's box j cannot object: no look-up.
      if (!submap_j.global_box.Contains(global)) continue;
      Mark(i, k);
      if (submap_j.answers.Objects(catalog_.GlobalInSubmap(global, w.j))) {
        AddEntry(i, k, &w, slack);  // stores it, sets the witness
        break;
      }
    }
    if (witness_[i][k] != kLost) continue;
    // Nobody objects: a frontier, which every watch must store or cover.
    witness_[i][k] = kNoWitness;
    is_frontier_[i][k] = 1;
    for (Watch& w : watches_[i]) AddEntry(i, k, &w, slack);
  }
}

const ExactStrategy::PointsDisc& ExactStrategy::DiscOf(int i) {
  PointsDisc& disc = discs_[i];
  if (disc.valid) return disc;
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) sum += p;
  disc.center = points.empty() ? sum : Eigen::Vector2d(sum / static_cast<double>(points.size()));
  disc.radius_m = 0.0;
  for (const Eigen::Vector2d& p : points) {
    disc.radius_m = std::max(disc.radius_m, (p - disc.center).norm());
  }
  disc.valid = true;
  return disc;
}

void ExactStrategy::Mark(int i, uint32_t k) {
  if (point_stamp_[i][k] == stamp_) return;
  point_stamp_[i][k] = stamp_;
  ++pending_.queried_points;
  if (submap_stamp_[i] != stamp_) {
    submap_stamp_[i] = stamp_;
    ++pending_.queried_submaps;
    pending_.submap_ids.push_back(i);
  }
}

void ExactStrategy::BeginUpdate() {
  ++stamp_;
  pending_ = UpdateCost{};
}

UpdateCost ExactStrategy::EndUpdate(double time_us) {
  pending_.time_us = time_us;
  return pending_;
}

ExactStrategy::Watch* ExactStrategy::FindWatch(int i, int j) {
  for (Watch& w : watches_[i]) {
    if (w.j == j) return &w;
  }
  return nullptr;
}

void ExactStrategy::Anchor(int i, Watch* w) {
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  const double slack = catalog_.options().exact_slack_m;
  w->entries.clear();
  w->has_entry.assign(points.size(), false);
  const geometry::Rigid2d rel = Relative(i, w->j);
  w->coverage_anchor = w->key_anchor = rel;
  w->seen_version_i = catalog_.submap(i).pose_version;
  w->seen_version_j = catalog_.submap(w->j).pose_version;
  // The points' disc is fixed in i's frame; only its centre moves.
  const PointsDisc& disc = DiscOf(i);
  w->center = rel * disc.center;
  w->key_center = w->center;
  w->min_key_m = std::numeric_limits<float>::infinity();
  w->radius_m = disc.radius_m + kSafety_m;
  for (uint32_t k = 0; k < points.size(); ++k) {
    if (Tracks(i, k, w->j)) AddEntry(i, k, w, slack);
  }
}

void ExactStrategy::AddEntry(int i, uint32_t k, Watch* w, double slack_m) {
  const Eigen::Vector2d& p = catalog_.submap(i).frontier.points_m[k];
  const SubmapRecord& submap_j = catalog_.submap(w->j);
  const AnswerMap& answers = submap_j.answers;
  const Eigen::Vector2d global = catalog_.GlobalPosition(i, p);
  const Eigen::Vector2d q = catalog_.GlobalInSubmap(global, w->j);
  // Outside j's box j objects nowhere, and its margin there is at least the
  // distance to the box plus how far its objecting cells keep from the grid's
  // border. Most points of a pair whose boxes meet lie outside the other's
  // grid; when that margin alone covers one, it needs no look-up.
  if (!w->has_entry[k]) {
    const double outside_m = submap_j.global_box.DistanceTo(global);
    if (outside_m > 0.0 && outside_m + answers.objecting_to_border_m() - kSafety_m >=
                               slack_m + (q - w->coverage_anchor * p).norm()) {
      Observe(i, k, w->j, false);
      return;
    }
  }
  Mark(i, k);
  const bool objects = answers.Objects(q);
  Observe(i, k, w->j, objects);
  // An entry the watch holds already is kept up to date by its passes (it is
  // checked before it is relied on), so one per point is enough.
  if (w->has_entry[k]) return;
  const double margin = answers.Margin(q) - kSafety_m;
  // Not stored: it keeps its answer while no point moves by 'slack' from the
  // coverage anchor (checked per pair).
  if (!objects && margin >= slack_m + (q - w->coverage_anchor * p).norm()) return;
  Entry e;
  e.ref_x_m = static_cast<float>(q.x());
  e.ref_y_m = static_cast<float>(q.y());
  const double stored = std::min(margin, MarginCap());
  e.ref_margin_m = static_cast<float>(stored);
  e.key_m = static_cast<float>(stored - (RefOf(e) - w->key_anchor * p).norm());
  w->min_key_m = std::min(w->min_key_m, e.key_m);
  e.point = k;
  w->entries.push_back(e);
  w->has_entry[k] = true;
}

void ExactStrategy::Reevaluate(int i, Watch& w, const AnswerMap& answers, const Eigen::Vector2d& p,
                               const Eigen::Vector2d& q, Entry* e) {
  Mark(i, e->point);
  const bool objects = answers.Objects(q);
  Observe(i, e->point, w.j, objects);
  const double margin = std::min(answers.Margin(q) - kSafety_m, MarginCap());
  e->ref_x_m = static_cast<float>(q.x());
  e->ref_y_m = static_cast<float>(q.y());
  e->ref_margin_m = static_cast<float>(margin);
  e->key_m = static_cast<float>(margin - (RefOf(*e) - w.key_anchor * p).norm());
  w.min_key_m = std::min(w.min_key_m, e->key_m);
}

void ExactStrategy::Rekey(int i, Watch* w) {
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  const geometry::Rigid2d rel = Relative(i, w->j);
  w->key_center = rel * (w->coverage_anchor.inverse() * w->center);
  w->key_anchor = rel;
  w->min_key_m = std::numeric_limits<float>::infinity();
  for (Entry& e : w->entries) {
    e.key_m = static_cast<float>(e.ref_margin_m - (RefOf(e) - rel * points[e.point]).norm());
    w->min_key_m = std::min(w->min_key_m, e.key_m);
  }
}

template <typename Visit>
void ExactStrategy::PassOverTracked(int i, Watch* w, const Visit& visit) {
  size_t kept = 0;
  for (Entry& e : w->entries) {
    if (!Tracks(i, e.point, w->j)) {
      w->has_entry[e.point] = false;
      continue;
    }
    visit(e);
    w->entries[kept++] = e;
  }
  w->entries.resize(kept);
}

void ExactStrategy::Refresh(int i, Watch* w) {
  const uint64_t version_i = catalog_.submap(i).pose_version;
  const uint64_t version_j = catalog_.submap(w->j).pose_version;
  if (w->seen_version_i == version_i && w->seen_version_j == version_j) return;
  w->seen_version_i = version_i;
  w->seen_version_j = version_j;
  const geometry::Rigid2d rel = Relative(i, w->j);
  const double slack = catalog_.options().exact_slack_m;
  if (geometry::MaxDisplacementWithin(rel * w->coverage_anchor.inverse(), w->center, w->radius_m) >=
      slack) {
    Anchor(i, w);
    return;
  }
  const double bound =
      geometry::MaxDisplacementWithin(rel * w->key_anchor.inverse(), w->key_center, w->radius_m);
  if (bound <= w->min_key_m) return;
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  const AnswerMap& answers = catalog_.submap(w->j).answers;
  // A pass over the keys (no transforms) finds the entries the bound does not
  // clear; only those are checked exactly. The same pass drops the entries
  // the watch no longer needs.
  size_t checked = 0;
  float min_key_m = std::numeric_limits<float>::infinity();
  PassOverTracked(i, w, [&](Entry& e) {
    if (e.key_m < bound) {
      ++checked;
      const Eigen::Vector2d& p = points[e.point];
      const Eigen::Vector2d q = catalog_.PointInSubmap(i, p, w->j);
      if ((q - RefOf(e)).norm() >= e.ref_margin_m) Reevaluate(i, *w, answers, p, q, &e);
    }
    min_key_m = std::min(min_key_m, e.key_m);
  });
  w->min_key_m = min_key_m;
  // When most entries need a check each round, move the keys to the current pose.
  if (2 * checked > w->entries.size()) Rekey(i, w);
}

void ExactStrategy::ReviewNearChange(int i, Watch* w, const geometry::Box2d& region) {
  const double slack = catalog_.options().exact_slack_m;
  // Every recorded position lies within the coverage disc grown by the slack
  // (refs are positions looked up since anchoring), and no stored margin
  // exceeds the cap: a region farther than that touches nothing.
  if (region.DistanceTo(w->center) >= w->radius_m + slack + std::max(slack, MarginCap())) return;
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(i).frontier.points_m;
  const AnswerMap& answers = catalog_.submap(w->j).answers;
  PassOverTracked(i, w, [&](Entry& e) {
    // The recorded answer holds at q_ref itself and within its margin; a
    // margin of 0 (q_ref on a boundary) still needs q_ref outside the region.
    const double to_region = region.DistanceTo(RefOf(e));
    if (to_region > 0.0 && to_region >= e.ref_margin_m) return;
    const Eigen::Vector2d& p = points[e.point];
    Reevaluate(i, *w, answers, p, catalog_.PointInSubmap(i, p, w->j), &e);
  });
  // Unstored points were safe for 'slack' around their coverage position under
  // the old answers; near the change that no longer holds.
  // Points the watch does not track (witnessed elsewhere) need no answer here.
  for (uint32_t k = 0; k < points.size(); ++k) {
    if (w->has_entry[k] || !Tracks(i, k, w->j)) continue;
    if (region.DistanceTo(w->coverage_anchor * points[k]) >= slack + kSafety_m) continue;
    AddEntry(i, k, w, slack);
  }
}

void ExactStrategy::UpdateWatchesOf(int i) {
  std::vector<Watch>& watches = watches_[i];
  const geometry::Box2d points_box = catalog_.GlobalPointsBox(i);
  // A pair whose boxes no longer meet has no point of i inside j's grid.
  std::erase_if(watches, [&](Watch& w) {
    if (catalog_.submap(w.j).global_box.Intersects(points_box)) return false;
    // Nothing of i lies in j's grid: j objects nowhere.
    for (const Entry& e : w.entries) Observe(i, e.point, w.j, false);
    std::erase(watchers_[w.j], i);
    return true;
  });
  ResolveLost(i);
  for (Watch& w : watches) {
    Refresh(i, &w);
    ResolveLost(i);
  }
  if (catalog_.submap(i).frontier.points_m.empty()) return;
  // Marks the watched submaps so each candidate is checked in O(1).
  watched_.resize(catalog_.size(), 0);
  for (const Watch& w : watches) watched_[w.j] = 1;
  const size_t existing = watches.size();
  for (const int j : catalog_.index().Intersecting(points_box)) {
    if (j != i && !watched_[j]) {
      AddWatch(i, j);
      ResolveLost(i);
    }
  }
  for (size_t k = 0; k < existing; ++k) watched_[watches_[i][k].j] = 0;
}

void ExactStrategy::AddWatch(int i, int j) {
  watches_[i].push_back(Watch{});
  watches_[i].back().j = j;
  watchers_[j].push_back(i);
  Anchor(i, &watches_[i].back());
}

void ExactStrategy::EnsureSize(int n) {
  while (static_cast<int>(watches_.size()) < n) {
    watches_.emplace_back();
    watchers_.emplace_back();
    witness_.emplace_back();
    discs_.emplace_back();
    point_stamp_.emplace_back();
    seen_.emplace_back();
    submap_stamp_.push_back(0);
  }
}

int64_t ExactStrategy::num_entries() const {
  int64_t n = 0;
  for (const std::vector<Watch>& watches : watches_) {
    for (const Watch& w : watches) n += static_cast<int64_t>(w.entries.size());
  }
  return n;
}

UpdateCost ExactStrategy::OnOptimized(const std::vector<geometry::Rigid2d>&) {
  const Stopwatch stopwatch;
  BeginUpdate();
  const int n = catalog_.size();
  EnsureSize(n);
  // UpdateWatchesOf(i) has work only if i's placement changed (pose, grid box
  // or points box), if a submap it watches changed (its entries may need a
  // check, or the pair no longer meets), or if a changed submap's box now
  // meets i's points (a new watch). Every other submap's watches are up to
  // date, and the call would leave them as they are: only the affected ones
  // are updated, in the same (ascending) order, so the answers and the counts
  // equal updating all of them.
  affected_.assign(n, 0);
  for (int m = 0; m < n; ++m) {
    const SubmapRecord& r = catalog_.submap(m);
    SeenPlacement& seen = seen_[m];
    const geometry::Box2d points_box = catalog_.GlobalPointsBox(m);
    if (seen.valid && seen.pose_version == r.pose_version && SameBox(seen.box, r.global_box) &&
        SameBox(seen.points_box, points_box)) {
      continue;
    }
    seen = {r.pose_version, r.global_box, points_box, true};
    affected_[m] = 1;
    for (const int i : watchers_[m]) affected_[i] = 1;
    // Points lie inside their grid, so the grids' boxes find every candidate.
    for (const int i : catalog_.index().Intersecting(r.global_box)) affected_[i] = 1;
  }
  for (int i = 0; i < n; ++i) {
    if (affected_[i]) UpdateWatchesOf(i);
  }
  return EndUpdate(stopwatch.ElapsedUs());
}

void ExactStrategy::RemapOwnWatches(const SubmapChange& change) {
  const int j = change.id;
  const size_t n = change.previous_index.size();
  point_stamp_[j].assign(n, 0);
  std::vector<int> new_index_of_old;
  // Surviving points keep their witnesses (no other submap changed); new
  // points have none yet.
  std::vector<int32_t> witness(n, kLost);
  for (size_t k = 0; k < n; ++k) {
    const int old = change.previous_index[k];
    if (old < 0) continue;
    if (static_cast<int>(new_index_of_old.size()) <= old) new_index_of_old.resize(old + 1, -1);
    new_index_of_old[old] = static_cast<int>(k);
    witness[k] = witness_[j][old];
  }
  witness_[j] = std::move(witness);
  const std::vector<Eigen::Vector2d>& points = catalog_.submap(j).frontier.points_m;
  for (Watch& w : watches_[j]) {
    std::vector<Entry> kept;
    for (Entry e : w.entries) {
      const int k = e.point < new_index_of_old.size() ? new_index_of_old[e.point] : -1;
      if (k < 0) continue;
      e.point = static_cast<uint32_t>(k);
      kept.push_back(e);
    }
    w.entries = std::move(kept);
    w.has_entry.assign(n, false);
    for (const Entry& e : w.entries) w.has_entry[e.point] = true;
    // New points join the coverage disc; ResolveLost looks them up below.
    for (size_t k = 0; k < n; ++k) {
      if (change.previous_index[k] >= 0) continue;
      w.radius_m =
          std::max(w.radius_m, (w.coverage_anchor * points[k] - w.center).norm() + kSafety_m);
    }
  }
  for (size_t k = 0; k < n; ++k) {
    if (change.previous_index[k] < 0) lost_.push_back(static_cast<uint32_t>(k));
  }
  ResolveLost(j);
  for (size_t k = 0; k < n; ++k) is_frontier_[j][k] = witness_[j][k] == kNoWitness;
}

UpdateCost ExactStrategy::OnSubmapChanged(const SubmapChange& change) {
  const Stopwatch stopwatch;
  BeginUpdate();
  const int j = change.id;
  EnsureSize(catalog_.size());
  RemapPoints(change);  // sizes is_frontier_ / hint_; answers are rebuilt below
  discs_[j].valid = false;
  RemapOwnWatches(change);
  UpdateWatchesOf(j);
  // Other submaps' watches on j: j's answers changed inside the changed region.
  if (!change.changed_region.empty()) {
    for (const int i : watchers_[j]) {
      ReviewNearChange(i, FindWatch(i, j), change.changed_region);
      ResolveLost(i);
    }
    // Submaps whose points j's (grown) grid reaches for the first time.
    // Marks the submaps already watching j, so each candidate is checked in O(1).
    const geometry::Box2d& box = catalog_.submap(j).global_box;
    watched_.resize(catalog_.size(), 0);
    const size_t existing = watchers_[j].size();
    for (const int i : watchers_[j]) watched_[i] = 1;
    for (const int i : catalog_.index().Intersecting(box)) {
      if (i == j || watched_[i] || catalog_.submap(i).frontier.points_m.empty() ||
          !catalog_.GlobalPointsBox(i).Intersects(box)) {
        continue;
      }
      AddWatch(i, j);
      ResolveLost(i);
    }
    for (size_t k = 0; k < existing; ++k) watched_[watchers_[j][k]] = 0;
  }
  return EndUpdate(stopwatch.ElapsedUs());
}

}  // namespace scout::frontier
