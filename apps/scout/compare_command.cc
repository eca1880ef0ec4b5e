#include "apps/scout/compare_command.h"

#include <iostream>

#include "scout/common/atomic_file.h"
#include "scout/io/output_directory.h"
#include "scout/report/compare.h"

namespace scout::apps {

CLI::App* AddCompareCommand(CLI::App& app, CompareArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare several output directories in one table and overlaid figures");
  cmd->add_option("dirs", args->dirs, "output directories of frontier-bench, replay or explore")
      ->required();
  cmd->add_option("--out", args->out_dir, "where to write compare.html and figures/")
      ->capture_default_str();
  return cmd;
}

int RunCompare(const CompareArgs& args) {
  const std::vector<std::filesystem::path> dirs(args.dirs.begin(), args.dirs.end());
  // Read every run before creating the output directory.
  const std::vector<report::ReportFile> files = report::BuildComparison(dirs);
  std::vector<std::filesystem::path> inputs;
  for (const std::filesystem::path& dir : dirs) inputs.push_back(dir / "summary.json");
  io::OutputDirectory out(args.out_dir, io::OutputDirectory::Mode::kReplaceRun, "compare", inputs);
  for (const report::ReportFile& file : files) {
    WriteTextFileAtomically(out.Stage(file.name), file.content);
  }
  out.Commit();
  const size_t figures = files.size() - 1;
  std::cout << "compare: " << dirs.size() << (dirs.size() == 1 ? " run, " : " runs, ")
            << (out.path() / "compare.html").string() << " and " << figures
            << (figures == 1 ? " figure\n" : " figures\n");
  return 0;
}

}  // namespace scout::apps
