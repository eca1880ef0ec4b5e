#include "scout/report/html_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scout/report/strategy_stats.h"
#include "scout/report/svg_plot.h"

namespace scout::report {
namespace {

const std::vector<std::string> kOptionKeys = {"config", "options"};

std::string StrategyTable(const std::vector<StrategyStats>& stats) {
  std::vector<std::vector<std::string>> rows;
  for (const StrategyStats& s : stats) {
    rows.push_back({s.strategy, FormatNumber("%.2f", 100.0 * s.performance_p),
                    FormatNumber("%.3f", 100.0 * s.accuracy),
                    FormatNumber("%.3f", 100.0 * s.precision),
                    FormatNumber("%.3f", 100.0 * s.recall),
                    FormatNumber("%.3f", s.time_per_round_ms), std::to_string(s.queried_points),
                    s.rounds > 0 ? std::to_string(s.queried_points / s.rounds) : "–"});
  }
  return HtmlTable({"strategy", "P (%)", "accuracy (%)", "precision (%)", "recall (%)",
                    "time per round (ms)", "queried points", "queried points per round"},
                   rows);
}

std::string KeyValueTable(const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& [key, value] : pairs) rows.push_back({key, value});
  return HtmlTable({"key", "value"}, rows);
}

}  // namespace

std::string RenderRunReport(const RunData& run, const std::vector<Figure>& figures) {
  std::ostringstream body;
  body << "<p>Scout output directory <code>" << EscapeXml(run.dir.string()) << "</code>.</p>\n";
  const std::vector<StrategyStats> stats = StrategyStatsOf(run);
  if (!stats.empty()) {
    body << "<h2 id=\"strategies\">Frontier update strategies</h2>\n"
         << "<p>P = 1 − Σ queried points / Σ queried points of dfd over all optimisation rounds; "
            "accuracy, precision and recall compare each strategy's answers with full "
            "recomputation over all local frontier points after every round.</p>\n"
         << StrategyTable(stats);
  }
  if (!run.pictures.empty()) {
    body << "<h2 id=\"maps\">Maps</h2>\n";
    for (const std::filesystem::path& picture : run.pictures) {
      const std::string name = picture.filename().string();
      body << "<figure><img class=\"map\" alt=\"" << EscapeXml(name) << "\" src=\""
           << PngDataUri(picture) << "\"><figcaption>" << EscapeXml(name)
           << "</figcaption></figure>\n";
    }
  }
  if (!run.navigation_points.empty()) {
    // A long list helps nobody: the best ones are what an explorer would try.
    constexpr size_t kShown = 20;
    const size_t n = run.navigation_points.size();
    body << "<h2 id=\"navigation\">Navigation points</h2>\n<p>Where an explorer would go next "
            "from the last pose, best revenue (info multiplier × unknown area − path length) first"
         << (n > kShown ? "; the first " + std::to_string(kShown) + " of " + std::to_string(n) : "")
         << " (navigation_points.csv).</p>\n";
    std::vector<std::vector<std::string>> rows;
    for (size_t k = 0; k < std::min(n, kShown); ++k) {
      const NavigationPointRow& p = run.navigation_points[k];
      rows.push_back({std::to_string(p.rank), FormatNumber("%.2f", p.x_m),
                      FormatNumber("%.2f", p.y_m), FormatNumber("%.2f", p.path_cost_m),
                      FormatNumber("%.2f", p.info_gain_m2), FormatNumber("%.2f", p.revenue)});
    }
    body << HtmlTable({"rank", "x (m)", "y (m)", "path (m)", "unknown area (m²)", "revenue"}, rows);
  }
  if (!run.goals.empty()) {
    // How the goals ended, then the ones a user looks into: those the robot
    // neither reached nor saw on the way.
    std::vector<std::pair<std::string, int>> counts;
    for (const GoalRow& g : run.goals) {
      auto it = std::find_if(counts.begin(), counts.end(),
                             [&](const auto& c) { return c.first == g.outcome; });
      if (it == counts.end()) {
        counts.push_back({g.outcome, 0});
        it = counts.end() - 1;
      }
      ++it->second;
    }
    std::vector<std::vector<std::string>> count_rows;
    for (const auto& [outcome, n] : counts) count_rows.push_back({outcome, std::to_string(n)});
    constexpr size_t kShown = 20;
    std::vector<std::vector<std::string>> rows;
    size_t others = 0;
    for (const GoalRow& g : run.goals) {
      if (g.outcome == "reached" || g.outcome == "seen") continue;
      if (++others > kShown) continue;
      rows.push_back({FormatNumber("%.2f", g.issued_s), FormatNumber("%.2f", g.goal_x_m),
                      FormatNumber("%.2f", g.goal_y_m),
                      std::isfinite(g.score) ? FormatNumber("%.2f", g.score) : "–",
                      FormatNumber("%.2f", g.path_m), g.outcome,
                      g.reachable_in_truth ? "yes" : "no"});
    }
    body << "<h2 id=\"goals\">Goals</h2>\n<p>" << run.goals.size()
         << " goals issued, by how they ended (goals.csv).</p>\n"
         << HtmlTable({"outcome", "goals"}, count_rows);
    if (!rows.empty()) {
      body << "<p>Goals neither reached nor seen on the way"
           << (others > kShown
                   ? ", the first " + std::to_string(kShown) + " of " + std::to_string(others)
                   : "")
           << " (true-world frame):</p>\n"
           << HtmlTable({"issued (s)", "x (m)", "y (m)", "score", "path (m)", "outcome",
                         "reachable in truth"},
                        rows);
    }
  }
  if (!figures.empty()) {
    body << "<h2 id=\"figures\">Figures</h2>\n";
    for (const Figure& f : figures) {
      body << "<figure id=\"fig-" << EscapeXml(f.name) << "\">\n"
           << f.svg << "<figcaption>" << EscapeXml(f.caption) << " (figures/" << EscapeXml(f.name)
           << ".svg)</figcaption></figure>\n";
    }
  }
  if (run.summary.is_object()) {
    // The strategies have their own table; the options theirs.
    std::vector<std::string> skip = kOptionKeys;
    if (!stats.empty()) skip.push_back("frontier");
    body << "<h2 id=\"summary\">Summary</h2>\n" << KeyValueTable(FlattenJson(run.summary, skip));
    if (!stats.empty() && run.summary.contains("frontier")) {
      const auto rest = FlattenJson(run.summary["frontier"], {"strategies"});
      if (!rest.empty()) body << KeyValueTable(rest);
    }
    for (const std::string& key : kOptionKeys) {
      if (!run.summary.contains(key)) continue;
      body << "<h2 id=\"options\">Options used</h2>\n"
           << KeyValueTable(FlattenJson(nlohmann::json{{key, run.summary[key]}}));
    }
  }
  return HtmlPage("Scout report: " + run.name, body.str());
}

std::vector<ReportFile> BuildRunReport(const std::filesystem::path& dir, const std::string& name,
                                       const std::filesystem::path& shown_dir) {
  RunData run = ReadRun(dir, name);
  if (!shown_dir.empty()) run.dir = shown_dir;
  const std::vector<Figure> figures = RunFigures(run);
  std::vector<ReportFile> files;
  for (const Figure& f : figures) files.push_back({"figures/" + f.name + ".svg", f.svg});
  files.push_back({"report.html", RenderRunReport(run, figures)});
  return files;
}

}  // namespace scout::report
