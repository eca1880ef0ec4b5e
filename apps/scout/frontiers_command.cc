#include "apps/scout/frontiers_command.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/scout/command_util.h"
#include "apps/scout/report_command.h"
#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/exploration/exploration_options.h"
#include "scout/explore/map_navigation_points.h"
#include "scout/frontier/local_frontiers.h"
#include "scout/frontier/stopwatch.h"
#include "scout/grid/map_io.h"
#include "scout/grid/probability_grid.h"
#include "scout/io/map_picture.h"
#include "scout/io/output_directory.h"

namespace scout::apps {
namespace {

// The map as one submap at the origin, for the map picture: free and
// occupied cells at probabilities that read back as the same states.
std::shared_ptr<const grid::ProbabilityGrid> AsGrid(const grid::OccupancyMap& map) {
  auto g = std::make_shared<grid::ProbabilityGrid>(map.limits);
  for (int y = 0; y < map.limits.height(); ++y) {
    for (int x = 0; x < map.limits.width(); ++x) {
      const grid::CellState s = map.at({x, y});
      if (s != grid::CellState::kUnknown) {
        g->SetProbability({x, y}, s == grid::CellState::kFree ? 0.1f : 0.9f);
      }
    }
  }
  return g;
}

std::string PointsCsv(const std::vector<Eigen::Vector2d>& points) {
  std::ostringstream csv;
  csv << "x_m,y_m\n" << std::fixed << std::setprecision(3);
  for (const Eigen::Vector2d& p : points) csv << p.x() << "," << p.y() << "\n";
  return csv.str();
}

}  // namespace

CLI::App* AddFrontiersCommand(CLI::App& app, FrontiersArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "frontiers",
      "Find the frontier a robot can reach on a saved occupancy map (map_server YAML, from any "
      "SLAM system) and rank its navigation points as scout explore would, without driving");
  cmd->add_option("map", args->map, "the map_server .yaml file")->required();
  cmd->add_option("--robot", args->robot, "the robot's position X,Y in metres, map frame")
      ->required();
  cmd->add_option("--out", args->out_dir, "output directory")->capture_default_str();
  cmd->add_option("--config", args->config_file,
                  "YAML options file (see config/default.yaml): explore.traversability, "
                  "explore.policy.navigation, explore.frontier_inflation_radius_m, "
                  "explore.boundary (map frame) and robot.radius_m apply");
  cmd->add_flag("--quiet", args->quiet, "print only the summary line");
  return cmd;
}

int RunFrontiers(const FrontiersArgs& args) {
  const exploration::ExplorationOptions options =
      ExplorationOptionsFrom(LoadConfigOrDefaults(args.config_file));
  exploration::CheckExplorationOptions(options);
  const Eigen::Vector2d robot = ParsePoint(args.robot, "--robot");
  const grid::OccupancyMap map = grid::ReadMapServerMap(args.map);
  const geometry::Box2d bounds = map.limits.Bounds();
  if (!map.limits.Contains(map.limits.CellContaining(robot))) {
    throw InputError("--robot " + args.robot + " lies outside the map '" + args.map +
                     "', which spans x " + FormatNumber(bounds.min.x()) + " to " +
                     FormatNumber(bounds.max.x()) + " and y " + FormatNumber(bounds.min.y()) +
                     " to " + FormatNumber(bounds.max.y()) + " m");
  }
  io::OutputDirectory out(args.out_dir, io::OutputDirectory::Mode::kReplaceRun, "frontiers",
                          {args.map, args.config_file});

  const frontier::Stopwatch watch;
  // The frontier the exploration loop's detector finds: reachable from the
  // robot with the explorer's inflation (explore.frontier_inflation_radius_m).
  const frontier::FrontierOptions frontier_options = exploration::EffectiveFrontierOptions(options);
  const frontier::LocalFrontier frontier = frontier::ExtractReachableFrontier(
      map.cells, map.limits, {robot}, frontier_options.inflation_radius_m);
  const explore::MapNavigationPoints navigation = explore::NavigationPointsOnMap(
      map, frontier.points_m, robot, {}, exploration::PlanningTraversability(options),
      options.explore.policy.navigation, options.explore.boundary);
  const double time_s = watch.ElapsedUs() * 1e-6;

  nlohmann::json summary;
  summary["map"] = args.map;
  summary["resolution_m"] = map.limits.resolution();
  summary["robot"] = {robot.x(), robot.y()};
  summary["frontier_points"] = frontier.points_m.size();
  summary["frontier_points_in_boundary"] = navigation.frontier_points_in_boundary;
  summary["frontier_inflation_radius_m"] = frontier_options.inflation_radius_m;
  summary["navigation_points"] = {
      {"count", navigation.points.size()},
      {"clusters", navigation.stats.clusters},
      {"components", navigation.stats.components},
      {"unreachable_components", navigation.stats.unreachable_components},
      {"robot_escaped", navigation.robot_escaped},
      {"robot_boxed_in", navigation.robot_boxed_in}};
  summary["time_s"] = time_s;

  io::MapOverlay overlay;
  overlay.frontier = frontier.points_m;
  for (const explore::NavigationPoint& p : navigation.points) {
    overlay.candidates.push_back(p.position);
  }
  io::WriteMapPicture({{geometry::Rigid2d(), AsGrid(map)}}, {{0.0, geometry::Rigid2d(robot, 0.0)}},
                      overlay, out.Stage("map.png"));
  WriteTextFileAtomically(out.Stage("navigation_points.csv"),
                          NavigationPointsCsv(navigation.points));
  WriteTextFileAtomically(out.Stage("frontier_points.csv"), PointsCsv(frontier.points_m));
  const std::filesystem::path summary_path = out.Stage("summary.json");
  WriteTextFileAtomically(summary_path, summary.dump(2) + "\n");
  StageRunReport(summary_path.parent_path(), out);
  out.Commit();

  std::cout << "frontiers: " << frontier.points_m.size() << " frontier points reachable from ("
            << std::fixed << std::setprecision(2) << robot.x() << ", " << robot.y() << "), "
            << navigation.points.size() << " navigation points";
  if (!navigation.points.empty()) {
    const explore::NavigationPoint& best = navigation.points.front();
    std::cout << "; best (" << best.position.x() << ", " << best.position.y() << ") m, "
              << best.cost_m << " m of path";
  }
  if (navigation.robot_boxed_in) {
    std::cout << "; the robot's disc fits nowhere near (" << robot.x() << ", " << robot.y()
              << "): is it inside a wall or unknown space?";
  }
  std::cout << "\n";
  if (!args.quiet) {
    std::cout << "outputs: " << (out.path() / "summary.json").string()
              << ", navigation_points.csv, frontier_points.csv, map.png, report.html\n";
  }
  return 0;
}

}  // namespace scout::apps
