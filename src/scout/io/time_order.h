#ifndef SCOUT_IO_TIME_ORDER_H_
#define SCOUT_IO_TIME_ORDER_H_

// Internal to the dataset readers (C++17-compatible: the bag reader uses it).

#include <cstddef>
#include <utility>
#include <vector>

namespace scout::io {

// Returns, for each of 'times' (in arrival order), whether it is kept: the
// longest non-decreasing subsequence, and of several equally long ones the
// one that keeps the earliest arrivals. One corrupt stamp far in the future
// thus loses only itself, where dropping every message earlier than the last
// kept one would lose everything after it. Equal times are kept.
std::vector<bool> LongestTimeOrder(const std::vector<double>& times);

// LongestTimeOrder of the items' 'time_s'.
template <typename Stamped>
std::vector<bool> LongestTimeOrderOf(const std::vector<Stamped>& items) {
  std::vector<double> times;
  times.reserve(items.size());
  for (const Stamped& item : items) times.push_back(item.time_s);
  return LongestTimeOrder(times);
}

// Removes the items whose 'keep' is false; the rest keep their order.
template <typename T>
void KeepOnly(const std::vector<bool>& keep, std::vector<T>* items) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < items->size(); ++i) {
    if (!keep[i]) continue;
    // Never onto itself: a vector moved onto itself is left empty.
    if (kept != i) (*items)[kept] = std::move((*items)[i]);
    ++kept;
  }
  items->resize(kept);
}

}  // namespace scout::io

#endif  // SCOUT_IO_TIME_ORDER_H_
