#include "scout/report/csv_table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scout/common/error.h"
#include "scout/common/input_file.h"

namespace scout::report {
namespace {

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  // getline drops a trailing empty field ("a,b,"); keep it so counts are honest.
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

CsvTable CsvTable::Read(const std::filesystem::path& path,
                        const std::vector<std::string>& required_columns) {
  RequireRegularFile(path, "a CSV table");
  std::ifstream in(path);
  if (!in) throw InputError("cannot open '" + path.string() + "'");
  CsvTable table;
  table.path_ = path;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // Spreadsheets save CSV with a UTF-8 byte order mark before the header.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (line.empty()) continue;
    std::vector<std::string> fields = SplitFields(line);
    if (table.header_.empty()) {
      table.header_ = std::move(fields);
      continue;
    }
    if (fields.size() != table.header_.size()) {
      throw InputError(path.string() + ":" + std::to_string(line_number) + ": expected " +
                       std::to_string(table.header_.size()) + " fields, got " +
                       std::to_string(fields.size()));
    }
    table.cells_.push_back(std::move(fields));
    table.line_numbers_.push_back(line_number);
  }
  if (table.header_.empty()) throw InputError(path.string() + ":1: missing header line");
  for (const std::string& column : required_columns) {
    if (!table.Has(column)) {
      throw InputError(path.string() + ":1: header lacks column '" + column + "'");
    }
  }
  return table;
}

bool CsvTable::Has(const std::string& column) const {
  for (const std::string& h : header_) {
    if (h == column) return true;
  }
  return false;
}

int CsvTable::Column(const std::string& column) const {
  for (size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == column) return static_cast<int>(i);
  }
  throw InputError(path_.string() + ":1: header lacks column '" + column + "'");
}

const std::string& CsvTable::Text(int row, const std::string& column) const {
  return cells_.at(row)[Column(column)];
}

double CsvTable::Number(int row, const std::string& column) const {
  const std::string& text = Text(row, column);
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InputError(Where(row) + ": column '" + column + "' is '" + text + "', expected a number");
  }
  return value;
}

std::string CsvTable::Where(int row) const {
  return path_.string() + ":" + std::to_string(line_numbers_.at(row));
}

}  // namespace scout::report
