#include "scout/report/csv_reader.h"

#include <charconv>
#include <cmath>

#include "scout/common/error.h"
#include "scout/common/input_file.h"

namespace scout::report {

CsvReader::CsvReader(const std::filesystem::path& path,
                     const std::vector<std::string>& required_columns)
    : path_(path) {
  RequireRegularFile(path, "a CSV table");
  in_.open(path);
  if (!in_) throw InputError("cannot open '" + path.string() + "'");
  while (std::getline(in_, line_)) {
    ++line_number_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    // Spreadsheets save CSV with a UTF-8 byte order mark before the header.
    if (line_number_ == 1 && line_.rfind("\xEF\xBB\xBF", 0) == 0) line_.erase(0, 3);
    if (line_.empty()) continue;
    const size_t n = Split();
    for (size_t f = 0; f < n; ++f) {
      header_.emplace_back(line_, field_begin_[f], field_end_[f] - field_begin_[f]);
    }
    break;
  }
  if (header_.empty()) throw InputError(path.string() + ":1: missing header line");
  for (const std::string& column : required_columns) {
    if (!Has(column)) {
      throw InputError(path.string() + ":1: header lacks column '" + column + "'");
    }
  }
}

size_t CsvReader::Split() {
  field_begin_.clear();
  field_end_.clear();
  size_t begin = 0;
  // A trailing comma ("a,b,") ends in an empty field, counted so that counts
  // are honest.
  for (;;) {
    const size_t comma = line_.find(',', begin);
    field_begin_.push_back(begin);
    field_end_.push_back(comma == std::string::npos ? line_.size() : comma);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return field_begin_.size();
}

bool CsvReader::Next() {
  while (std::getline(in_, line_)) {
    ++line_number_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    if (line_.empty()) continue;
    const size_t n = Split();
    if (n != header_.size()) {
      throw InputError(Where() + ": expected " + std::to_string(header_.size()) + " fields, got " +
                       std::to_string(n));
    }
    return true;
  }
  if (in_.bad())
    throw InputError(path_.string() + ": read error after line " + std::to_string(line_number_));
  return false;
}

bool CsvReader::Has(const std::string& column) const {
  for (const std::string& h : header_) {
    if (h == column) return true;
  }
  return false;
}

int CsvReader::Column(const std::string& column) const {
  for (size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == column) return static_cast<int>(i);
  }
  throw InputError(path_.string() + ":1: header lacks column '" + column + "'");
}

std::string_view CsvReader::Text(int column) const {
  return std::string_view(line_).substr(field_begin_.at(column),
                                        field_end_.at(column) - field_begin_.at(column));
}

double CsvReader::Number(int column) const {
  const std::string_view text = Text(column);
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InputError(Where() + ": column '" + Name(column) + "' is '" + std::string(text) +
                     "', expected a number");
  }
  return value;
}

std::string CsvReader::Where() const { return path_.string() + ":" + std::to_string(line_number_); }

}  // namespace scout::report
