#pragma once
// Input plumbing shared by every reader: whole-file reads and comma-separated tables whose errors
// name the file and the line ("blocks.csv line 7: ..."), the mirror of common/output.*.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace coldblast::common {

/// Largest input read_text accepts by default (run data: blocks.csv, snapshots; 1 GiB).
inline constexpr std::size_t data_size_limit = std::size_t{1} << 30;
/// Largest scene or configuration file (a short TOML text; 16 MiB), so that a device such as
/// /dev/zero given as SCENE fails at once instead of filling the memory.
inline constexpr std::size_t text_size_limit = std::size_t{1} << 24;

/// The bytes of `path`. Throws std::invalid_argument "<what> = <path> cannot be read" (or "is a
/// folder, not a file", or "is longer than <max_bytes> bytes"), what naming the parameter that gave
/// the path (e.g. "SCENE", "--resume"); without it the message starts "cannot read <path>".
std::string read_text(const std::filesystem::path& path, const std::string& what = "",
                      std::size_t max_bytes = data_size_limit);

/// Splits one line at `separator`; a trailing separator yields a trailing empty field.
std::vector<std::string> split_fields(const std::string& line, char separator = ',');

/// One data line of a CSV table: its 1-based line number in the file and its fields.
struct CsvRow {
  long line = 0;
  std::vector<std::string> fields;
};

/// A CSV table: '#' comment lines and empty lines skipped, '\r' stripped, the first remaining line
/// is the column header.
struct CsvTable {
  std::string source;                ///< file name used in messages
  std::string header_line;           ///< the column header as written
  std::vector<std::string> columns;  ///< the header split at commas
  std::vector<CsvRow> rows;
  /// "<source> line <n>", the prefix of every message about `row`.
  std::string where(const CsvRow& row) const;
  /// Index of column `name`; throws std::invalid_argument naming the source otherwise.
  std::size_t column(const std::string& name) const;
};

/// Parses `text` as a CSV table. Throws std::invalid_argument naming `source` when there is no
/// header, when `expected_header` is given and differs, or when a row's field count differs from
/// the header's.
CsvTable parse_csv(const std::string& text, const std::string& source, const std::string& expected_header = "");

/// A CSV table whose fields are all finite numbers after the header.
struct NumericTable {
  std::string source;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of column `name`; throws std::invalid_argument naming the source otherwise.
  std::size_t column(const std::string& name) const;
};
/// Reads `path` as a NumericTable; throws std::invalid_argument naming the file and line.
NumericTable read_numeric_csv(const std::filesystem::path& path);

/// A finite number (the whole field must parse); throws std::invalid_argument "<where>: '<text>' is
/// not a finite number".
double parse_finite(const std::string& text, const std::string& where);
/// As parse_finite, but "nan" (written for undefined values) reads as NaN.
double parse_number_or_nan(const std::string& text, const std::string& where);
/// A whole non-negative integer; throws std::invalid_argument naming `where` otherwise.
long long parse_count(const std::string& text, const std::string& where);

}  // namespace coldblast::common
