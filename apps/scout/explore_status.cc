#include "apps/scout/explore_status.h"

#include <Eigen/Core>
#include <exception>
#include <numbers>
#include <system_error>
#include <utility>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"

namespace scout::apps {
namespace {

nlohmann::ordered_json PoseJson(const geometry::Rigid2d& pose) {
  return {
      {"x_m", pose.x()}, {"y_m", pose.y()}, {"theta_deg", pose.theta() * 180.0 / std::numbers::pi}};
}

nlohmann::ordered_json PointJson(const Eigen::Vector2d& p) {
  return {{"x_m", p.x()}, {"y_m", p.y()}};
}

}  // namespace

ExploreStatusFile::ExploreStatusFile(std::filesystem::path path, nlohmann::ordered_json run)
    : path_(std::move(path)), run_(std::move(run)) {
  CheckPath(path_);
  Write(ToJson(run_, std::nullopt, 0.0));
}

void ExploreStatusFile::CheckPath(const std::filesystem::path& path) {
  std::error_code error;
  if (path.empty() || std::filesystem::is_directory(path, error)) {
    throw InputError("--status '" + path.string() + "': expected a file name, not a directory");
  }
  const std::filesystem::path dir =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(dir, error)) {
    throw InputError("--status " + path.string() + ": directory " + dir.string() +
                     " does not exist");
  }
}

ExploreStatusFile::~ExploreStatusFile() {
  if (finished_) return;
  try {
    nlohmann::ordered_json status = ToJson(run_, last_, last_wall_time_s_);
    status["running"] = false;
    status["error"] = "the run ended without writing its outputs (see its error message)";
    Write(status);
  } catch (const std::exception&) {
    // A destructor must not throw; the run's own error is what the user sees.
  }
}

void ExploreStatusFile::Update(const exploration::ExplorationProgress& progress,
                               double wall_time_s) {
  last_ = progress;
  last_wall_time_s_ = wall_time_s;
  Write(ToJson(run_, last_, wall_time_s));
}

void ExploreStatusFile::Finish(exploration::Termination terminated,
                               const std::filesystem::path& summary) {
  nlohmann::ordered_json status = ToJson(run_, last_, last_wall_time_s_);
  status["running"] = false;
  status["terminated"] = std::string(exploration::ToString(terminated));
  status["summary"] = summary.string();
  Write(status);
  finished_ = true;
}

nlohmann::ordered_json ExploreStatusFile::ToJson(
    const nlohmann::ordered_json& run,
    const std::optional<exploration::ExplorationProgress>& progress, double wall_time_s) {
  nlohmann::ordered_json status = run;
  status["running"] = true;
  status["terminated"] = nullptr;
  status["summary"] = nullptr;
  if (!progress) {
    status["state"] = "starting";
    return status;
  }
  const exploration::ExplorationProgress& p = *progress;
  status["state"] = p.finished ? "ended" : std::string(explore::ToString(p.state));
  status["sim_time_s"] = p.sim_time_s;
  status["wall_time_s"] = wall_time_s;
  status["coverage"] = p.coverage;
  status["path_length_m"] = p.path_length_m;
  status["collisions"] = p.collisions;
  status["pose"] = PoseJson(p.estimated_pose);
  status["true_pose"] = PoseJson(p.true_pose);
  status["goal"] = p.goal ? PointJson(*p.goal) : nlohmann::ordered_json(nullptr);
  status["frontier_points"] = p.frontier_points;
  status["navigation_points"] = p.navigation_points;
  status["goals"] = {{"issued", p.counters.goals_issued},
                     {"reached", p.counters.goals_reached},
                     {"failed", p.counters.goals_failed},
                     {"no_plan", p.counters.goals_unreachable},
                     {"superseded", p.counters.goals_superseded},
                     // A robot that struggles shows here before goals fail.
                     {"recoveries", p.counters.recoveries},
                     {"retraces", p.counters.retraces},
                     {"last_resorts", p.counters.last_resorts},
                     {"guard_stops", p.counters.guard_stops}};
  nlohmann::ordered_json blacklisted = nlohmann::ordered_json::array();
  for (const Eigen::Vector2d& b : p.blacklisted_goals) blacklisted.push_back(PointJson(b));
  status["blacklisted_goals"] = blacklisted;
  return status;
}

void ExploreStatusFile::Write(const nlohmann::ordered_json& status) const {
  WriteTextFileAtomically(path_, status.dump(2) + "\n");
}

}  // namespace scout::apps
