#ifndef SCOUT_GRID_DISTANCE_TRANSFORM_H_
#define SCOUT_GRID_DISTANCE_TRANSFORM_H_

#include <cstdint>
#include <vector>

namespace scout::grid {

// Exact Euclidean distance transform (Felzenszwalb & Huttenlocher's lower
// envelope of parabolas, separable in x then y). 'is_site' is row-major,
// width x height, non-zero for site cells. Returns, for every cell, the squared
// distance in cells from its centre to the nearest site centre; +infinity when
// there is no site at all. O(width * height).
std::vector<float> SquaredDistanceToNearestSite(const std::vector<uint8_t>& is_site, int width,
                                                int height);

}  // namespace scout::grid

#endif  // SCOUT_GRID_DISTANCE_TRANSFORM_H_
