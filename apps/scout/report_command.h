#ifndef SCOUT_APPS_SCOUT_REPORT_COMMAND_H_
#define SCOUT_APPS_SCOUT_REPORT_COMMAND_H_

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "scout/io/output_directory.h"

namespace scout::apps {

struct ReportArgs {
  std::string dir;
};

// Registers `scout report DIR` on 'app'.
CLI::App* AddReportCommand(CLI::App& app, ReportArgs* args);

// Writes DIR/report.html and DIR/figures/*.svg from the outputs in DIR, all
// moved into place together. Returns the exit code; throws InputError when
// DIR holds no readable Scout outputs.
int RunReport(const ReportArgs& args);

// Stages report.html and figures/*.svg into 'out', drawn from the outputs in
// 'inputs' (which may be 'out's staging directory, for commands that report
// on the run they are writing). The run is titled after 'out's directory.
void StageRunReport(const std::filesystem::path& inputs, io::OutputDirectory& out);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_REPORT_COMMAND_H_
