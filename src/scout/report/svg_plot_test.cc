#include "scout/report/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "scout/report/xml_check.h"

namespace scout::report {
namespace {

using testing::CheckXml;

int Count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
  return n;
}

LineChart ThreeSeries() {
  LineChart chart;
  chart.title = "Points <re-queried> & time";
  chart.x_label = "optimisation round";
  chart.y_label = "points";
  chart.series = {{"dfd", {0, 1, 2, 3}, {100, 120, 130, 160}},
                  {"direct", {0, 1, 2, 3}, {10, 0, 30, 5}},
                  {"bfs", {0, 1, 2, 3}, {12, 2, 28, 7}}};
  return chart;
}

TEST(SvgPlot, LineChartIsWellFormedWithOneGroupPerSeries) {
  const std::string svg = RenderLineChart(ThreeSeries());
  const testing::XmlCheck xml = CheckXml(svg);
  ASSERT_EQ(xml.error, "") << svg;
  EXPECT_EQ(xml.counts.at("svg"), 1);
  EXPECT_EQ(xml.classes.at("series"), 3);
  EXPECT_EQ(xml.classes.at("line"), 3);
  // Short series carry a marker at every point.
  EXPECT_EQ(xml.classes.at("marker"), 3 * 4 + 3);  // + one per legend entry
  // 0..160 in steps of 20 (9 ticks) and rounds 0..3 without half steps.
  EXPECT_EQ(xml.classes.at("ytick"), 9);
  EXPECT_EQ(xml.classes.at("xtick"), 4);
  EXPECT_NE(svg.find("Points &lt;re-queried&gt; &amp; time"), std::string::npos);
  EXPECT_NE(svg.find(">optimisation round<"), std::string::npos);
  // Distinct colours, one per series.
  EXPECT_GE(Count(svg, SeriesColour(0)), 2);
  EXPECT_GE(Count(svg, SeriesColour(1)), 2);
  EXPECT_GE(Count(svg, SeriesColour(2)), 2);
  // No external resources.
  EXPECT_EQ(svg.find("href"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("@import"), std::string::npos);
}

TEST(SvgPlot, LongSeriesHaveNoMarkersAndEveryPointIsOnTheLine) {
  LineChart chart;
  chart.title = "long";
  Series s{"s", {}, {}};
  for (int i = 0; i < 200; ++i) {
    s.x.push_back(i);
    s.y.push_back(i * i);
  }
  chart.series = {s};
  const std::string svg = RenderLineChart(chart);
  const testing::XmlCheck xml = CheckXml(svg);
  ASSERT_EQ(xml.error, "");
  EXPECT_EQ(xml.classes.count("marker"), 0u);
  const size_t points = svg.find("points=\"");
  ASSERT_NE(points, std::string::npos);
  const std::string list = svg.substr(points + 8, svg.find('"', points + 8) - points - 8);
  EXPECT_EQ(Count(list, ","), 200);
}

// A long run's frontier.csv holds a million rounds: the line is drawn through
// the extremes of each quarter-pixel column only, and a spike of one round
// still shows.
TEST(SvgPlot, MillionPointSeriesIsSmallAndKeepsItsSpikes) {
  LineChart chart;
  chart.title = "long";
  Series s{"s", {}, {}};
  for (int i = 0; i < 1000000; ++i) {
    s.x.push_back(i);
    s.y.push_back(i == 123457 ? 1000.0 : i == 777777 ? -1000.0 : 0.1 * (i % 10));
  }
  chart.series = {s};
  const std::string svg = RenderLineChart(chart);
  ASSERT_EQ(CheckXml(svg).error, "");
  const size_t points = svg.find("points=\"");
  ASSERT_NE(points, std::string::npos);
  const std::string list = svg.substr(points + 8, svg.find('"', points + 8) - points - 8);
  // At most four points per quarter-pixel column of the 760 px wide picture.
  EXPECT_LE(Count(list, ","), 4 * 4 * 760);
  EXPECT_LT(svg.size(), 500000u);
  double top = std::numeric_limits<double>::infinity(), bottom = -top;
  double previous_x = -top;
  bool x_in_order = true;
  std::istringstream in(list);
  for (std::string pair; in >> pair;) {
    const double x = std::stod(pair.substr(0, pair.find(',')));
    const double y = std::stod(pair.substr(pair.find(',') + 1));
    x_in_order = x_in_order && x >= previous_x;
    previous_x = x;
    top = std::min(top, y);
    bottom = std::max(bottom, y);
  }
  EXPECT_TRUE(x_in_order);
  // The y axis runs from -1000 to 1000, and both one-round spikes reach its
  // ends: the plot's bottom edge (440 - 58 px) and near its top (under the
  // title and legend, about 60 px), far from the zero line in the middle.
  EXPECT_NE(svg.find(">-1000<"), std::string::npos);
  EXPECT_NE(svg.find(">1000<"), std::string::npos);
  EXPECT_DOUBLE_EQ(bottom, 382.0);
  EXPECT_LT(top, 100.0);
}

TEST(SvgPlot, GapsBreakTheLineAndLogAxisDropsNonPositiveValues) {
  LineChart chart;
  chart.title = "gaps";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  chart.series = {{"a", {0, 1, 2, 3, 4}, {1, 10, nan, 100, 1000}}};
  std::string svg = RenderLineChart(chart);
  ASSERT_EQ(CheckXml(svg).error, "");
  EXPECT_EQ(CheckXml(svg).classes.at("line"), 2);
  chart.log_y = true;
  chart.series = {{"a", {0, 1, 2, 3}, {0, 10, 100, 5000}}};
  svg = RenderLineChart(chart);
  const testing::XmlCheck xml = CheckXml(svg);
  ASSERT_EQ(xml.error, "");
  EXPECT_EQ(xml.classes.at("line"), 1);
  EXPECT_EQ(xml.classes.at("marker"), 3 + 1);
  // Decades 10 .. 10k.
  EXPECT_EQ(xml.classes.at("ytick"), 4);
  EXPECT_NE(svg.find(">10k<"), std::string::npos);
}

TEST(SvgPlot, EscapedTextIsWellFormedUtf8) {
  EXPECT_EQ(EscapeXml("<a & 'b'>"), "&lt;a &amp; &#39;b&#39;&gt;");
  // A directory name in Latin-1, a truncated sequence and a control character
  // each become U+FFFD; well-formed UTF-8 passes unchanged.
  EXPECT_EQ(EscapeXml("bad\xff\xfename"), "bad\xEF\xBF\xBD\xEF\xBF\xBDname");
  EXPECT_EQ(EscapeXml("caf\xc3"), "caf\xEF\xBF\xBD");
  EXPECT_EQ(EscapeXml("a\x01"
                      "b"),
            "a\xEF\xBF\xBD"
            "b");
  EXPECT_EQ(EscapeXml("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82"),
            "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82");
  EXPECT_EQ(EscapeXml("\xed\xa0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate
}

TEST(SvgPlot, MismatchedSeriesIsRejected) {
  LineChart chart;
  chart.series = {{"a", {0, 1}, {1}}};
  EXPECT_THROW(RenderLineChart(chart), std::invalid_argument);
}

TEST(SvgPlot, GroupedBarsOnePerValueWithZoomNote) {
  BarChart chart;
  chart.title = "Accuracy";
  chart.y_label = "%";
  chart.categories = {"dfd", "bfs", "direct"};
  chart.series = {{"accuracy", {100, 99.93, 99.95}},
                  {"precision", {100, 99.8, std::numeric_limits<double>::quiet_NaN()}},
                  {"recall", {100, 99.9, 99.97}}};
  chart.zoom = true;
  chart.value_format = "%.2f";
  const std::string svg = RenderBarChart(chart);
  const testing::XmlCheck xml = CheckXml(svg);
  ASSERT_EQ(xml.error, "") << svg;
  EXPECT_EQ(xml.classes.at("series"), 3);
  EXPECT_EQ(xml.classes.at("bar"), 8);  // the NaN draws nothing
  EXPECT_EQ(xml.classes.at("value"), 8);
  EXPECT_EQ(xml.classes.at("xtick"), 3);
  EXPECT_NE(svg.find("y axis starts at"), std::string::npos);
  EXPECT_NE(svg.find(">99.93<"), std::string::npos);
  chart.zoom = false;
  const std::string unzoomed = RenderBarChart(chart);
  EXPECT_EQ(unzoomed.find("y axis starts at"), std::string::npos);
  EXPECT_NE(unzoomed.find(">0<"), std::string::npos);
  // "auto" labels carry one decimal more than the axis: 0..100 in steps of 20.
  chart.value_format = "auto";
  EXPECT_NE(RenderBarChart(chart).find(">99.9<"), std::string::npos);
}

TEST(SvgPlot, NegativeBarsHangFromZero) {
  BarChart chart;
  chart.title = "P";
  chart.categories = {"a", "b"};
  chart.series = {{"run", {40, -10}}};
  const std::string svg = RenderBarChart(chart);
  ASSERT_EQ(CheckXml(svg).error, "");
  EXPECT_NE(svg.find(">-10<"), std::string::npos);  // a tick below zero
  EXPECT_EQ(CheckXml(svg).classes.at("bar"), 2);
}

TEST(SvgPlot, CheckerRejectsBrokenXml) {
  EXPECT_NE(CheckXml("<svg><g></svg>").error, "");
  EXPECT_NE(CheckXml("<svg a=b></svg>").error, "");
  EXPECT_NE(CheckXml("<svg>a & b</svg>").error, "");
  EXPECT_EQ(CheckXml("<svg><g a=\"1\"/></svg>").error, "");
}

}  // namespace
}  // namespace scout::report
