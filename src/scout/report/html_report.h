#ifndef SCOUT_REPORT_HTML_REPORT_H_
#define SCOUT_REPORT_HTML_REPORT_H_

#include <filesystem>
#include <string>
#include <vector>

#include "scout/report/html_page.h"
#include "scout/report/run_data.h"
#include "scout/report/run_figures.h"

namespace scout::report {

// Returns report.html of 'run': its map pictures as data URIs, 'figures'
// inline, the per-strategy table (P, accuracy, precision, recall, time per
// round, queried points), summary.json flattened into a table, and the
// options the run used when the summary records them ("config" or "options").
// The page loads nothing from anywhere else.
std::string RenderRunReport(const RunData& run, const std::vector<Figure>& figures);

// Reads the outputs in 'dir' and returns "report.html" and one
// "figures/<name>.svg" per figure, for the caller to write (atomically).
// 'name' is the run's title (default: the directory's name); the page names
// 'shown_dir' as the run's directory (default: 'dir'; commands that report
// on the run they are staging pass where it will be). Throws InputError like
// ReadRun.
std::vector<ReportFile> BuildRunReport(const std::filesystem::path& dir,
                                       const std::string& name = "",
                                       const std::filesystem::path& shown_dir = {});

}  // namespace scout::report

#endif  // SCOUT_REPORT_HTML_REPORT_H_
