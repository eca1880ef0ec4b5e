#ifndef SCOUT_APPS_SCOUT_COMPARE_COMMAND_H_
#define SCOUT_APPS_SCOUT_COMPARE_COMMAND_H_

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace scout::apps {

struct CompareArgs {
  std::vector<std::string> dirs;
  std::string out_dir = "out/compare";
};

// Registers `scout compare DIR... --out OUT` on 'app'.
CLI::App* AddCompareCommand(CLI::App& app, CompareArgs* args);

// Writes OUT/compare.html and OUT/figures/*.svg comparing the runs in the
// directories, all moved into place together. Returns the exit code; throws
// InputError when a directory holds no readable Scout outputs.
int RunCompare(const CompareArgs& args);

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_COMPARE_COMMAND_H_
