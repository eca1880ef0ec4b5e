#include "scout/sim/make_world.h"

#include "scout/common/error.h"
#include "scout/sim/museum_world.h"
#include "scout/sim/office_world.h"

namespace scout::sim {

World MakeWorld(const std::string& name_or_yaml, uint64_t seed) {
  if (name_or_yaml == "office") return GenerateOfficeWorld(seed);
  if (name_or_yaml == "museum") return GenerateMuseumWorld(seed);
  const std::string suffix = ".yaml";
  if (name_or_yaml.size() > suffix.size() &&
      name_or_yaml.compare(name_or_yaml.size() - suffix.size(), suffix.size(), suffix) == 0) {
    return LoadMapWorld(name_or_yaml);
  }
  throw InputError("unknown world '" + name_or_yaml +
                   "': expected office, museum or a map_server .yaml file");
}

}  // namespace scout::sim
