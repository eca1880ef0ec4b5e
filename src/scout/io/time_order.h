#ifndef SCOUT_IO_TIME_ORDER_H_
#define SCOUT_IO_TIME_ORDER_H_

// Internal to the dataset readers (C++17-compatible: the bag reader uses it).

#include <vector>

namespace scout::io {

// Returns, for each of 'times' (in arrival order), whether it is kept: the
// longest non-decreasing subsequence, and of several equally long ones the
// one that keeps the earliest arrivals. One corrupt stamp far in the future
// thus loses only itself, where dropping every message earlier than the last
// kept one would lose everything after it. Equal times are kept.
std::vector<bool> LongestTimeOrder(const std::vector<double>& times);

}  // namespace scout::io

#endif  // SCOUT_IO_TIME_ORDER_H_
