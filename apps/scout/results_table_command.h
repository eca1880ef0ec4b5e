#ifndef SCOUT_APPS_SCOUT_RESULTS_TABLE_COMMAND_H_
#define SCOUT_APPS_SCOUT_RESULTS_TABLE_COMMAND_H_

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace scout::apps {

struct ResultsTableArgs {
  std::string kind;
  std::vector<std::string> dirs;
  std::string figures_dir;  // empty: no sweep figures
};

// Registers `scout results-table --kind replay|bench|explore DIR...` on 'app'.
CLI::App* AddResultsTableCommand(CLI::App& app, ResultsTableArgs* args);

// Prints the Markdown tables of report::ResultsTables to stdout (the results
// driver pastes them into docs/RESULTS.md). Throws InputError on a bad kind or
// a directory without summary.json. With --figures DIR, also writes the sweep
// figures (report::SweepFigures) of the runs as DIR/<name>.svg.
int RunResultsTable(const ResultsTableArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_RESULTS_TABLE_COMMAND_H_
