#ifndef SCOUT_APPS_SCOUT_COMMAND_UTIL_H_
#define SCOUT_APPS_SCOUT_COMMAND_UTIL_H_

#include <ostream>
#include <string>
#include <vector>

#include "scout/frontier/frontier_engine.h"

namespace scout::apps {

// Splits a comma-separated list, dropping empty items.
std::vector<std::string> SplitList(const std::string& list);

// Prints one line per strategy: queried points, P, accuracy, precision,
// recall and total update time.
void PrintStrategyTable(const frontier::FrontierEngine& engine, std::ostream& out);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_COMMAND_UTIL_H_
