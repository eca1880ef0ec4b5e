#include "scout/io/trajectory_association.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>

namespace scout::io {
namespace {

// Float32 ranges and their printed copies differ by the print rounding plus
// the float representation error (under 1e-5 m at 80 m); this covers the latter.
constexpr double kFloatSlackM = 1e-4;
// Rounded value standing for a non-finite range in the hash.
constexpr int64_t kNonFiniteKey = INT64_MIN;

using IndexPair = std::pair<int, int>;

int64_t RoundedRange(float r, double tolerance_m) {
  return std::isfinite(r) ? std::llround(r / tolerance_m) : kNonFiniteKey;
}

uint64_t HashOfRoundedRanges(const std::vector<float>& ranges, int beams, double tolerance_m) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the rounded values
  for (int k = 0; k < beams; ++k) {
    h ^= static_cast<uint64_t>(RoundedRange(ranges[k], tolerance_m));
    h *= 1099511628211ull;
  }
  return h;
}

bool SameReading(const std::vector<float>& a, const std::vector<float>& b, double tolerance_m) {
  const size_t n = std::min(a.size(), b.size());
  if (n == 0 || std::max(a.size(), b.size()) - n > 1) return false;
  const double max_difference = 0.5 * tolerance_m + kFloatSlackM;
  for (size_t k = 0; k < n; ++k) {
    const bool finite_a = std::isfinite(a[k]);
    if (finite_a != static_cast<bool>(std::isfinite(b[k]))) return false;
    if (finite_a && std::abs(static_cast<double>(a[k]) - b[k]) > max_difference) return false;
  }
  return true;
}

// Returns the chain of 'candidates' strictly increasing in both indices with
// the most elements and, among those, the least summed cost(i, j). A Fenwick
// tree over j holds the best chain ending below each j; candidates of one i
// are visited by decreasing j so that no chain takes two of them.
std::vector<IndexPair> BestMonotoneChain(std::vector<IndexPair> candidates, int b_size,
                                         const std::function<double(int, int)>& cost) {
  std::sort(candidates.begin(), candidates.end(), [](const IndexPair& l, const IndexPair& r) {
    return l.first != r.first ? l.first < r.first : l.second > r.second;
  });
  struct Chain {
    int length = 0;
    double cost = 0.0;
    int last = -1;  // index into 'candidates' of the chain's last element
  };
  const auto better = [](const Chain& l, const Chain& r) {
    return l.length != r.length ? l.length > r.length : l.cost < r.cost;
  };
  std::vector<Chain> tree(b_size + 1);
  std::vector<int> previous(candidates.size(), -1);
  Chain best;
  for (size_t c = 0; c < candidates.size(); ++c) {
    const auto [i, j] = candidates[c];
    Chain prefix;  // best chain whose last j is < j
    for (int k = j; k > 0; k -= k & -k) {
      if (better(tree[k], prefix)) prefix = tree[k];
    }
    const Chain extended{prefix.length + 1, prefix.cost + cost(i, j), static_cast<int>(c)};
    previous[c] = prefix.last;
    for (int k = j + 1; k <= b_size; k += k & -k) {
      if (better(extended, tree[k])) tree[k] = extended;
    }
    if (better(extended, best)) best = extended;
  }
  std::vector<IndexPair> chain;
  for (int c = best.last; c >= 0; c = previous[c]) chain.push_back(candidates[c]);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// The j expected for each i from the unambiguous matches: linear between
// them, a constant index offset beyond them, proportional without any.
std::function<double(int)> ExpectedProgression(const std::vector<IndexPair>& anchors, int a_size,
                                               int b_size) {
  if (anchors.empty()) {
    const double slope = a_size > 1 ? static_cast<double>(b_size - 1) / (a_size - 1) : 0.0;
    return [slope](int i) { return slope * i; };
  }
  return [anchors](int i) {
    const auto next = std::lower_bound(anchors.begin(), anchors.end(), IndexPair{i, -1});
    if (next == anchors.begin()) return static_cast<double>(next->second + (i - next->first));
    const IndexPair& lo = *(next - 1);
    if (next == anchors.end()) return static_cast<double>(lo.second + (i - lo.first));
    const double f = static_cast<double>(i - lo.first) / (next->first - lo.first);
    return lo.second + f * (next->second - lo.second);
  };
}

}  // namespace

std::vector<PosePair> PairByIndex(const std::vector<StampedPose>& estimate,
                                  const std::vector<std::optional<geometry::Rigid2d>>& reference) {
  std::vector<PosePair> pairs;
  for (size_t i = 0; i < estimate.size() && i < reference.size(); ++i) {
    if (reference[i]) pairs.push_back({estimate[i].time_s, estimate[i].pose, *reference[i]});
  }
  return pairs;
}

std::vector<PosePair> AssociateByTime(const std::vector<StampedPose>& estimate,
                                      const std::vector<StampedPose>& reference, double max_dt_s) {
  std::vector<StampedPose> sorted_reference = reference;
  std::stable_sort(sorted_reference.begin(), sorted_reference.end(),
                   [](const StampedPose& l, const StampedPose& r) { return l.time_s < r.time_s; });
  std::vector<PosePair> pairs;
  for (const StampedPose& e : estimate) {
    const auto after =
        std::lower_bound(sorted_reference.begin(), sorted_reference.end(), e.time_s,
                         [](const StampedPose& r, double t) { return r.time_s < t; });
    const StampedPose* nearest = nullptr;
    if (after != sorted_reference.end()) nearest = &*after;
    if (after != sorted_reference.begin() &&
        (nearest == nullptr || e.time_s - (after - 1)->time_s < nearest->time_s - e.time_s)) {
      nearest = &*(after - 1);
    }
    if (nearest == nullptr || std::abs(nearest->time_s - e.time_s) > max_dt_s) continue;
    pairs.push_back({e.time_s, e.pose, nearest->pose});
  }
  return pairs;
}

std::vector<std::pair<int, int>> MatchScansByRanges(const std::vector<std::vector<float>>& a,
                                                    const std::vector<std::vector<float>>& b,
                                                    double tolerance_m) {
  const int a_size = static_cast<int>(a.size());
  const int b_size = static_cast<int>(b.size());
  if (a_size == 0 || b_size == 0 || !(tolerance_m > 0.0)) return {};
  // Hash the leading beams every scan has, so that a 360- and a 361-beam copy
  // of one reading land in the same bucket.
  size_t hashed_beams = SIZE_MAX;
  for (const auto* scans : {&a, &b}) {
    for (const std::vector<float>& s : *scans) hashed_beams = std::min(hashed_beams, s.size());
  }
  const int beams = static_cast<int>(hashed_beams);
  std::unordered_map<uint64_t, std::vector<int>> b_by_hash;
  for (int j = 0; j < b_size; ++j) {
    b_by_hash[HashOfRoundedRanges(b[j], beams, tolerance_m)].push_back(j);
  }
  std::vector<IndexPair> candidates;
  std::vector<int> candidates_of_j(b_size, 0);
  std::vector<int> candidates_of_i(a_size, 0);
  for (int i = 0; i < a_size; ++i) {
    const auto bucket = b_by_hash.find(HashOfRoundedRanges(a[i], beams, tolerance_m));
    if (bucket == b_by_hash.end()) continue;
    for (const int j : bucket->second) {
      if (!SameReading(a[i], b[j], tolerance_m)) continue;
      candidates.push_back({i, j});
      ++candidates_of_i[i];
      ++candidates_of_j[j];
    }
  }
  // Readings seen once on each side fix the progression the ambiguous ones follow.
  std::vector<IndexPair> unique;
  for (const IndexPair& c : candidates) {
    if (candidates_of_i[c.first] == 1 && candidates_of_j[c.second] == 1) unique.push_back(c);
  }
  const std::vector<IndexPair> anchors =
      BestMonotoneChain(unique, b_size, [](int, int) { return 0.0; });
  const std::function<double(int)> expected = ExpectedProgression(anchors, a_size, b_size);
  std::vector<IndexPair> chain = BestMonotoneChain(
      candidates, b_size, [&expected](int i, int j) { return std::abs(j - expected(i)); });

  // Scans the hash missed (a range on a rounding boundary) can only lie
  // between the matches around them.
  std::vector<IndexPair> matches;
  size_t next = 0;
  int previous_j = -1;
  for (int i = 0; i < a_size; ++i) {
    if (next < chain.size() && chain[next].first == i) {
      matches.push_back(chain[next]);
      previous_j = chain[next++].second;
      continue;
    }
    const int end_j = next < chain.size() ? chain[next].second : b_size;
    for (int j = previous_j + 1; j < end_j; ++j) {
      if (SameReading(a[i], b[j], tolerance_m)) {
        matches.push_back({i, j});
        previous_j = j;
        break;
      }
    }
  }
  return matches;
}

}  // namespace scout::io
