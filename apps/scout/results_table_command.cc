#include "apps/scout/results_table_command.h"

#include <filesystem>
#include <iostream>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/report/results_tables.h"
#include "scout/report/sweep_figures.h"

namespace scout::apps {

CLI::App* AddResultsTableCommand(CLI::App& app, ResultsTableArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "results-table",
      "Print Markdown tables (with the command of each run) from the summary.json of output "
      "directories");
  cmd->add_option("--kind", args->kind, "replay, bench (frontier-bench) or explore")->required();
  cmd->add_option("dirs", args->dirs, "output directories, each with summary.json")->required();
  cmd->add_option("--figures", args->figures_dir,
                  "also write the ε and world-size sweep figures of the runs into this directory");
  return cmd;
}

int RunResultsTable(const ResultsTableArgs& args) {
  // Parse the kind first so a typo is reported before any directory is read.
  const report::TableKind kind = report::ParseTableKind(args.kind);
  const std::vector<std::filesystem::path> dirs(args.dirs.begin(), args.dirs.end());
  const std::string markdown = report::ResultsTables(kind, dirs);
  if (!args.figures_dir.empty()) {
    std::vector<report::RunData> runs;
    for (const std::filesystem::path& dir : dirs) runs.push_back(report::ReadRun(dir));
    std::error_code ec;
    std::filesystem::create_directories(args.figures_dir, ec);
    if (ec || !std::filesystem::is_directory(args.figures_dir)) {
      throw InputError("--figures '" + args.figures_dir + "': cannot create the directory (" +
                       (ec ? ec.message() : std::string("a file of that name exists")) + ")");
    }
    for (const report::Figure& figure : report::SweepFigures(runs)) {
      WriteTextFileAtomically(std::filesystem::path(args.figures_dir) / (figure.name + ".svg"),
                              figure.svg);
    }
  }
  std::cout << markdown;
  return 0;
}

}  // namespace scout::apps
