#ifndef SCOUT_REPORT_RESULTS_TABLES_H_
#define SCOUT_REPORT_RESULTS_TABLES_H_

#include <filesystem>
#include <string>
#include <vector>

namespace scout::report {

// What kind of output directories a results table is drawn from.
enum class TableKind {
  kReplay,   // scout replay: SLAM accuracy and cost, then per-strategy frontier figures
  kBench,    // scout frontier-bench: the stream, then per-strategy frontier figures
  kExplore,  // scout explore: one row per run, then means per world and goal policy
};

// Parses "replay", "bench" or "explore". Throws InputError naming 'text'.
TableKind ParseTableKind(const std::string& text);

// Returns the Markdown for docs/RESULTS.md drawn from the summary.json (and
// frontier.csv / coverage.csv when present) of every directory of 'dirs', in
// order: first a ```sh block with the command of each run, read from its
// command.txt (written by the results driver, since a summary does not hold
// the command line; a run without one is listed as "(command not recorded)"),
// then the tables. Missing values print as "—". Throws InputError naming the
// directory when it has no summary.json or an unreadable one, and when 'dirs'
// is empty.
std::string ResultsTables(TableKind kind, const std::vector<std::filesystem::path>& dirs);

}  // namespace scout::report

#endif  // SCOUT_REPORT_RESULTS_TABLES_H_
