#pragma once

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace houghloc {

/// One data line of a CSV file with its 1-based line number in the file.
struct CsvRow {
  int line = 0;
  std::vector<std::string> fields;  ///< trimmed of surrounding spaces
};

/// A small CSV file as DESIGN §5.1 defines them: lines starting with `#` (after optional spaces)
/// and blank lines are skipped, the first other line is the header, fields are separated by
/// commas without quoting. Columns are found by header name, so extra columns are ignored.
/// Every error is a RecordingError "<path>:<line>: <what>".
class CsvTable {
 public:
  /// Throws RecordingError when the file cannot be opened, has no header, repeats a column name
  /// or has a row whose field count differs from the header's.
  static CsvTable read(const std::string& path);

  const std::string& path() const { return path_; }
  const std::vector<CsvRow>& rows() const { return rows_; }

  /// Index of a column; throws RecordingError naming the header line when it is missing.
  int column(const std::string& name) const;
  std::optional<int> optionalColumn(const std::string& name) const;

  /// Field accessors; each throws RecordingError naming file, line and column when the field is
  /// not of the expected type (numbers must be finite; t_us an integer).
  static const std::string& text(const CsvRow& row, int column);
  double number(const CsvRow& row, int column) const;
  /// Empty field -> none; otherwise as number().
  std::optional<double> optionalNumber(const CsvRow& row, int column) const;
  std::int64_t integer(const CsvRow& row, int column) const;

  /// Throws "<path>:<line>: <what>".
  [[noreturn]] void fail(const CsvRow& row, const std::string& what) const;

 private:
  std::string path_;
  int header_line_ = 0;
  std::vector<std::string> header_;
  std::vector<CsvRow> rows_;
};

/// Writes CSV files that CsvTable reads back exactly: numbers with the fewest significant digits
/// (15 to 17) that read back to the same double.
class CsvWriter {
 public:
  /// Throws RecordingError when the file cannot be created.
  CsvWriter(const std::string& path, const std::vector<std::string>& header);

  /// Formats a finite double exactly (see above); throws RecordingError for NaN or infinity.
  std::string format(double value) const;
  std::string format(std::int64_t value) const { return std::to_string(value); }
  /// Writes one row after checking a text field can be read back unchanged (no commas, line breaks
  /// or surrounding spaces, no leading `#` in the first column); throws RecordingError otherwise.
  void writeRow(const std::vector<std::string>& fields);
  /// Flushes and closes; throws RecordingError when writing failed.
  void close();

 private:
  std::string path_;
  std::size_t columns_ = 0;
  std::ofstream out_;
};

}  // namespace houghloc
