#ifndef SCOUT_EXPLORE_OPTION_CHECK_H_
#define SCOUT_EXPLORE_OPTION_CHECK_H_

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace scout::explore {

// Throws std::invalid_argument naming 'key', what was expected and the value.
[[noreturn]] inline void RejectOption(const std::string& group, const std::string& key,
                                      const std::string& expected, double value) {
  std::ostringstream os;
  os << group << " option '" << key << "': expected " << expected << ", got " << value;
  throw std::invalid_argument(os.str());
}

// Checks that 'value' is finite and at least 'min' (or above it when 'strict').
inline void CheckAtLeast(const std::string& group, const std::string& key, double value, double min,
                         bool strict = false) {
  const bool ok = std::isfinite(value) && (strict ? value > min : value >= min);
  if (!ok) {
    RejectOption(group, key,
                 std::string("a finite value ") + (strict ? "> " : ">= ") + std::to_string(min),
                 value);
  }
}

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_OPTION_CHECK_H_
