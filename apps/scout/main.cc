// scout: autonomous exploration with submap graph SLAM and reachable frontiers.
// Exit codes: 0 success, 2 bad input (the message names the file/key/value),
// 1 an unexpected internal failure, 128 + N when ended by signal N (SIGINT,
// SIGTERM) with nothing written.

#include <malloc.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "apps/scout/build_commit.h"
#include "apps/scout/command_util.h"
#include "apps/scout/compare_command.h"
#include "apps/scout/explore_command.h"
#include "apps/scout/frontier_bench_command.h"
#include "apps/scout/frontiers_command.h"
#include "apps/scout/interrupt.h"
#include "apps/scout/replay_command.h"
#include "apps/scout/report_command.h"
#include "apps/scout/results_table_command.h"
#include "scout/common/error.h"

namespace {

// The goal manager allocates and frees map-sized arrays (the path distance
// fields) many times a second. glibc serves large blocks with fresh mmap
// pages and hands freed heap tops back to the kernel, so every one is faulted
// in and zeroed again, work that grows with the map. Measured with `scout
// explore --world museum --seed 1`, two builds side by side, same outputs:
// blocks up to 32 MiB from the heap and freed memory kept (the threshold's
// cap) took the run to 2000 s of simulated time from 397 to 214 s of wall
// time (kernel 97 -> 2 s; 2026-12-03). Beyond 32 MiB, late in a large map,
// blocks still came from mmap: no mmap at all (glibc falls back to it only
// when the heap cannot grow) took the run to 3600 s from 890 to 817 s, beside
// each other and a third job (kernel 42.7 -> 4.9 s, peak 1075 -> 1054 MB;
// 2026-12-04).
void KeepFreedMemoryForReuse() {
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
}

}  // namespace

int main(int argc, char** argv) {
  KeepFreedMemoryForReuse();
  CLI::App app{"Scout: reachable-frontier exploration on submap graph SLAM"};
  app.require_subcommand(1);
  // The commit in brackets is what scripts/results records as a run's build.
  app.set_version_flag("--version",
                       std::string("scout 0.1.0 (") + scout::apps::BuildCommit() + ")");
  scout::apps::FrontierBenchArgs bench_args;
  CLI::App* bench = scout::apps::AddFrontierBenchCommand(app, &bench_args);
  scout::apps::ReportArgs report_args;
  CLI::App* report = scout::apps::AddReportCommand(app, &report_args);
  scout::apps::CompareArgs compare_args;
  CLI::App* compare = scout::apps::AddCompareCommand(app, &compare_args);
  scout::apps::ReplayArgs replay_args;
  CLI::App* replay = scout::apps::AddReplayCommand(app, &replay_args);
  scout::apps::ExploreArgs explore_args;
  CLI::App* explore = scout::apps::AddExploreCommand(app, &explore_args);
  scout::apps::FrontiersArgs frontiers_args;
  CLI::App* frontiers = scout::apps::AddFrontiersCommand(app, &frontiers_args);
  scout::apps::ResultsTableArgs table_args;
  CLI::App* table = scout::apps::AddResultsTableCommand(app, &table_args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "scout: error: " << e.what() << " (see 'scout --help')\n";
    return 2;
  }
  scout::apps::InstallInterruptHandler();
  try {
    for (const CLI::App* command : app.get_subcommands()) {
      scout::apps::RejectEmptyValues(*command);
    }
    if (bench->parsed()) return scout::apps::RunFrontierBench(bench_args);
    if (report->parsed()) return scout::apps::RunReport(report_args);
    if (compare->parsed()) return scout::apps::RunCompare(compare_args);
    if (replay->parsed()) return scout::apps::RunReplay(replay_args);
    if (explore->parsed()) return scout::apps::RunExplore(explore_args);
    if (frontiers->parsed()) return scout::apps::RunFrontiers(frontiers_args);
    if (table->parsed()) return scout::apps::RunResultsTable(table_args);
  } catch (const scout::InputError& e) {
    std::cerr << "scout: error: " << e.what() << "\n";
    return 2;
  } catch (const scout::apps::Interrupted& e) {
    std::cerr << "scout: " << e.what() << "; nothing written\n";
    return 128 + e.signal_number();
  } catch (const std::exception& e) {
    std::cerr << "scout: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
