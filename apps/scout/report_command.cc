#include "apps/scout/report_command.h"

#include <iostream>

#include "scout/common/atomic_file.h"
#include "scout/report/html_report.h"

namespace scout::apps {

CLI::App* AddReportCommand(CLI::App& app, ReportArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Draw the figures of an output directory and write a self-contained report.html into it");
  cmd->add_option("dir", args->dir, "output directory of frontier-bench, replay or explore")
      ->required();
  return cmd;
}

void StageRunReport(const std::filesystem::path& inputs, io::OutputDirectory& out) {
  const std::string name = report::RunName(out.path());
  for (const report::ReportFile& file : report::BuildRunReport(inputs, name, out.path())) {
    WriteTextFileAtomically(out.Stage(file.name), file.content);
  }
}

int RunReport(const ReportArgs& args) {
  // Read everything before creating anything, so a bad directory is left alone.
  const std::vector<report::ReportFile> files = report::BuildRunReport(args.dir);
  io::OutputDirectory out(args.dir, io::OutputDirectory::Mode::kAddFiles);
  // The report is its page and figures: figures an earlier report drew from
  // files since removed go with it.
  out.ReplaceEarlier("report.html");
  out.ReplaceEarlier("figures/");
  for (const report::ReportFile& file : files) {
    WriteTextFileAtomically(out.Stage(file.name), file.content);
  }
  out.Commit();
  const size_t figures = files.size() - 1;
  std::cout << "report: " << (out.path() / "report.html").string() << " and " << figures
            << (figures == 1 ? " figure in " : " figures in ") << (out.path() / "figures").string()
            << "\n";
  return 0;
}

}  // namespace scout::apps
