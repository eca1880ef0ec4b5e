#ifndef SCOUT_COMMON_FORMAT_H_
#define SCOUT_COMMON_FORMAT_H_

#include <sstream>
#include <string>

namespace scout {

// A value for an error message as a user would write it: 0.05, 1e-09, 1000
// (std::to_string prints 1e-9 as 0.000000).
inline std::string ShortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace scout

#endif  // SCOUT_COMMON_FORMAT_H_
