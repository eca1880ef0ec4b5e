#ifndef SCOUT_COMMON_FORMAT_H_
#define SCOUT_COMMON_FORMAT_H_

#include <cstdio>
#include <string>

namespace scout {

// 'value' for a message, with up to 15 significant digits and no trailing
// zeros: 0.05, 1e-09, 1134860000 (std::to_string prints 1e-9 as "0.000000"
// and 1.13486e+09 as "1134860000.000000").
inline std::string FormatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.15g", value);
  return text;
}

}  // namespace scout

#endif  // SCOUT_COMMON_FORMAT_H_
