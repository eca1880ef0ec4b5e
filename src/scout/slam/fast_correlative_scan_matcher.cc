#include "scout/slam/fast_correlative_scan_matcher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "scout/common/format.h"
#include "scout/grid/probability_values.h"

namespace scout::slam {
namespace {

// Unknown cells and cells outside the grid count as this raw value, which
// decodes to kMinProbability.
constexpr uint16_t kFloorValue = 1;
// Coarse levels store ceil(value * kMaxCoarse / kMaxValue): never below the
// value they bound. The floor maps to 1 as well.
constexpr int kMaxCoarse = 255;
constexpr uint8_t kCoarseFloor = 1;

uint8_t ToCoarse(uint16_t value) {
  return static_cast<uint8_t>((static_cast<int>(value) * kMaxCoarse + grid::kMaxValue - 1) /
                              grid::kMaxValue);
}

// Level 0 reads the grid's raw values: the update marker bit masked off and
// unknown (0) counted as the floor, branch-free.
struct DecodeRaw {
  int64_t operator()(uint16_t v) const {
    const int value = v & grid::kMaxValue;
    return value + (value == grid::kUnknownValue);
  }
};
struct AsIs {
  int64_t operator()(uint8_t v) const { return v; }
};

// Sum of the decoded values of a level under 'cells' shifted by (x, y); cells
// outside count as 'floor'. Cells wholly inside (known from the scan's
// bounds), the common case near a match, are read through 'flat' (the cells
// as y * width + x, made here on first use): a shift then adds one offset per
// cell instead of a multiply, and no cell needs the bounds check.
template <typename T, typename Decode>
int64_t SumCells(const T* values, int offset, int width, int height,
                 const std::vector<grid::CellIndex>& cells, std::vector<int32_t>& flat, bool inside,
                 int x, int y, int64_t floor, Decode decode) {
  int64_t sum = 0;
  const int dx = x + offset;
  const int dy = y + offset;
  if (inside) {
    if (flat.empty()) {
      flat.reserve(cells.size());
      for (const grid::CellIndex& cell : cells) flat.push_back(cell.y * width + cell.x);
    }
    const int64_t base = int64_t{dy} * width + dx;
    for (const int32_t f : flat) sum += decode(values[static_cast<size_t>(base + f)]);
    return sum;
  }
  for (const grid::CellIndex& cell : cells) {
    const int sx = cell.x + dx;
    const int sy = cell.y + dy;
    sum += (static_cast<unsigned>(sx) >= static_cast<unsigned>(width) ||
            static_cast<unsigned>(sy) >= static_cast<unsigned>(height))
               ? floor
               : decode(values[static_cast<size_t>(sy) * width + sx]);
  }
  return sum;
}

constexpr int kMidValue = (1 + grid::kMaxValue) / 2;  // decodes to 0.5
constexpr double kProbabilityPerValue =
    (0.9 - 0.1) /  // the exact bounds behind kMinProbability and kMaxProbability
    (grid::kMaxValue - 1);

// Scores are kept as integer sums of raw values: exact and independent of the
// summation order, so pruning compares bounds and leaves without rounding.
double ScoreOfSum(int64_t sum, size_t num_points) {
  return 0.5 + (static_cast<double>(sum) / static_cast<double>(num_points) - kMidValue) *
                   kProbabilityPerValue;
}

}  // namespace

struct FastCorrelativeScanMatcher::Candidate {
  int angle_index = 0;  // into the discretized scans
  int x = 0;            // cell offset
  int y = 0;
  int64_t sum = 0;  // upper bound (or, at depth 0, exact) sum of raw values
};

void Validate(const FastCorrelativeScanMatcherOptions& options) {
  if (!(options.linear_search_window_m >= 0.0)) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.linear_search_window_m must be >= 0, got " +
        std::to_string(options.linear_search_window_m));
  }
  if (!(options.angular_search_window_rad >= 0.0 &&
        options.angular_search_window_rad <= std::numbers::pi)) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.angular_search_window_rad must be in [0, pi], got " +
        FormatNumber(options.angular_search_window_rad));
  }
  if (options.branch_and_bound_depth < 1 || options.branch_and_bound_depth > 16) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.branch_and_bound_depth must be in [1, 16], got " +
        std::to_string(options.branch_and_bound_depth));
  }
}

double AngularSearchStep(double max_range_m, double resolution_m) {
  // A slightly smaller step than eq. 7 so a point at max range moves strictly
  // less than one cell between neighbouring angles.
  constexpr double kSafetyMargin = 1.0 - 1e-3;
  if (!(max_range_m > 0.0)) return std::numbers::pi;
  const double cos_step = 1.0 - resolution_m * resolution_m / (2.0 * max_range_m * max_range_m);
  return kSafetyMargin * std::acos(std::clamp(cos_step, -1.0, 1.0));
}

FastCorrelativeScanMatcher::FastCorrelativeScanMatcher(
    const grid::ProbabilityGrid& grid, const FastCorrelativeScanMatcherOptions& options)
    : FastCorrelativeScanMatcher(std::make_shared<const grid::ProbabilityGrid>(grid), options) {}

FastCorrelativeScanMatcher::FastCorrelativeScanMatcher(
    std::shared_ptr<const grid::ProbabilityGrid> grid,
    const FastCorrelativeScanMatcherOptions& options)
    : options_(options), grid_(std::move(grid)) {
  Validate(options);
  if (grid_ == nullptr) {
    throw std::invalid_argument("FastCorrelativeScanMatcher: null grid");
  }
  limits_ = grid_->limits();
  // Decoded level 0, needed only while pooling level 1.
  PrecomputedGrid<uint16_t> exact;
  exact.width = limits_.width();
  exact.height = limits_.height();
  exact.values.resize(grid_->values().size());
  for (size_t i = 0; i < exact.values.size(); ++i) {
    exact.values[i] = static_cast<uint16_t>(DecodeRaw()(grid_->values()[i]));
  }
  // Level d from level d - 1: a 2^d window is the union of four 2^(d-1)
  // windows, so each level costs four lookups per cell. Rounding up commutes
  // with max, so quantizing level 1 and pooling bytes above stays a bound.
  const auto pool = [this](const auto& finer, int d, auto quantize) {
    const int half = 1 << (d - 1);
    PrecomputedGrid<uint8_t> level;
    level.offset = (1 << d) - 1;
    level.width = limits_.width() + level.offset;
    level.height = limits_.height() + level.offset;
    level.values.resize(static_cast<size_t>(level.width) * level.height);
    using Value = typename std::decay_t<decltype(finer.values)>::value_type;
    const Value floor = static_cast<Value>(d == 1 ? kFloorValue : kCoarseFloor);
    const auto finer_at = [&finer, floor](int cx, int cy) -> Value {
      const int sx = cx + finer.offset;
      const int sy = cy + finer.offset;
      if (sx < 0 || sy < 0 || sx >= finer.width || sy >= finer.height) return floor;
      return finer.values[static_cast<size_t>(sy) * finer.width + sx];
    };
    for (int sy = 0; sy < level.height; ++sy) {
      const int cy = sy - level.offset;
      for (int sx = 0; sx < level.width; ++sx) {
        const int cx = sx - level.offset;
        level.values[static_cast<size_t>(sy) * level.width + sx] =
            quantize(std::max({finer_at(cx, cy), finer_at(cx + half, cy), finer_at(cx, cy + half),
                               finer_at(cx + half, cy + half)}));
      }
    }
    return level;
  };
  for (int d = 1; d < options.branch_and_bound_depth; ++d) {
    if (d == 1) {
      coarse_.push_back(pool(exact, d, ToCoarse));
    } else {
      coarse_.push_back(pool(coarse_.back(), d, [](uint8_t v) { return v; }));
    }
  }
}

int64_t FastCorrelativeScanMatcher::Score(int depth, const DiscreteScan& scan, int x, int y) const {
  if (depth == 0) {
    const bool inside = scan.min_x + x >= 0 && scan.min_y + y >= 0 &&
                        scan.max_x + x < limits_.width() && scan.max_y + y < limits_.height();
    return SumCells(grid_->values().data(), 0, limits_.width(), limits_.height(), scan.cells,
                    scan.flat_cells[0], inside, x, y, kFloorValue, DecodeRaw());
  }
  const PrecomputedGrid<uint8_t>& level = coarse_[depth - 1];
  const bool inside = scan.min_x + x + level.offset >= 0 && scan.min_y + y + level.offset >= 0 &&
                      scan.max_x + x + level.offset < level.width &&
                      scan.max_y + y + level.offset < level.height;
  const int64_t sum =
      SumCells(level.values.data(), level.offset, level.width, level.height, scan.cells,
               scan.flat_cells[depth], inside, x, y, kCoarseFloor, AsIs());
  // Back to level 0 units, rounded up so the bound stays a bound.
  return (sum * grid::kMaxValue + kMaxCoarse - 1) / kMaxCoarse;
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::Match(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
    double min_score) const {
  return Search(initial_pose_estimate, points, options_.linear_search_window_m,
                options_.angular_search_window_rad, min_score, /*check_ambiguity=*/true);
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::Match(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points, double min_score,
    double linear_window_m, double angular_window_rad,
    std::optional<ScanMatchResult>* ambiguous) const {
  return Search(initial_pose_estimate, points, linear_window_m, angular_window_rad, min_score,
                /*check_ambiguity=*/true, ambiguous);
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::MatchFullSubmap(const PointCloud& points,
                                                                           double min_score) const {
  const geometry::Box2d bounds = limits_.Bounds();
  const Eigen::Vector2d center = 0.5 * (bounds.min + bounds.max);
  const double half_extent_m =
      0.5 * std::max(bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y());
  return Search(geometry::Rigid2d(center, 0.0), points, half_extent_m + limits_.resolution(),
                std::numbers::pi, min_score, /*check_ambiguity=*/true);
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::Search(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
    double linear_window_m, double angular_window_rad, double min_score, bool check_ambiguity,
    std::optional<ScanMatchResult>* ambiguous) const {
  if (points.empty()) return std::nullopt;
  const double resolution = limits_.resolution();
  double max_range_m = 0.0;
  for (const Eigen::Vector2d& p : points) max_range_m = std::max(max_range_m, p.norm());
  const double angle_step = AngularSearchStep(max_range_m, resolution);
  const int num_angles_each_side = static_cast<int>(std::ceil(angular_window_rad / angle_step));
  const int linear_bound = static_cast<int>(std::ceil(linear_window_m / resolution));

  // The scan, placed at the initial translation under each candidate angle and
  // discretized once; translations then only shift cell indices.
  std::vector<DiscreteScan> scans;
  std::vector<double> angles;
  for (int k = -num_angles_each_side; k <= num_angles_each_side; ++k) {
    const double angle = initial_pose_estimate.theta() + k * angle_step;
    const geometry::Rigid2d pose(initial_pose_estimate.translation(), angle);
    DiscreteScan& scan = scans.emplace_back();
    scan.flat_cells.resize(coarse_.size() + 1);
    scan.cells.reserve(points.size());
    for (const Eigen::Vector2d& p : points) scan.cells.push_back(limits_.CellContaining(pose * p));
    scan.min_x = scan.max_x = scan.cells.front().x;
    scan.min_y = scan.max_y = scan.cells.front().y;
    for (const grid::CellIndex& c : scan.cells) {
      scan.min_x = std::min(scan.min_x, c.x);
      scan.max_x = std::max(scan.max_x, c.x);
      scan.min_y = std::min(scan.min_y, c.y);
      scan.max_y = std::max(scan.max_y, c.y);
    }
    angles.push_back(angle);
  }

  const auto by_bound = [](const Candidate& a, const Candidate& b) { return a.sum > b.sum; };
  const int top = static_cast<int>(coarse_.size());
  const int top_step = 1 << top;

  // Returns the best candidate with a sum of at least 'min_sum' outside
  // 'exclusion' (none if radius < 0); with 'any_will_do', the first such
  // candidate found, which is all the ambiguity test asks (whether one exists)
  // and saves exploring the rest of the tree for a better one.
  const auto best_candidate = [&](int64_t min_sum, const Exclusion& exclusion,
                                  bool any_will_do) -> std::optional<Candidate> {
    const double radius_sq = exclusion.radius * exclusion.radius;
    const auto excluded = [&](int x, int y) {
      const double dx = x - exclusion.x;
      const double dy = y - exclusion.y;
      return exclusion.radius >= 0.0 && dx * dx + dy * dy <= radius_sq;
    };
    // A block [x, x + size) x [y, y + size) wholly inside the exclusion disc
    // holds no answer (its four corners inside suffice: the disc is convex).
    const auto block_excluded = [&](int x, int y, int size) {
      return excluded(x, y) && excluded(x + size - 1, y) && excluded(x, y + size - 1) &&
             excluded(x + size - 1, y + size - 1);
    };
    std::vector<Candidate> roots;
    for (int a = 0; a < static_cast<int>(scans.size()); ++a) {
      for (int x = -linear_bound; x <= linear_bound; x += top_step) {
        for (int y = -linear_bound; y <= linear_bound; y += top_step) {
          if (block_excluded(x, y, top_step)) continue;
          const Candidate c{a, x, y, Score(top, scans[a], x, y)};
          // Hopeless roots never need sorting.
          if (c.sum >= min_sum) roots.push_back(c);
        }
      }
    }
    std::sort(roots.begin(), roots.end(), by_bound);

    std::optional<Candidate> best;
    bool done = false;
    // Depth-first, best bound first (Hess et al. 2016, algorithm 3): a node is
    // expanded only if its bound beats both the threshold and the best leaf.
    const auto branch = [&](auto&& self, const Candidate* candidates, size_t count,
                            int depth) -> void {
      for (size_t i = 0; i < count; ++i) {
        const Candidate& c = candidates[i];
        if (c.sum < min_sum) return;
        if (best.has_value() && c.sum <= best->sum) return;
        if (depth == 0) {
          if (excluded(c.x, c.y)) continue;
          best = c;
          if (any_will_do) {
            done = true;
            return;
          }
          continue;  // sorted: later siblings cannot beat this leaf
        }
        const int half = 1 << (depth - 1);
        std::array<Candidate, 4> children;
        size_t num_children = 0;
        for (const int dx : {0, half}) {
          if (c.x + dx > linear_bound) continue;
          for (const int dy : {0, half}) {
            if (c.y + dy > linear_bound) continue;
            if (block_excluded(c.x + dx, c.y + dy, half)) continue;
            children[num_children++] = {c.angle_index, c.x + dx, c.y + dy,
                                        Score(depth - 1, scans[c.angle_index], c.x + dx, c.y + dy)};
          }
        }
        // Insertion sort: at most four elements (and std::sort's 16-element
        // threshold trips GCC's array-bounds analysis here).
        for (size_t j = 1; j < num_children; ++j) {
          for (size_t k = j; k > 0 && by_bound(children[k], children[k - 1]); --k) {
            std::swap(children[k], children[k - 1]);
          }
        }
        self(self, children.data(), num_children, depth - 1);
        if (done) return;
      }
    };
    branch(branch, roots.data(), roots.size(), top);
    return best;
  };

  // The smallest sum whose score reaches 'score' (ScoreOfSum is increasing).
  const auto min_sum_for = [&](double score) {
    const double per_point =
        kMidValue + (score - 0.5) / kProbabilityPerValue;  // inverse of ScoreOfSum
    int64_t sum = static_cast<int64_t>(std::floor(per_point * static_cast<double>(points.size())));
    while (ScoreOfSum(sum, points.size()) < score) ++sum;
    while (sum > 0 && ScoreOfSum(sum - 1, points.size()) >= score) --sum;
    return sum;
  };

  const std::optional<Candidate> best =
      best_candidate(min_sum_for(min_score), Exclusion{0, 0, -1.0}, /*any_will_do=*/false);
  if (!best.has_value()) return std::nullopt;
  const Eigen::Vector2d translation =
      initial_pose_estimate.translation() + resolution * Eigen::Vector2d(best->x, best->y);
  const ScanMatchResult result{geometry::Rigid2d(translation, angles[best->angle_index]),
                               ScoreOfSum(best->sum, points.size())};
  if (check_ambiguity && options_.ambiguity_radius_m > 0.0) {
    const Exclusion around_best{best->x, best->y, options_.ambiguity_radius_m / resolution};
    if (best_candidate(min_sum_for(result.score - options_.ambiguity_score_margin), around_best,
                       /*any_will_do=*/true)) {
      if (ambiguous != nullptr) *ambiguous = result;
      return std::nullopt;  // a distant pose fits about as well: ambiguous
    }
  }
  return result;
}

}  // namespace scout::slam
