#ifndef SCOUT_REPORT_CSV_TABLE_H_
#define SCOUT_REPORT_CSV_TABLE_H_

#include <filesystem>
#include <string>
#include <vector>

namespace scout::report {

// A comma-separated file with a header line, as Scout writes them (no quoting:
// Scout's fields never contain commas). Cells are kept as text; the accessors
// convert and name the file and line when a value is not what was expected.
class CsvTable {
 public:
  // Reads 'path'. Throws InputError naming the file when it cannot be opened,
  // has no header, lacks one of 'required_columns', or a row has a different
  // number of fields than the header (naming file:line).
  static CsvTable Read(const std::filesystem::path& path,
                       const std::vector<std::string>& required_columns);

  int rows() const { return static_cast<int>(cells_.size()); }
  // Returns true when the header names 'column'.
  bool Has(const std::string& column) const;
  // Returns the text of 'column' in data row 'row' (0-based).
  const std::string& Text(int row, const std::string& column) const;
  // Returns the finite number in 'column' of 'row'; throws InputError naming
  // file:line and the column otherwise.
  double Number(int row, const std::string& column) const;
  // Returns "file:line" of data row 'row', for error messages.
  std::string Where(int row) const;

 private:
  int Column(const std::string& column) const;

  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<int> line_numbers_;
};

}  // namespace scout::report

#endif  // SCOUT_REPORT_CSV_TABLE_H_
