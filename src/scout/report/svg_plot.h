#ifndef SCOUT_REPORT_SVG_PLOT_H_
#define SCOUT_REPORT_SVG_PLOT_H_

#include <string>
#include <vector>

namespace scout::report {

// One named line of a LineChart. Points with a non-finite y (or y <= 0 on a
// log axis) are gaps: the line is broken there rather than drawn through.
struct Series {
  std::string name;
  std::vector<double> x;
  std::vector<double> y;  // same length as x
};

struct LineChart {
  std::string title;
  std::string x_label;  // with its unit, e.g. "path length (m)"
  std::string y_label;
  std::vector<Series> series;
  bool log_y = false;
  // Series with at most this many points get a marker at every point, so a
  // short series is not mistaken for a straight line.
  int max_points_with_markers = 40;
  int width_px = 760;
  int height_px = 440;
};

// Bars of one measure (e.g. "precision") over all categories of a BarChart.
struct BarSeries {
  std::string name;
  std::vector<double> values;  // one per category; NaN draws no bar
};

struct BarChart {
  std::string title;
  std::string y_label;
  std::vector<std::string> categories;  // groups along x (e.g. strategies)
  std::vector<BarSeries> series;        // bars within each group
  // Values near 1 (accuracy 0.999) are indistinguishable on an axis from 0:
  // with 'zoom', the axis starts at a nice value below the smallest bar and
  // the chart says so under its title.
  bool zoom = false;
  // printf format of the value written on each bar ("" writes none; "auto"
  // uses one decimal more than the axis labels).
  std::string value_format = "auto";
  int width_px = 760;
  int height_px = 440;
};

// Returns a standalone SVG document (no external fonts, images or scripts)
// with a title, labelled axes with nice ticks, a legend in palette order, and
// one <g class="series"> per series. Throws std::invalid_argument when a
// series has x and y of different lengths.
std::string RenderLineChart(const LineChart& chart);

// Returns a standalone SVG grouped bar chart: one <g class="series"> per
// BarSeries holding one <rect class="bar"> per drawn value.
std::string RenderBarChart(const BarChart& chart);

// Returns the colour of series 'index': the Okabe-Ito palette, which stays
// distinguishable under the common colour-vision deficiencies.
const char* SeriesColour(int index);

// Returns 'text' with &, <, >, " and ' escaped for XML text and attributes.
std::string EscapeXml(const std::string& text);

}  // namespace scout::report

#endif  // SCOUT_REPORT_SVG_PLOT_H_
