#include "apps/scout/command_util.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "scout/common/error.h"
#include "scout/common/input_limits.h"
#include "scout/sim/make_world.h"

namespace scout::apps {

CLI::Validator NonNegativeInteger(uint64_t max) {
  return CLI::Validator(
      [max](std::string& value) -> std::string {
        const bool digits =
            !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
        uint64_t parsed = 0;
        const auto [end, error] =
            std::from_chars(value.data(), value.data() + value.size(), parsed);
        if (digits && error == std::errc() && end == value.data() + value.size() && parsed <= max) {
          return std::string();
        }
        return "expected a non-negative integer (at most " + std::to_string(max) + "), got '" +
               value + "'";
      },
      "NONNEGATIVE");
}

io::ScoutConfig LoadConfigOrDefaults(const std::string& config_file) {
  return config_file.empty() ? io::ScoutConfig{} : io::LoadConfig(config_file);
}

namespace {

// The whole of 'value' as a finite decimal number, or nothing.
std::optional<double> ParseFiniteNumber(const std::string& value) {
  const char* begin = value.c_str();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(begin, &end);
  if (value.empty() || end != begin + value.size() || errno != 0 || !std::isfinite(x)) {
    return std::nullopt;
  }
  return x;
}

}  // namespace

CLI::Validator NonNegativeFiniteNumber(double max) {
  return CLI::Validator(
      [max](std::string& value) -> std::string {
        const std::optional<double> x = ParseFiniteNumber(value);
        if (x && *x >= 0.0 && *x <= max) return std::string();
        if (max < std::numeric_limits<double>::max()) {
          std::ostringstream range;
          range << "expected a number from 0 to " << max << ", got '" << value << "'";
          return range.str();
        }
        return "expected a finite number >= 0, got '" + value + "'";
      },
      "NONNEGATIVE");
}

CLI::Validator PositiveFiniteNumber(const std::string& unit) {
  return CLI::Validator(
      [unit](std::string& value) -> std::string {
        const std::optional<double> x = ParseFiniteNumber(value);
        if (x && *x > 0.0) return std::string();
        return "expected a positive finite number of " + unit + ", got '" + value + "'";
      },
      "POSITIVE");
}

std::vector<std::string> SplitList(const std::string& list, const std::string& option) {
  std::vector<std::string> items;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) items.push_back(item);
  // getline drops one trailing empty item: "exact," gives only "exact".
  if (!list.empty() && list.back() == ',') items.emplace_back();
  for (const std::string& name : items) {
    if (name.empty()) {
      throw InputError(option + " '" + list + "': expected comma-separated names, none empty");
    }
  }
  return items;
}

std::string PictureStrategy(const std::string& requested,
                            const std::vector<std::string>& strategies,
                            const frontier::FrontierEngine& engine) {
  std::string name = requested;
  if (name.empty()) {
    const bool has_exact =
        std::find(strategies.begin(), strategies.end(), "exact") != strategies.end();
    name = has_exact || strategies.empty() ? "exact" : strategies.front();
  }
  try {
    engine.strategy(name);
  } catch (const InputError&) {
    std::string running;
    for (const std::string& s : engine.strategy_names())
      running += (running.empty() ? "" : ",") + s;
    throw InputError("--picture-strategy '" + name + "': not among the strategies that run (" +
                     running + ")");
  }
  return name;
}

std::string FixedOrDash(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

void PrintStrategyTable(const frontier::FrontierEngine& engine, std::ostream& out) {
  out << std::left << std::setw(8) << "strategy" << std::right << std::setw(14) << "queried_pts"
      << std::setw(10) << "P" << std::setw(10) << "accuracy" << std::setw(11) << "precision"
      << std::setw(9) << "recall" << std::setw(11) << "time_ms"
      << "\n";
  // Not measured prints as a dash: P without dfd (NaN), the scores without
  // "full" to score against (an unscored strategy would read 1.0000).
  const double unscored = std::numeric_limits<double>::quiet_NaN();
  const bool scored = engine.evaluating();
  const auto figure = [&](double value, bool measured) {
    return FixedOrDash(measured ? value : unscored, 4);
  };
  for (const frontier::StrategyTotals& t : engine.Totals()) {
    out << std::left << std::setw(8) << t.strategy << std::right << std::setw(14)
        << t.queried_points << std::setw(10) << figure(t.performance_p, true) << std::setw(10)
        << figure(t.confusion.accuracy(), scored) << std::setw(11)
        << figure(t.confusion.precision(), scored) << std::setw(9)
        << figure(t.confusion.recall(), scored) << std::fixed << std::setprecision(1)
        << std::setw(11) << t.time_ms << "\n";
  }
}

sim::World MakeCommandWorld(const std::string& world, uint64_t seed,
                            const std::string& world_size) {
  if (world_size.empty()) return sim::MakeWorld(world, seed, std::nullopt);
  const sim::WorldSize size = sim::ParseWorldSize(world_size);
  try {
    return sim::MakeWorld(world, seed, size);
  } catch (const InputError& e) {
    // The generator names its own field (width_m); the user wrote --world-size.
    throw InputError("--world-size " + world_size + ": " + e.what());
  }
}

void RejectEmptyValues(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& value : option->results()) {
      if (value.empty()) {
        throw InputError(option->get_name() + ": expected a value, got an empty string");
      }
    }
  }
}

Eigen::Vector2d ParsePoint(const std::string& text, const std::string& option) {
  static_assert(kMaxInputCoordinateM == 1e6, "the message below names the limit");
  std::istringstream in(text);
  double x = 0.0, y = 0.0;
  char comma = 0;
  if (!(in >> x >> comma >> y) || comma != ',' || !(in >> std::ws).eof() ||
      !(std::abs(x) <= kMaxInputCoordinateM) || !(std::abs(y) <= kMaxInputCoordinateM)) {
    throw InputError(option + " '" + text + "': expected X,Y in metres, each within +-1e6, e.g. " +
                     option + " 2.5,-1");
  }
  return {x, y};
}

std::string NavigationPointsCsv(const std::vector<explore::NavigationPoint>& points) {
  std::ostringstream csv;
  csv << "rank,x_m,y_m,path_cost_m,info_gain_m2,revenue,cluster,component_points\n";
  csv << std::fixed;
  for (size_t k = 0; k < points.size(); ++k) {
    const explore::NavigationPoint& p = points[k];
    csv << k + 1 << "," << std::setprecision(3) << p.position.x() << "," << p.position.y() << ","
        << p.cost_m << "," << p.info_gain_m2 << "," << p.revenue << "," << p.cluster << ","
        << p.component_size << "\n";
  }
  return csv.str();
}

exploration::ExplorationOptions ExplorationOptionsFrom(const io::ScoutConfig& config) {
  exploration::ExplorationOptions o;
  o.explore = config.explore;
  o.robot = config.robot;
  o.slam = config.slam;
  o.frontier = config.frontier;
  return o;
}

}  // namespace scout::apps
