#include "scout/frontier/frontier_options.h"

#include <cmath>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"

namespace scout::frontier {
namespace {

void RequirePositive(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(std::string("frontier option '") + key +
                     "': expected a positive number of metres, got " + FormatNumber(value));
  }
}

}  // namespace

void Validate(const FrontierOptions& options) {
  if (!(std::isfinite(options.inflation_radius_m) && options.inflation_radius_m >= 0.0)) {
    throw InputError("frontier option 'inflation_radius_m': expected >= 0 metres, got " +
                     FormatNumber(options.inflation_radius_m));
  }
  RequirePositive("epsilon_m", options.epsilon_m);
  RequirePositive("lidar_range_m", options.lidar_range_m);
  RequirePositive("exact_slack_m", options.exact_slack_m);
}

}  // namespace scout::frontier
