#include "scout/report/coverage_curves.h"

#include <algorithm>
#include <map>

namespace scout::report {
namespace {

double XOf(const CoverageSample& c, bool over_path) {
  return over_path ? c.path_length_m : c.sim_time_s;
}

// Coverage of 'run' at x: the last sample at or before x (0 before the first).
double CoverageAt(const RunData& run, double x, bool over_path) {
  double value = 0.0;
  for (const CoverageSample& c : run.coverage) {
    if (XOf(c, over_path) > x) break;
    value = c.coverage;
  }
  return value;
}

std::string SummaryText(const RunData& run, const std::string& key) {
  if (!run.summary.is_object() || !run.summary.contains(key)) return "";
  const nlohmann::json& v = run.summary[key];
  return v.is_string() ? v.get<std::string>() : v.dump();
}

Series RunLine(const RunData& run, bool over_path) {
  Series s{run.name, {}, {}};
  for (const CoverageSample& c : run.coverage) {
    s.x.push_back(XOf(c, over_path));
    s.y.push_back(100.0 * c.coverage);
  }
  return s;
}

}  // namespace

Series MeanCoverage(const std::string& name, const std::vector<const RunData*>& runs,
                    bool over_path, int samples) {
  Series s{name, {}, {}};
  double x_max = 0.0;
  for (const RunData* run : runs) {
    for (const CoverageSample& c : run->coverage) x_max = std::max(x_max, XOf(c, over_path));
  }
  if (runs.empty() || samples < 2) return s;
  for (int i = 0; i < samples; ++i) {
    const double x = x_max * i / (samples - 1);
    double sum = 0.0;
    for (const RunData* run : runs) sum += CoverageAt(*run, x, over_path);
    s.x.push_back(x);
    s.y.push_back(100.0 * sum / runs.size());
  }
  return s;
}

CoverageLines CoverageLinesOf(const std::vector<RunData>& runs) {
  // Groups in order of first appearance.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const RunData*>> groups;
  for (const RunData& run : runs) {
    if (run.coverage.empty()) continue;
    const std::string policy = SummaryText(run, "goals_policy");
    // Without a policy (not an explore run) a run is its own group.
    const std::string key =
        policy.empty() ? "run " + run.name : SummaryText(run, "world") + " · " + policy;
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&run);
  }
  CoverageLines lines;
  for (const std::string& key : order) {
    const std::vector<const RunData*>& g = groups[key];
    if (g.size() == 1) {
      lines.over_path.push_back(RunLine(*g[0], true));
      lines.over_time.push_back(RunLine(*g[0], false));
      continue;
    }
    lines.grouped = true;
    const std::string name = key + " (mean of " + std::to_string(g.size()) + " runs)";
    lines.over_path.push_back(MeanCoverage(name, g, true));
    lines.over_time.push_back(MeanCoverage(name, g, false));
  }
  return lines;
}

}  // namespace scout::report
