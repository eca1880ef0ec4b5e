#include "scout/io/time_order.h"

#include <algorithm>
#include <cstddef>

namespace scout::io {

std::vector<bool> LongestTimeOrder(const std::vector<double>& times) {
  const std::size_t n = times.size();
  // longest_from[i]: length of the longest non-decreasing subsequence that
  // starts at i. Walking backwards, it is the longest non-increasing one
  // ending at i, found by patience sorting on the negated times.
  std::vector<std::size_t> longest_from(n);
  std::vector<double> tails;  // tails[k]: smallest negated time ending a run of k + 1
  for (std::size_t i = n; i-- > 0;) {
    const double negated = -times[i];
    const auto it = std::upper_bound(tails.begin(), tails.end(), negated);
    longest_from[i] = static_cast<std::size_t>(it - tails.begin()) + 1;
    if (it == tails.end()) {
      tails.push_back(negated);
    } else {
      *it = negated;
    }
  }
  // Forward, take the first message that can still start a run as long as
  // what is left to keep: the earliest arrivals among the longest runs.
  std::vector<bool> keep(n, false);
  std::size_t needed = tails.size();
  bool any = false;
  double last = 0.0;
  for (std::size_t i = 0; i < n && needed > 0; ++i) {
    if (longest_from[i] == needed && (!any || times[i] >= last)) {
      keep[i] = true;
      last = times[i];
      any = true;
      --needed;
    }
  }
  return keep;
}

}  // namespace scout::io
