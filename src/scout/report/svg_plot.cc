#include "scout/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scout/report/axis_ticks.h"

namespace scout::report {
namespace {

constexpr double kCharWidthPx = 6.6;  // rough width of a 12 px sans-serif glyph
constexpr double kValueCharPx = 6.4;  // a 10 px digit, with room to breathe
constexpr double kLegendRowPx = 20.0;
constexpr double kMarginLeftPx = 78.0;
constexpr double kMarginRightPx = 24.0;
constexpr double kMarginBottomPx = 58.0;

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1f", v);
  return buffer;
}

// Second cue besides colour, for print and colour-vision deficiencies.
const char* DashPattern(int index) {
  static const char* kDashes[] = {"", "7 4", "2 3", "9 3 2 3", "4 4", "12 4", "2 6", "6 2 2 2"};
  return kDashes[index % 8];
}

// Where the plot area sits inside the picture and how values map onto it.
struct Frame {
  double left, top, right, bottom;
  AxisTicks x_axis, y_axis;
  bool log_y = false;
  double X(double v) const {
    return left + (v - x_axis.lo) / (x_axis.hi - x_axis.lo) * (right - left);
  }
  double Y(double v) const {
    const double t = log_y ? (std::log10(v) - std::log10(y_axis.lo)) /
                                 (std::log10(y_axis.hi) - std::log10(y_axis.lo))
                           : (v - y_axis.lo) / (y_axis.hi - y_axis.lo);
    return bottom - t * (bottom - top);
  }
};

// A point of a line in picture coordinates (px).
struct Pixel {
  double x, y;
};

// Consecutive points of a line that fall in one column kColumnPx wide. Kept()
// returns its first, lowest, highest and last point in their order along the
// line: drawn through those, the line covers the same pixels.
class ColumnRun {
 public:
  static constexpr double kColumnPx = 0.25;

  bool Accepts(const Pixel& p) const {
    return count_ == 0 || std::floor(p.x / kColumnPx) == column_;
  }
  void Add(const Pixel& p) {
    if (count_ == 0) {
      column_ = std::floor(p.x / kColumnPx);
      first_ = lowest_ = highest_ = p;
      lowest_at_ = highest_at_ = 0;
    }
    // Screen y grows downwards; "lowest" is the largest y.
    if (p.y > lowest_.y) lowest_ = p, lowest_at_ = count_;
    if (p.y < highest_.y) highest_ = p, highest_at_ = count_;
    last_ = p;
    last_at_ = count_;
    ++count_;
  }
  std::vector<Pixel> Kept() const {
    std::vector<Pixel> kept;
    if (count_ == 0) return kept;
    kept.push_back(first_);
    const bool lowest_first = lowest_at_ <= highest_at_;
    const std::pair<const Pixel*, size_t> middle[] = {
        {lowest_first ? &lowest_ : &highest_, lowest_first ? lowest_at_ : highest_at_},
        {lowest_first ? &highest_ : &lowest_, lowest_first ? highest_at_ : lowest_at_}};
    size_t previous = 0;
    for (const auto& [p, at] : middle) {
      if (at > previous) kept.push_back(*p), previous = at;
    }
    if (last_at_ > previous) kept.push_back(last_);
    return kept;
  }
  void Clear() { count_ = 0; }

 private:
  double column_ = 0.0;
  Pixel first_{}, lowest_{}, highest_{}, last_{};
  size_t lowest_at_ = 0, highest_at_ = 0, last_at_ = 0, count_ = 0;
};

struct LegendEntry {
  std::string name;
  int index;
  bool line;  // a line swatch (with marker) rather than a filled box
  bool marker;
};

void Marker(std::ostringstream& svg, int index, double x, double y, const char* colour) {
  const double r = 3.6;
  svg << "<path class=\"marker\" fill=\"" << colour
      << "\" stroke=\"white\" stroke-width=\"0.8\" d=\"";
  switch (index % 5) {
    case 0:  // circle as two arcs, so every marker is one <path>
      svg << "M" << Num(x - r) << " " << Num(y) << "a" << r << " " << r << " 0 1 0 " << 2 * r
          << " 0a" << r << " " << r << " 0 1 0 " << -2 * r << " 0Z";
      break;
    case 1:
      svg << "M" << Num(x - r) << " " << Num(y - r) << "h" << 2 * r << "v" << 2 * r << "h" << -2 * r
          << "Z";
      break;
    case 2:
      svg << "M" << Num(x) << " " << Num(y - r - 0.8) << "L" << Num(x + r + 0.6) << " "
          << Num(y + r) << "L" << Num(x - r - 0.6) << " " << Num(y + r) << "Z";
      break;
    case 3:
      svg << "M" << Num(x) << " " << Num(y - r - 1) << "L" << Num(x + r + 1) << " " << Num(y) << "L"
          << Num(x) << " " << Num(y + r + 1) << "L" << Num(x - r - 1) << " " << Num(y) << "Z";
      break;
    default:
      svg << "M" << Num(x) << " " << Num(y + r + 0.8) << "L" << Num(x + r + 0.6) << " "
          << Num(y - r) << "L" << Num(x - r - 0.6) << " " << Num(y - r) << "Z";
  }
  svg << "\"/>";
}

// Lays the legend out in rows under the title; returns the height it takes.
double LegendHeight(const std::vector<LegendEntry>& entries, double width) {
  double x = 0.0;
  int rows = entries.empty() ? 0 : 1;
  for (const LegendEntry& e : entries) {
    const double w = 40.0 + kCharWidthPx * e.name.size() + 18.0;
    if (x > 0.0 && x + w > width) {
      ++rows;
      x = 0.0;
    }
    x += w;
  }
  return rows * kLegendRowPx;
}

void DrawLegend(std::ostringstream& svg, const std::vector<LegendEntry>& entries, double left,
                double top, double width) {
  svg << "<g class=\"legend\">";
  double x = 0.0, y = top;
  for (const LegendEntry& e : entries) {
    const double w = 40.0 + kCharWidthPx * e.name.size() + 18.0;
    if (x > 0.0 && x + w > width) {
      x = 0.0;
      y += kLegendRowPx;
    }
    const char* colour = SeriesColour(e.index);
    const double cx = left + x, cy = y + kLegendRowPx / 2;
    if (e.line) {
      svg << "<line x1=\"" << Num(cx) << "\" y1=\"" << Num(cy) << "\" x2=\"" << Num(cx + 32)
          << "\" y2=\"" << Num(cy) << "\" stroke=\"" << colour
          << "\" stroke-width=\"2.2\" stroke-dasharray=\"" << DashPattern(e.index) << "\"/>";
      if (e.marker) Marker(svg, e.index, cx + 16, cy, colour);
    } else {
      svg << "<rect x=\"" << Num(cx + 8) << "\" y=\"" << Num(cy - 6) << "\" width=\"16\" "
          << "height=\"12\" fill=\"" << colour << "\"/>";
    }
    svg << "<text x=\"" << Num(cx + 38) << "\" y=\"" << Num(cy + 4) << "\">" << EscapeXml(e.name)
        << "</text>";
    x += w;
  }
  svg << "</g>\n";
}

void Header(std::ostringstream& svg, int width, int height, const std::string& title) {
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height
      << "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\" font-size=\"12\" "
         "role=\"img\">\n<title>"
      << EscapeXml(title) << "</title>\n<rect width=\"" << width << "\" height=\"" << height
      << "\" fill=\"white\"/>\n<text class=\"title\" x=\"" << width / 2
      << "\" y=\"22\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">"
      << EscapeXml(title) << "</text>\n";
}

// Horizontal grid lines, y tick labels and the rotated y axis label.
void DrawYAxis(std::ostringstream& svg, const Frame& f, const std::string& label) {
  svg << "<g class=\"y-axis\">";
  const std::vector<std::string> labels = TickLabels(f.y_axis);
  for (size_t i = 0; i < labels.size(); ++i) {
    const double y = f.Y(f.y_axis.ticks[i]);
    svg << "<line x1=\"" << Num(f.left) << "\" y1=\"" << Num(y) << "\" x2=\"" << Num(f.right)
        << "\" y2=\"" << Num(y) << "\" stroke=\"#dddddd\"/>"
        << "<text class=\"ytick\" x=\"" << Num(f.left - 6) << "\" y=\"" << Num(y + 4)
        << "\" text-anchor=\"end\">" << labels[i] << "</text>";
  }
  const double mid = (f.top + f.bottom) / 2;
  svg << "<text class=\"axis-label\" x=\"18\" y=\"" << Num(mid) << "\" transform=\"rotate(-90 18 "
      << Num(mid) << ")\" text-anchor=\"middle\" font-size=\"13\">" << EscapeXml(label)
      << "</text></g>\n";
}

void DrawFrameBox(std::ostringstream& svg, const Frame& f) {
  svg << "<rect x=\"" << Num(f.left) << "\" y=\"" << Num(f.top) << "\" width=\""
      << Num(f.right - f.left) << "\" height=\"" << Num(f.bottom - f.top)
      << "\" fill=\"none\" stroke=\"#444444\"/>\n";
}

}  // namespace

const char* SeriesColour(int index) {
  // Okabe & Ito (2008), ordered so the first colours differ most; yellow last.
  static const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  return kPalette[index % 8];
}

namespace {

// Length of the well-formed UTF-8 sequence at text[i], or 0 if there is none
// (a stray byte of another encoding, a truncated or overlong sequence).
size_t Utf8SequenceLength(const std::string& text, size_t i) {
  const auto byte = [&text](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  size_t length = 0;
  unsigned char min_second = 0x80, max_second = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) min_second = 0xA0;  // overlong
    if (lead == 0xED) max_second = 0x9F;  // surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) min_second = 0x90;  // overlong
    if (lead == 0xF4) max_second = 0x8F;  // beyond U+10FFFF
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < min_second || byte(i + 1) > max_second) return 0;
  for (size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

std::string EscapeXml(const std::string& text) {
  // Pages and figures declare UTF-8: a directory name in another encoding, or
  // a control character, would make the file ill-formed, so each becomes the
  // replacement character U+FFFD.
  static const char kReplacement[] = "\xEF\xBF\xBD";
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    const size_t length = Utf8SequenceLength(text, i);
    if (length == 0) {
      out += kReplacement;
      ++i;
      continue;
    }
    if (length > 1) {
      out.append(text, i, length);
      i += length;
      continue;
    }
    ++i;
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += kReplacement;
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string RenderLineChart(const LineChart& chart) {
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
  double y_min = x_min, y_max = -x_min;
  bool all_integral_x = true;
  std::vector<LegendEntry> legend;
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const Series& series = chart.series[s];
    if (series.x.size() != series.y.size()) {
      throw std::invalid_argument("series '" + series.name + "' has x and y of different lengths");
    }
    const bool markers = static_cast<int>(series.x.size()) <= chart.max_points_with_markers;
    legend.push_back({series.name, static_cast<int>(s), true, markers});
    for (size_t i = 0; i < series.x.size(); ++i) {
      const double y = series.y[i];
      if (!std::isfinite(series.x[i]) || !std::isfinite(y) || (chart.log_y && y <= 0)) continue;
      x_min = std::min(x_min, series.x[i]);
      x_max = std::max(x_max, series.x[i]);
      y_min = std::min(y_min, y);
      y_max = std::max(y_max, y);
      all_integral_x = all_integral_x && series.x[i] == std::round(series.x[i]);
    }
  }
  if (!std::isfinite(x_min)) x_min = 0, x_max = 1, y_min = chart.log_y ? 1 : 0, y_max = 10;
  Frame f;
  f.log_y = chart.log_y;
  f.left = kMarginLeftPx;
  f.right = chart.width_px - kMarginRightPx;
  const double legend_height = LegendHeight(legend, f.right - f.left);
  f.top = 34.0 + legend_height + 8.0;
  f.bottom = chart.height_px - kMarginBottomPx;
  f.x_axis = NiceTicks(x_min, x_max, 8);
  if (all_integral_x && f.x_axis.step < 1.0) {
    // Round numbers and counts have no half steps.
    f.x_axis = NiceTicks(std::floor(x_min), std::max(std::ceil(x_max), std::floor(x_min) + 1),
                         static_cast<int>(std::ceil(x_max) - std::floor(x_min)));
  }
  // Counts and times read against zero; a log axis cannot show it.
  f.y_axis = chart.log_y ? LogTicks(y_min, y_max) : NiceTicks(std::min(0.0, y_min), y_max, 6);

  std::ostringstream svg;
  Header(svg, chart.width_px, chart.height_px, chart.title);
  DrawLegend(svg, legend, f.left, 34.0, f.right - f.left);
  DrawYAxis(svg, f, chart.y_label);
  svg << "<g class=\"x-axis\">";
  const std::vector<std::string> x_labels = TickLabels(f.x_axis);
  for (size_t i = 0; i < x_labels.size(); ++i) {
    const double x = f.X(f.x_axis.ticks[i]);
    svg << "<line x1=\"" << Num(x) << "\" y1=\"" << Num(f.top) << "\" x2=\"" << Num(x) << "\" y2=\""
        << Num(f.bottom) << "\" stroke=\"#eeeeee\"/>"
        << "<text class=\"xtick\" x=\"" << Num(x) << "\" y=\"" << Num(f.bottom + 18)
        << "\" text-anchor=\"middle\">" << x_labels[i] << "</text>";
  }
  svg << "<text class=\"axis-label\" x=\"" << Num((f.left + f.right) / 2) << "\" y=\""
      << chart.height_px - 14 << "\" text-anchor=\"middle\" font-size=\"13\">"
      << EscapeXml(chart.x_label) << "</text></g>\n";
  DrawFrameBox(svg, f);

  for (size_t s = 0; s < chart.series.size(); ++s) {
    const Series& series = chart.series[s];
    const char* colour = SeriesColour(static_cast<int>(s));
    svg << "<g class=\"series\" data-name=\"" << EscapeXml(series.name) << "\">";
    std::string points;
    // A run of consecutive points within one column a quarter pixel wide is
    // drawn through its first, lowest, highest and last point only: the line
    // looks the same, and a series of a million rounds (a long run's
    // frontier.csv) gives a figure of kilobytes, not of tens of megabytes.
    ColumnRun run;
    const auto emit = [&] {
      for (const Pixel& p : run.Kept()) {
        points += (points.empty() ? "" : " ") + Num(p.x) + "," + Num(p.y);
      }
      run.Clear();
    };
    const auto flush = [&] {
      emit();
      if (points.empty()) return;
      svg << "<polyline class=\"line\" fill=\"none\" stroke=\"" << colour
          << "\" stroke-width=\"2\" stroke-linejoin=\"round\" stroke-dasharray=\""
          << DashPattern(static_cast<int>(s)) << "\" points=\"" << points << "\"/>";
      points.clear();
    };
    for (size_t i = 0; i < series.x.size(); ++i) {
      const double y = series.y[i];
      if (!std::isfinite(series.x[i]) || !std::isfinite(y) || (chart.log_y && y <= 0)) {
        flush();
        continue;
      }
      const Pixel p{f.X(series.x[i]), f.Y(y)};
      if (!run.Accepts(p)) emit();
      run.Add(p);
    }
    flush();
    if (legend[s].marker) {
      for (size_t i = 0; i < series.x.size(); ++i) {
        const double y = series.y[i];
        if (!std::isfinite(series.x[i]) || !std::isfinite(y) || (chart.log_y && y <= 0)) continue;
        Marker(svg, static_cast<int>(s), f.X(series.x[i]), f.Y(y), colour);
      }
    }
    svg << "</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string RenderBarChart(const BarChart& chart) {
  double v_min = std::numeric_limits<double>::infinity(), v_max = -v_min;
  std::vector<LegendEntry> legend;
  for (size_t s = 0; s < chart.series.size(); ++s) {
    legend.push_back({chart.series[s].name, static_cast<int>(s), false, false});
    for (const double v : chart.series[s].values) {
      if (!std::isfinite(v)) continue;
      v_min = std::min(v_min, v);
      v_max = std::max(v_max, v);
    }
  }
  if (!std::isfinite(v_min)) v_min = 0, v_max = 1;
  Frame f;
  f.left = kMarginLeftPx;
  f.right = chart.width_px - kMarginRightPx;
  const double legend_height = LegendHeight(legend, f.right - f.left);
  const bool zoomed = chart.zoom && v_min > 0.0;
  f.top = 34.0 + (zoomed ? 16.0 : 0.0) + legend_height + 8.0;
  f.bottom = chart.height_px - kMarginBottomPx;
  f.x_axis = {0.0, static_cast<double>(std::max<size_t>(chart.categories.size(), 1)), 1.0, {}};
  if (zoomed) {
    const double pad = v_max > v_min ? 0.5 * (v_max - v_min) : std::max(0.01 * v_max, 1e-9);
    f.y_axis = NiceTicks(v_min - pad, v_max, 6);
  } else {
    f.y_axis = NiceTicks(std::min(0.0, v_min), std::max(0.0, v_max), 6);
  }
  const double baseline = f.Y(std::clamp(0.0, f.y_axis.lo, f.y_axis.hi));

  std::ostringstream svg;
  Header(svg, chart.width_px, chart.height_px, chart.title);
  if (zoomed) {
    svg << "<text class=\"subtitle\" x=\"" << chart.width_px / 2
        << "\" y=\"40\" text-anchor=\"middle\" font-size=\"11\" fill=\"#555555\">y axis starts at "
        << FormatTick(f.y_axis.lo, f.y_axis.step) << ", not 0</text>\n";
  }
  DrawLegend(svg, legend, f.left, zoomed ? 50.0 : 34.0, f.right - f.left);
  DrawYAxis(svg, f, chart.y_label);
  const double group = (f.right - f.left) / f.x_axis.hi;
  const double bar = group * 0.8 / std::max<size_t>(chart.series.size(), 1);
  svg << "<g class=\"x-axis\">";
  for (size_t c = 0; c < chart.categories.size(); ++c) {
    svg << "<text class=\"xtick\" x=\"" << Num(f.left + (c + 0.5) * group) << "\" y=\""
        << Num(f.bottom + 18) << "\" text-anchor=\"middle\" font-size=\"13\">"
        << EscapeXml(chart.categories[c]) << "</text>";
  }
  svg << "</g>\n";
  DrawFrameBox(svg, f);
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const BarSeries& series = chart.series[s];
    svg << "<g class=\"series\" data-name=\"" << EscapeXml(series.name) << "\" fill=\""
        << SeriesColour(static_cast<int>(s)) << "\">";
    for (size_t c = 0; c < series.values.size() && c < chart.categories.size(); ++c) {
      const double v = series.values[c];
      if (!std::isfinite(v)) continue;
      const double x = f.left + c * group + 0.1 * group + s * bar;
      const double y = f.Y(std::clamp(v, f.y_axis.lo, f.y_axis.hi));
      svg << "<rect class=\"bar\" x=\"" << Num(x + 1) << "\" y=\"" << Num(std::min(y, baseline))
          << "\" width=\"" << Num(std::max(bar - 2, 1.0)) << "\" height=\""
          << Num(std::abs(baseline - y)) << "\"><title>" << EscapeXml(series.name) << " / "
          << EscapeXml(chart.categories[c]) << ": " << v << "</title></rect>";
      if (chart.value_format.empty()) continue;
      char text[48];
      if (chart.value_format == "auto") {
        // One decimal more than the axis labels, so neighbouring bars differ.
        const double step = f.y_axis.step;
        const int decimals =
            1 + (step < 1.0 ? static_cast<int>(std::ceil(-std::log10(step) - 1e-9)) : 0);
        std::snprintf(text, sizeof(text), "%.*f", std::min(decimals, 6), v);
      } else {
        std::snprintf(text, sizeof(text), chart.value_format.c_str(), v);
      }
      const double cx = x + bar / 2;
      const double text_px = kValueCharPx * std::string(text).size();
      // Labels wider than their bar are turned upright so neighbours never overlap.
      const bool upright = text_px > bar - 2;
      const double height = std::abs(baseline - y);
      // Inside the bar when it is long enough, so tall bars do not push labels
      // into the legend; light palette colours get dark text for contrast.
      const bool inside = v >= 0 && height > (upright ? text_px : 12.0) + 8;
      const bool light = s % 8 == 4 || s % 8 == 5 || s % 8 == 7;
      const char* ink = inside && !light ? "white" : "#222222";
      const double top = std::min(y, baseline), low = std::max(y, baseline);
      svg << "<text class=\"value\" font-size=\"10\" fill=\"" << ink << "\" ";
      if (upright) {
        const double ty = inside ? top + 4 : (v >= 0 ? top - 4 : low + 4);
        const char* anchor = inside || v < 0 ? "end" : "start";
        svg << "x=\"" << Num(cx + 3.5) << "\" y=\"" << Num(ty) << "\" text-anchor=\"" << anchor
            << "\" transform=\"rotate(-90 " << Num(cx + 3.5) << " " << Num(ty) << ")\">";
      } else {
        const double ty = inside ? top + 14 : (v >= 0 ? top - 4 : low + 12);
        svg << "x=\"" << Num(cx) << "\" y=\"" << Num(ty) << "\" text-anchor=\"middle\">";
      }
      svg << text << "</text>";
    }
    svg << "</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace scout::report
