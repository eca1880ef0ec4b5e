#include "scout/sim/make_world.h"

#include <cmath>
#include <cstdlib>

#include "scout/common/error.h"
#include "scout/sim/museum_world.h"
#include "scout/sim/office_world.h"

namespace scout::sim {
namespace {

// Parses the whole of 'text' as a finite number > 0, or returns nullopt.
std::optional<double> ParsePositive(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v) || v <= 0.0) return std::nullopt;
  return v;
}

}  // namespace

WorldSize ParseWorldSize(const std::string& text) {
  const size_t x = text.find('x');
  const std::optional<double> w = ParsePositive(text.substr(0, x));
  const std::optional<double> h = x == std::string::npos ? w : ParsePositive(text.substr(x + 1));
  if (!w || !h) {
    throw InputError("world size '" + text +
                     "': expected W or WxH in metres, both > 0 (e.g. 100 or 160x100)");
  }
  if (*w > kMaxWorldSide_m || *h > kMaxWorldSide_m) {
    throw InputError("world size '" + text + "': expected sides of at most " +
                     std::to_string(static_cast<int>(kMaxWorldSide_m)) +
                     " m (a 500 m museum's synthetic SLAM stream already takes more than 8 GB)");
  }
  return {*w, *h};
}

World MakeWorld(const std::string& name_or_yaml, uint64_t seed,
                const std::optional<WorldSize>& size) {
  if (name_or_yaml == "office") {
    OfficeWorldOptions options;
    if (size) {
      options.width_m = size->width_m;
      options.height_m = size->height_m;
    }
    return GenerateOfficeWorld(seed, options);
  }
  if (name_or_yaml == "museum") {
    MuseumWorldOptions options;
    if (size) {
      options.width_m = size->width_m;
      options.height_m = size->height_m;
    }
    return GenerateMuseumWorld(seed, options);
  }
  const std::string suffix = ".yaml";
  if (name_or_yaml.size() > suffix.size() &&
      name_or_yaml.compare(name_or_yaml.size() - suffix.size(), suffix.size(), suffix) == 0) {
    if (size) {
      throw InputError("world size given for the map file '" + name_or_yaml +
                       "': only the generated office and museum can be resized");
    }
    return LoadMapWorld(name_or_yaml);
  }
  throw InputError("unknown world '" + name_or_yaml +
                   "': expected office, museum or a map_server .yaml file");
}

}  // namespace scout::sim
