#ifndef SCOUT_REPORT_HTML_PAGE_H_
#define SCOUT_REPORT_HTML_PAGE_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace scout::report {

// A file of a report, relative to the directory it belongs in
// ("report.html", "figures/accuracy.svg").
struct ReportFile {
  std::string name;
  std::string content;
};

// Returns 'bytes' in standard base64 (RFC 4648, padded).
std::string Base64(const std::string& bytes);

// Returns a data: URI holding the PNG file 'path', so the page needs no other
// file. Throws InputError when it cannot be read.
std::string PngDataUri(const std::filesystem::path& path);

// Returns the scalar leaves of 'object' as (dotted key, text) rows in key
// order, skipping the top-level keys in 'skip'. Short arrays of scalars are
// joined with ", "; longer or nested arrays are summarised by their length.
std::vector<std::pair<std::string, std::string>> FlattenJson(
    const nlohmann::json& object, const std::vector<std::string>& skip = {});

// Returns the text of a JSON scalar (numbers with 6 significant digits).
std::string JsonText(const nlohmann::json& value);

// Returns an HTML table: a header row, then one row per entry of 'rows';
// cells are escaped. Numeric-looking cells are right-aligned.
std::string HtmlTable(const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows);

// Returns a complete HTML5 page (inline stylesheet, no external resources).
std::string HtmlPage(const std::string& title, const std::string& body);

// Returns 'value' in printf 'format', or "–" when it is not finite.
std::string FormatNumber(const char* format, double value);

}  // namespace scout::report

#endif  // SCOUT_REPORT_HTML_PAGE_H_
