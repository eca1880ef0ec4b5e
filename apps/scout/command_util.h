#ifndef SCOUT_APPS_SCOUT_COMMAND_UTIL_H_
#define SCOUT_APPS_SCOUT_COMMAND_UTIL_H_

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "scout/explore/navigation_points.h"
#include "scout/frontier/frontier_engine.h"
#include "scout/io/config.h"
#include "scout/sim/world.h"

namespace scout::apps {

// Returns the options of 'config_file', or the built-in defaults when it is
// empty. Throws InputError for a bad file (see io::LoadConfig).
io::ScoutConfig LoadConfigOrDefaults(const std::string& config_file);

// Accepts decimal digits only, of a value at most 'max'. CLI11 parses "-3"
// into an unsigned seed as 2^64 - 3, and 2^64 + 1 as 2^64 - 1, without
// complaint; a seed the user mistyped must be an error.
CLI::Validator NonNegativeInteger(uint64_t max = std::numeric_limits<uint64_t>::max());

// Accepts a finite decimal number in [0, max]. CLI::NonNegativeNumber lets
// "nan" through (no comparison with NaN fails) and prints its range as 0 to
// DBL_MAX.
CLI::Validator NonNegativeFiniteNumber(double max = std::numeric_limits<double>::max());

// Accepts a finite decimal number > 0, named in the message by its unit
// ("seconds"): left to CLI11, "abc" reads "Could not convert: --opt = abc".
CLI::Validator PositiveFiniteNumber(const std::string& unit);

// Splits the comma-separated list given as 'option'. Throws InputError naming
// the option when an item is empty ("exact,", ",exact", "full,,exact"): a
// name left out by a typo must not pass silently.
std::vector<std::string> SplitList(const std::string& list, const std::string& option);

// The strategy whose frontier frontiers.png shows: 'requested' when given,
// else exact when it runs, else the first of 'strategies'. Throws InputError
// naming --picture-strategy when that one does not run in 'engine'.
std::string PictureStrategy(const std::string& requested,
                            const std::vector<std::string>& strategies,
                            const frontier::FrontierEngine& engine);

// Parses "X,Y" in metres given as 'option' ("--start"). Throws InputError
// naming the option and the expected form otherwise.
Eigen::Vector2d ParsePoint(const std::string& text, const std::string& option);

// navigation_points.csv: one row per navigation point, best first
// (rank,x_m,y_m,path_cost_m,info_gain_m2,revenue,cluster,component_points).
std::string NavigationPointsCsv(const std::vector<explore::NavigationPoint>& points);

// 'value' in fixed notation with 'decimals' decimals, or "-" when it was not
// measured (not finite): the commands' tables and summary lines print no "nan".
std::string FixedOrDash(double value, int decimals);

// Prints one line per strategy: queried points, P, accuracy, precision,
// recall and total update time.
void PrintStrategyTable(const frontier::FrontierEngine& engine, std::ostream& out);

// The options of one exploration run from an options file's sections
// (explore, robot, slam, frontier), before any command-line override.
exploration::ExplorationOptions ExplorationOptionsFrom(const io::ScoutConfig& config);

// Makes the world of --world and --seed, sized by --world-size when given
// ("W" or "WxH"); a size the generator cannot use is named as --world-size.
sim::World MakeCommandWorld(const std::string& world, uint64_t seed, const std::string& world_size);

// Throws InputError naming the first option of 'command' given an empty
// value ("--max-sim-time ''"), which CLI11 would take as not given at all.
void RejectEmptyValues(const CLI::App& command);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_COMMAND_UTIL_H_
