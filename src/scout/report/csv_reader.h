#ifndef SCOUT_REPORT_CSV_READER_H_
#define SCOUT_REPORT_CSV_READER_H_

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace scout::report {

// Reads a comma-separated file with a header line, as Scout writes them (no
// quoting: Scout's fields never contain commas), one data row at a time: a long
// run's frontier.csv holds millions of rows, and keeping every cell as a string
// took 17 times the file's size. The accessors convert the current row's cells
// and name the file and line when a value is not what was expected.
class CsvReader {
 public:
  // Opens 'path' and reads its header. Throws InputError naming the file when it
  // cannot be opened, has no header or lacks one of 'required_columns'.
  CsvReader(const std::filesystem::path& path, const std::vector<std::string>& required_columns);

  // Moves to the next data row (blank lines are skipped); returns false at the
  // end of the file. Throws InputError naming file:line when the row has a
  // different number of fields than the header.
  bool Next();

  // Returns true when the header names 'column'.
  bool Has(const std::string& column) const;
  // Returns the index of 'column'; throws InputError when the header lacks it.
  int Column(const std::string& column) const;
  // The current row's text in column 'column' (an index from Column()).
  std::string_view Text(int column) const;
  // The finite number in 'column' of the current row; throws InputError naming
  // file:line and the column otherwise.
  double Number(int column) const;
  // The header's name of 'column'.
  const std::string& Name(int column) const { return header_.at(column); }
  // "file:line" of the current row, for error messages.
  std::string Where() const;

 private:
  // Splits line_ into field_begin_ / field_end_; returns the number of fields.
  size_t Split();

  std::filesystem::path path_;
  std::ifstream in_;
  std::vector<std::string> header_;
  std::string line_;
  int line_number_ = 0;
  std::vector<size_t> field_begin_, field_end_;  // of the current row, in line_
};

}  // namespace scout::report

#endif  // SCOUT_REPORT_CSV_READER_H_
