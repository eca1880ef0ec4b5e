#include "scout/grid/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "scout/common/parallel.h"

namespace scout::grid {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Felzenszwalb & Huttenlocher's 1-D transform: d[q] = min_p (q - p)^2 + f[p],
// the lower envelope of the parabolas rooted at (p, f[p]). Infinite samples
// are left out of the envelope rather than represented by a large constant, so
// intersections are computed only between finite parabolas (no inf - inf) and
// the result stays exact. 'v' and 'z' are scratch space of size n and n + 1.
// Values are doubles: squared distances of large grids exceed float's exact
// integer range, and the intersection formula needs the extra precision.
void DistanceTransform1d(const std::vector<double>& f, int n, std::vector<double>* d,
                         std::vector<int>* v, std::vector<double>* z) {
  int k = -1;  // index of the rightmost parabola in the envelope
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInfinity) continue;
    double s = -kInfinity;
    while (k >= 0) {
      const int p = (*v)[k];
      s = ((f[q] + static_cast<double>(q) * q) - (f[p] + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s > (*z)[k]) break;
      --k;  // parabola p is hidden below q's from z[k] on
    }
    if (k < 0) s = -kInfinity;
    ++k;
    (*v)[k] = q;
    (*z)[k] = s;
    (*z)[k + 1] = kInfinity;
  }
  if (k < 0) {
    for (int q = 0; q < n; ++q) (*d)[q] = kInfinity;
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while ((*z)[j + 1] < q) ++j;
    const double dq = q - (*v)[j];
    (*d)[q] = dq * dq + f[(*v)[j]];
  }
}

}  // namespace

std::vector<float> SquaredDistanceToNearestSite(const std::vector<uint8_t>& is_site, int width,
                                                int height) {
  if (width < 0 || height < 0 ||
      is_site.size() != static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw std::invalid_argument("SquaredDistanceToNearestSite: mask has " +
                                std::to_string(is_site.size()) + " cells, expected " +
                                std::to_string(width) + " x " + std::to_string(height));
  }
  const size_t num_cells = is_site.size();
  // Pass 1, along each column: distance in cells to the nearest site in the
  // same column, by one downward and one upward sweep over whole rows, so both
  // sweeps read memory contiguously (Meijster et al.'s first phase).
  constexpr int32_t kNone = std::numeric_limits<int32_t>::max();
  std::vector<int32_t> along_y(num_cells);
  // Columns are independent in pass 1 and rows in pass 2: each thread takes a
  // block of them, so the result is the serial one. Grids below
  // kMinCellsPerThread cells per thread stay on the calling thread.
  constexpr int64_t kMinCellsPerThread = 1 << 16;
  const auto lines_per_thread = [](int64_t length) {
    return std::max<int64_t>(1, kMinCellsPerThread / std::max<int64_t>(1, length));
  };
  common::ParallelFor(width, lines_per_thread(height), [&](int64_t x0, int64_t x1) {
    for (int y = 0; y < height; ++y) {
      const size_t row = static_cast<size_t>(y) * width;
      for (int64_t x = x0; x < x1; ++x) {
        const int32_t above = y > 0 ? along_y[row - width + x] : kNone;
        along_y[row + x] = is_site[row + x] ? 0 : (above == kNone ? kNone : above + 1);
      }
    }
    for (int y = height - 2; y >= 0; --y) {
      const size_t row = static_cast<size_t>(y) * width;
      for (int64_t x = x0; x < x1; ++x) {
        const int32_t below = along_y[row + width + x];
        if (below != kNone && below + 1 < along_y[row + x]) along_y[row + x] = below + 1;
      }
    }
  });
  // Pass 2, along each row over the column results: dx^2 + dy^2 minimised.
  std::vector<float> result(num_cells);
  common::ParallelFor(height, lines_per_thread(width), [&](int64_t y0, int64_t y1) {
    std::vector<double> f(width), d(width), z(width + 1);
    std::vector<int> v(width);
    for (int64_t y = y0; y < y1; ++y) {
      const size_t row = static_cast<size_t>(y) * width;
      for (int x = 0; x < width; ++x) {
        const int32_t dy = along_y[row + x];
        f[x] = dy == kNone ? kInfinity : static_cast<double>(dy) * dy;
      }
      DistanceTransform1d(f, width, &d, &v, &z);
      for (int x = 0; x < width; ++x) result[row + x] = static_cast<float>(d[x]);
    }
  });
  return result;
}

}  // namespace scout::grid
