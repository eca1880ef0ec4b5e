#include "scout/report/html_report.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/report/compare.h"
#include "scout/report/test_runs.h"
#include "scout/report/xml_check.h"

namespace scout::report {
namespace {

const ReportFile* FindFile(const std::vector<ReportFile>& files, const std::string& name) {
  for (const ReportFile& f : files) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// Nothing the page loads may come from elsewhere: every src/href is a data
// URI or a fragment, and there are no scripts.
// Returns the number of src/href references seen (all checked).
int ExpectSelfContained(const std::string& html) {
  // The SVG namespace is a name, not a resource.
  std::string rest = html;
  for (size_t p = rest.find("http://www.w3.org/2000/svg"); p != std::string::npos;
       p = rest.find("http://www.w3.org/2000/svg")) {
    rest.erase(p, 26);
  }
  EXPECT_EQ(rest.find("http://"), std::string::npos);
  // A plain scan for src="..." and href="..." (std::regex trips g++ 12's
  // -Wmaybe-uninitialized in sanitizer builds).
  int references = 0;
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (size_t p = html.find(attribute); p != std::string::npos; p = html.find(attribute, p + 1)) {
      const size_t begin = p + attribute.size();
      const std::string target = html.substr(begin, html.find('"', begin) - begin);
      EXPECT_TRUE(target.rfind("data:", 0) == 0 || target.rfind("#", 0) == 0) << target;
      ++references;
    }
  }

  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  return references;
}

TEST(HtmlReport, RunReportIsSelfContainedAndHoldsTheTables) {
  const std::vector<ReportFile> files = BuildRunReport(testing::WriteFrontierRun("report"));
  ASSERT_EQ(files.size(), 5u);
  EXPECT_EQ(files[0].name, "figures/local_points.svg");
  const ReportFile* page = FindFile(files, "report.html");
  ASSERT_NE(page, nullptr);
  const std::string& html = page->content;
  EXPECT_GT(ExpectSelfContained(html), 0);  // the embedded map at least
  // The map, embedded.
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);
  // Per-strategy values: direct's P, accuracy, recall, time per round, points.
  EXPECT_NE(html.find("<td>direct</td><td class=\"num\">88.89</td><td class=\"num\">99.722</td>"
                      "<td class=\"num\">100.000</td><td class=\"num\">99.167</td>"
                      "<td class=\"num\">0.135</td><td class=\"num\">40</td>"),
            std::string::npos)
      << html;
  // Summary and options, flattened.
  EXPECT_NE(html.find("<td>world</td><td>office</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>epsilon_m</td><td class=\"num\">0.1</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>config.frontier.inflation_radius_m</td><td class=\"num\">0.3</td>"),
            std::string::npos);
  // All four figures inline, each a well-formed SVG.
  size_t at = 0;
  for (int i = 0; i < 4; ++i) {
    const size_t begin = html.find("<svg", at);
    ASSERT_NE(begin, std::string::npos) << i;
    const size_t end = html.find("</svg>", begin) + 6;
    EXPECT_EQ(testing::CheckXml(html.substr(begin, end - begin)).error, "") << i;
    at = end;
  }
  EXPECT_EQ(html.find("<svg", at), std::string::npos);
}

TEST(HtmlReport, ExploreRunWithoutFrontierData) {
  const std::vector<ReportFile> files = BuildRunReport(testing::WriteExploreRun("explore", 1.0));
  const ReportFile* page = FindFile(files, "report.html");
  ASSERT_NE(page, nullptr);
  ExpectSelfContained(page->content);
  EXPECT_NE(page->content.find("<td>goals_policy</td><td>nearest</td>"), std::string::npos);
  EXPECT_EQ(page->content.find("Frontier update strategies"), std::string::npos);
  EXPECT_NE(FindFile(files, "figures/coverage_path.svg"), nullptr);
}

// A replay's navigation_points.csv: the best twenty, in rank order.
TEST(HtmlReport, ReplayRunListsTheBestNavigationPoints) {
  const std::filesystem::path dir = testing::WriteFrontierRun("navigation");
  std::string csv = "rank,x_m,y_m,path_cost_m,info_gain_m2,revenue,cluster,component_points\n";
  for (int k = 1; k <= 25; ++k) {
    csv += std::to_string(k) + "," + std::to_string(k) + ".500,-2.250,3.000,1.000," +
           std::to_string(30 - k) + ".000,0,10\n";
  }
  WriteTextFileAtomically(dir / "navigation_points.csv", csv);
  const std::vector<ReportFile> files = BuildRunReport(dir);
  const std::string& html = FindFile(files, "report.html")->content;
  ExpectSelfContained(html);
  EXPECT_NE(html.find("Navigation points"), std::string::npos);
  EXPECT_NE(html.find("the first 20 of 25"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">1</td><td class=\"num\">1.50</td>"
                      "<td class=\"num\">-2.25</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td class=\"num\">20</td><td class=\"num\">20.50</td>"), std::string::npos);
  EXPECT_EQ(html.find("<td class=\"num\">21</td><td class=\"num\">21.50</td>"), std::string::npos);
  // Ranks out of order name the file and line.
  WriteTextFileAtomically(dir / "navigation_points.csv",
                          "rank,x_m,y_m,path_cost_m,info_gain_m2,revenue,cluster,"
                          "component_points\n2,1,1,1,1,1,0,1\n");
  try {
    BuildRunReport(dir);
    ADD_FAILURE() << "no error for a rank of 2 in the first row";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("navigation_points.csv:2: rank '2', expected 1"),
              std::string::npos)
        << e.what();
  }
}

// An exploration's goals.csv: how the goals ended, and the ones neither
// reached nor seen on the way.
TEST(HtmlReport, ExploreRunCountsItsGoalsByOutcome) {
  const std::filesystem::path dir = testing::WriteExploreRun("goals", 1.0);
  const std::string header =
      "issued_s,robot_x,robot_y,goal_x,goal_y,target_x,target_y,score,path_m,ended_s,outcome,"
      "reachable_in_truth\n";
  WriteTextFileAtomically(dir / "goals.csv",
                          header +
                              "1,0,0,2,0,1.8,0,-1.500,2.1,3.000,seen,1\n"
                              "3.05,1,0,5,1,4.8,1,-3.250,4.2,9.000,reached,1\n"
                              "9.05,4.8,1,7.25,-3.5,7.2,-3.3,-6.125,6.6,20.000,failed,0\n"
                              "20.05,4,0,1,1,1.2,1,,3.3,,open,1\n");
  const std::string html = FindFile(BuildRunReport(dir), "report.html")->content;
  ExpectSelfContained(html);
  EXPECT_NE(html.find("4 goals issued"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>failed</td><td class=\"num\">1</td>"), std::string::npos) << html;
  // Only the failed and the open goal are listed, the failed one as the true
  // world could not be reached there.
  EXPECT_NE(html.find("<td class=\"num\">7.25</td><td class=\"num\">-3.50</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>failed</td><td>no</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>open</td><td>yes</td>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<td class=\"num\">5.00</td><td class=\"num\">1.00</td>"), std::string::npos);
  // Bad rows name the file, the line and what was expected.
  const auto expect_error = [&](const std::string& row, const std::string& message) {
    WriteTextFileAtomically(dir / "goals.csv",
                            header + "1,0,0,2,0,1.8,0,-1.5,2.1,3,seen,1\n" + row);
    try {
      BuildRunReport(dir);
      ADD_FAILURE() << "no error for " << row;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("goals.csv:3: " + message), std::string::npos)
          << e.what();
    }
  };
  expect_error("0.5,0,0,2,0,1.8,0,-1,2,3,seen,1\n", "issued_s '0.5' falls below");
  expect_error("2,0,0,2,0,1.8,0,-1,2,3,lost,1\n", "outcome 'lost', expected one of");
  expect_error("2,0,0,2,0,1.8,0,-1,2,,seen,1\n", "ended_s '' for outcome 'seen'");
  expect_error("2,0,0,2,0,1.8,0,-1,2,3,open,1\n", "ended_s '3' for outcome 'open'");
  expect_error("2,0,0,2,0,1.8,0,-1,2,1.5,seen,1\n", "ended_s '1.5' before issued_s");
  expect_error("2,0,0,2,0,1.8,0,-1,2,3,seen,yes\n", "reachable_in_truth 'yes', expected 0 or 1");
  expect_error("2,0,0,2,0,1.8,0,x,2,3,seen,1\n", "column 'score' is 'x'");
}

TEST(Compare, TwoRunsSideBySide) {
  const std::filesystem::path a = testing::WriteFrontierRun("eps_a");
  const std::filesystem::path b = testing::WriteFrontierRun("eps_b");
  std::string summary = testing::kSummaryJson;
  summary.replace(summary.find("\"P\": 0.888889"), 13, "\"P\": 0.5");
  WriteTextFileAtomically(b / "summary.json", summary);
  const std::vector<ReportFile> files =
      BuildComparison({a, b, testing::WriteExploreRun("explore_b", 2.0)});
  const ReportFile* page = FindFile(files, "compare.html");
  ASSERT_NE(page, nullptr);
  const std::string& html = page->content;
  ExpectSelfContained(html);
  EXPECT_NE(html.find("<th></th><th>eps_a</th><th>eps_b</th><th>explore_b</th>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>world / dataset</td><td>office</td><td>office</td><td>museum</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>P (%) (direct)</td><td class=\"num\">88.89</td>"
                      "<td class=\"num\">50.00</td><td>–</td>"),
            std::string::npos)
      << html;
  // The explore run names its frontier strategy and its goal policy; the
  // frontier runs their strategies.
  EXPECT_NE(html.find("<td>strategy / goal policy</td><td>full, dfd, direct</td>"
                      "<td>full, dfd, direct</td>"
                      "<td>exact / nearest</td>"),
            std::string::npos)
      << html;
  // Coverage 1 - 0.6^i at path 2 * 10 i m: 95 % at i = 6, 99 % at i = 10.
  EXPECT_NE(html.find("<td>path to 95 % coverage (m)</td><td>–</td><td>–</td>"
                      "<td class=\"num\">120.0</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td>path to 99 % coverage (m)</td><td>–</td><td>–</td>"
                      "<td class=\"num\">200.0</td>"),
            std::string::npos)
      << html;
  const ReportFile* p = FindFile(files, "figures/compare_p.svg");
  ASSERT_NE(p, nullptr);
  const testing::XmlCheck xml = testing::CheckXml(p->content);
  ASSERT_EQ(xml.error, "");
  EXPECT_EQ(xml.classes.at("series"), 3);  // one per run
  EXPECT_EQ(xml.classes.at("bar"), 4);     // dfd and direct of the two frontier runs
  EXPECT_NE(FindFile(files, "figures/compare_coverage_path.svg"), nullptr);
}

TEST(Compare, SameNamedDirectoriesAreDisambiguated) {
  const std::filesystem::path a = testing::WriteFrontierRun("x/out");
  const std::filesystem::path b = testing::WriteFrontierRun("y/out");
  const std::vector<ReportFile> files = BuildComparison({a, b});
  EXPECT_NE(files.back().content.find("<th>out (2)</th>"), std::string::npos);
  EXPECT_THROW(BuildComparison({}), InputError);
}

// Renders report.html in headless Chromium when it is installed: the page
// must load and its DOM must hold the figures.
TEST(HtmlReport, RendersInHeadlessChromium) {
  if (std::system("command -v chromium > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "chromium is not installed (Debian package 'chromium'); render check skipped";
  }
  const std::filesystem::path dir = testing::WriteFrontierRun("chromium");
  for (const ReportFile& f : BuildRunReport(dir)) {
    std::filesystem::create_directories((dir / f.name).parent_path());
    WriteTextFileAtomically(dir / f.name, f.content);
  }
  const std::filesystem::path dom = dir / "dom.html";
  const std::string command = "chromium --headless --disable-gpu --no-sandbox --user-data-dir=" +
                              (dir / "profile").string() + " --dump-dom file://" +
                              (dir / "report.html").string() + " > " + dom.string() + " 2> " +
                              (dir / "chromium.log").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(dom);
  const std::string rendered{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(rendered.find("Scout report: chromium"), std::string::npos);
  EXPECT_NE(rendered.find("Points re-queried per optimisation round"), std::string::npos);
  EXPECT_NE(rendered.find("<svg"), std::string::npos);
  EXPECT_NE(rendered.find("88.89"), std::string::npos);
}

}  // namespace
}  // namespace scout::report
