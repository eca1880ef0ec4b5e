#include "scout/report/html_page.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "scout/common/error.h"
#include "scout/report/svg_plot.h"

namespace scout::report {
namespace {

bool LooksNumeric(const std::string& s) {
  if (s.empty()) return false;
  for (const char c : s) {
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == 'e' || c == '%')) {
      return false;
    }
  }
  return true;
}

void Flatten(const nlohmann::json& value, const std::string& key,
             std::vector<std::pair<std::string, std::string>>* rows) {
  if (value.is_object()) {
    for (const auto& [k, v] : value.items()) Flatten(v, key.empty() ? k : key + "." + k, rows);
    return;
  }
  if (value.is_array()) {
    bool scalars = value.size() <= 12;
    for (const nlohmann::json& v : value) scalars = scalars && v.is_primitive();
    if (!scalars) {
      rows->emplace_back(key, "[" + std::to_string(value.size()) + " entries]");
      return;
    }
    std::string joined;
    for (const nlohmann::json& v : value) joined += (joined.empty() ? "" : ", ") + JsonText(v);
    rows->emplace_back(key, joined);
    return;
  }
  rows->emplace_back(key, JsonText(value));
}

}  // namespace

std::string Base64(const std::string& bytes) {
  static const char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t chunk = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= static_cast<uint8_t>(bytes[i + 2]);
    out += kAlphabet[(chunk >> 18) & 63];
    out += kAlphabet[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return out;
}

std::string PngDataUri(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path.string() + "'");
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return "data:image/png;base64," + Base64(bytes);
}

std::string JsonText(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_null()) return "–";
  if (value.is_number_float()) return FormatNumber("%.6g", value.get<double>());
  return value.dump();
}

std::vector<std::pair<std::string, std::string>> FlattenJson(const nlohmann::json& object,
                                                             const std::vector<std::string>& skip) {
  std::vector<std::pair<std::string, std::string>> rows;
  if (!object.is_object()) return rows;
  for (const auto& [k, v] : object.items()) {
    bool skipped = false;
    for (const std::string& s : skip) skipped = skipped || s == k;
    if (!skipped) Flatten(v, k, &rows);
  }
  return rows;
}

std::string FormatNumber(const char* format, double value) {
  if (!std::isfinite(value)) return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string HtmlTable(const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream html;
  html << "<table>\n<thead><tr>";
  for (const std::string& h : header) html << "<th>" << EscapeXml(h) << "</th>";
  html << "</tr></thead>\n<tbody>\n";
  for (const std::vector<std::string>& row : rows) {
    html << "<tr>";
    for (const std::string& cell : row) {
      html << (LooksNumeric(cell) ? "<td class=\"num\">" : "<td>") << EscapeXml(cell) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody>\n</table>\n";
  return html.str();
}

std::string HtmlPage(const std::string& title, const std::string& body) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
       << EscapeXml(title) << "</title>\n<style>\n"
       << "body{font-family:'DejaVu Sans',Arial,Helvetica,sans-serif;margin:2em auto;"
          "max-width:1100px;padding:0 1em;color:#222}\n"
          "h1{font-size:1.6em}h2{font-size:1.25em;margin-top:2em;border-bottom:1px solid #ccc}\n"
          "table{border-collapse:collapse;margin:0.5em 0}\n"
          "th,td{border:1px solid #ccc;padding:0.25em 0.6em;text-align:left}\n"
          "th{background:#f0f0f0}td.num{text-align:right;font-variant-numeric:tabular-nums}\n"
          "figure{margin:1em 0}figcaption{color:#555;font-size:0.9em}\n"
          "img.map{max-width:100%;image-rendering:pixelated;border:1px solid #ccc}\n"
          "svg{max-width:100%;height:auto}\n"
       << "</style>\n</head>\n<body>\n<h1>" << EscapeXml(title) << "</h1>\n"
       << body << "</body>\n</html>\n";
  return html.str();
}

}  // namespace scout::report
