#ifndef SCOUT_SIM_WORLD_OPTIONS_CHECK_H_
#define SCOUT_SIM_WORLD_OPTIONS_CHECK_H_

#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"

namespace scout::sim {

// Throws InputError "<world>: <key> = <value>: expected <expected>" unless 'ok'.
inline void RequireWorldOption(bool ok, const std::string& world, const std::string& key,
                               double value, const std::string& expected) {
  if (!ok) {
    throw InputError(world + ": " + key + " = " + FormatNumber(value) + ": expected " + expected);
  }
}

}  // namespace scout::sim

#endif  // SCOUT_SIM_WORLD_OPTIONS_CHECK_H_
