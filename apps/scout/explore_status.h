#ifndef SCOUT_APPS_SCOUT_EXPLORE_STATUS_H_
#define SCOUT_APPS_SCOUT_EXPLORE_STATUS_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "scout/exploration/exploration_loop.h"

namespace scout::apps {

// The live status of `scout explore --status FILE`: one JSON object that a
// monitor (watch, a dashboard, a supervising script) can read at any moment.
// It is rewritten through a temporary file and a rename, so a reader never
// sees half of it: at the start, about every 5 s of simulated time, when the
// run has ended and measured its map, and once more when its outputs are
// written ("running": false, "terminated" and "summary" set).
class ExploreStatusFile {
 public:
  // Throws InputError when 'path' is a directory or its directory does not
  // exist: checked before a run creates anything.
  static void CheckPath(const std::filesystem::path& path);
  // 'run' names the run (command, world, seed, ...); it opens every status.
  // Writes the first status. Throws InputError as CheckPath, or when the
  // directory is not writable.
  ExploreStatusFile(std::filesystem::path path, nlohmann::ordered_json run);
  // A run that ended with an error before Finish() says so: "running" false,
  // "terminated" null and an "error" (never throws).
  ~ExploreStatusFile();
  ExploreStatusFile(const ExploreStatusFile&) = delete;
  ExploreStatusFile& operator=(const ExploreStatusFile&) = delete;

  void Update(const exploration::ExplorationProgress& progress, double wall_time_s);
  // The run's outputs are written: the last progress with its termination.
  void Finish(exploration::Termination terminated, const std::filesystem::path& summary);

 private:
  // One status: 'run', then "running": true and the progress (none yet:
  // "state": "starting").
  static nlohmann::ordered_json ToJson(
      const nlohmann::ordered_json& run,
      const std::optional<exploration::ExplorationProgress>& progress, double wall_time_s);
  void Write(const nlohmann::ordered_json& status) const;

  std::filesystem::path path_;
  nlohmann::ordered_json run_;
  std::optional<exploration::ExplorationProgress> last_;
  double last_wall_time_s_ = 0.0;
  bool finished_ = false;
};

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_EXPLORE_STATUS_H_
