#include "apps/scout/frontier_bench_command.h"

#include <unistd.h>

#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/scout/command_util.h"
#include "apps/scout/interrupt.h"
#include "apps/scout/report_command.h"
#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/frontier/frontier_engine.h"
#include "scout/frontier/stopwatch.h"
#include "scout/io/config.h"
#include "scout/io/frontier_report.h"
#include "scout/io/output_directory.h"
#include "scout/sim/make_world.h"
#include "scout/synthetic/synthetic_stream.h"

namespace scout::apps {
CLI::App* AddFrontierBenchCommand(CLI::App& app, FrontierBenchArgs* args) {
  CLI::App* cmd = app.add_subcommand(
      "frontier-bench",
      "Run every frontier update strategy in lockstep on a synthetic SLAM event stream and "
      "score them against full recomputation");
  cmd->add_option("--world", args->world, "office, museum, or a ROS map_server .yaml file")
      ->capture_default_str();
  cmd->add_option("--world-size", args->world_size,
                  "outer extent of a generated world, W or WxH metres, at most 500 (default: the "
                  "generator's)");
  cmd->add_option("--seed", args->seed, "seed of the world, trajectory, sensor noise and drift")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->add_option("--out", args->out_dir, "output directory")->capture_default_str();
  cmd->add_option("--config", args->config_file, "YAML options file (see config/default.yaml)");
  cmd->add_option("--epsilon", args->epsilon_m,
                  "bfs/direct threshold in metres (overrides frontier.epsilon_m)")
      ->check(PositiveFiniteNumber("metres"));
  cmd->add_option("--strategies", args->strategies, "comma-separated strategies to run")
      ->capture_default_str();
  cmd->add_option("--picture-strategy", args->picture_strategy,
                  "strategy whose frontier and last re-queried submaps frontiers.png shows "
                  "(default: exact if it runs, else the first of --strategies)");
  cmd->add_flag("--no-reference", args->no_reference,
                "do not run full recomputation (which dominates the run time in large worlds); "
                "accuracy, precision and recall are then not measured");
  cmd->add_flag("--quiet", args->quiet, "print only the final summary line");
  return cmd;
}

int RunFrontierBench(const FrontierBenchArgs& args) {
  const frontier::Stopwatch wall;
  io::ScoutConfig config = LoadConfigOrDefaults(args.config_file);
  if (args.epsilon_m) config.frontier.epsilon_m = *args.epsilon_m;
  const std::vector<std::string> strategies = SplitList(args.strategies, "--strategies");
  // Validates options and names before any long work or any output.
  frontier::FrontierEngine engine(config.frontier, strategies, /*evaluate=*/!args.no_reference);
  const std::string picture_strategy = PictureStrategy(args.picture_strategy, strategies, engine);
  const sim::World world = MakeCommandWorld(args.world, args.seed, args.world_size);
  io::OutputDirectory out(args.out_dir, io::OutputDirectory::Mode::kReplaceRun, "frontier-bench",
                          {args.world, args.config_file});

  const bool terminal = !args.quiet && ::isatty(STDERR_FILENO);
  // By wall time, not by event count: one optimisation round of full
  // recomputation can take seconds in a large world or with tiny submaps.
  // A terminal's line is rewritten in place; a log gets a plain line now and
  // then, so a long run there shows it is alive too.
  const double progress_interval_s = terminal ? 0.5 : 30.0;
  double last_progress_s = 0.0;  // 0 until the first line
  synthetic::SyntheticEventStream stream(world, config.synthetic, args.seed);
  const synthetic::StreamStats stats = stream.Run([&](const events::SubmapEvent& event) {
    engine.Apply(event);
    // After the event: a round can take seconds, and the next event's check
    // would come only after its own. No line is printed after Ctrl-C.
    ThrowIfInterrupted();
    const double now_s = wall.ElapsedUs() * 1e-6;
    if (!args.quiet && now_s - last_progress_s >= progress_interval_s) {
      last_progress_s = now_s;
      std::cerr << (terminal ? "\r" : "") << "frontier-bench: " << std::fixed
                << std::setprecision(0) << now_s << " s, " << engine.catalog().size()
                << " submaps, " << engine.optimizations() << " optimisations, "
                << engine.catalog().total_points() << " local frontier points"
                << (terminal ? "" : "\n") << std::flush;
    }
  });
  if (terminal && last_progress_s > 0.0) std::cerr << "\n";
  engine.Flush();

  nlohmann::json summary;
  summary["world"] = args.world;
  summary["seed"] = args.seed;
  if (!args.world_size.empty()) {
    const sim::WorldSize world_size = sim::ParseWorldSize(args.world_size);
    summary["world_size_m"] = {world_size.width_m, world_size.height_m};
  }
  summary["submaps"] = engine.catalog().size();
  summary["optimizations"] = engine.optimizations();
  summary["local_frontier_points"] = engine.catalog().total_points();
  summary["global_frontier_points"] =
      engine.GlobalFrontier(args.no_reference ? picture_strategy : "full").size();
  summary["reference"] = !args.no_reference;
  summary["scans"] = stats.scans;
  summary["loop_closures"] = stats.loop_closures;
  summary["trajectory_length_m"] = stats.trajectory_length_m;
  summary["grid_changes"] = engine.grid_changes();
  summary["grid_change_events"] = engine.grid_change_events();
  summary["epsilon_m"] = config.frontier.epsilon_m;
  // Shared by all strategies: answer maps and local frontier extraction per grid change.
  summary["submap_update_ms"] = engine.catalog_time_ms();
  summary["frontier"] = io::FrontierSummary(engine);
  summary["wall_time_s"] = wall.ElapsedUs() * 1e-6;

  io::WriteFrontierCsv(engine, out.Stage("frontier.csv"));
  io::WriteFrontierPicture(engine, picture_strategy, out.Stage("frontiers.png"));
  const std::filesystem::path summary_path = out.Stage("summary.json");
  WriteTextFileAtomically(summary_path, summary.dump(2) + "\n");
  // The report reads the staged outputs and is committed together with them.
  StageRunReport(summary_path.parent_path(), out);
  out.Commit();

  std::cout << "frontier-bench: world " << args.world << ", seed " << args.seed << ": "
            << engine.catalog().size() << " submaps, " << engine.optimizations()
            << " optimisations, " << engine.catalog().total_points() << " local frontier points\n";
  PrintStrategyTable(engine, std::cout);
  std::cout << "outputs: " << (out.path() / "summary.json").string() << ", frontier.csv, "
            << "frontiers.png, report.html, figures/\n";
  return 0;
}

}  // namespace scout::apps
