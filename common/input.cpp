#include "common/input.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace coldblast::common {

namespace {
/// "16 MiB" for whole mebibytes, else "N bytes".
std::string size_text(std::size_t bytes) {
  if (bytes > 0 && bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}
}  // namespace

std::string read_text(const std::filesystem::path& path, const std::string& what, std::size_t max_bytes) {
  const auto refuse = [&](const std::string& why) {
    return std::invalid_argument(what.empty() ? "cannot read " + path.string() + ": it " + why
                                              : what + " = " + path.string() + " " + why);
  };
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw refuse("is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw what.empty() ? std::invalid_argument("cannot read " + path.string()) : refuse("cannot be read");
  // Chunked, so that an endless device (/dev/zero) stops at the limit instead of filling the memory.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) throw refuse("is longer than " + size_text(max_bytes) + ", the limit for this input");
  }
  if (in.bad()) throw refuse("cannot be read");
  return text;
}

std::vector<std::string> split_fields(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

namespace {
std::size_t column_index(const std::vector<std::string>& columns, const std::string& name, const std::string& source) {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::invalid_argument(source + ": no column '" + name + "'");
}
}  // namespace

std::string CsvTable::where(const CsvRow& row) const {
  return source + " line " + std::to_string(row.line);
}

std::size_t CsvTable::column(const std::string& name) const {
  return column_index(columns, name, source);
}

CsvTable parse_csv(const std::string& text, const std::string& source, const std::string& expected_header) {
  CsvTable table;
  table.source = source;
  std::istringstream stream(text);
  std::string line;
  long line_number = 0;
  bool header_seen = false;
  while (std::getline(stream, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      if (!expected_header.empty() && line != expected_header)
        throw std::invalid_argument(source + " line " + std::to_string(line_number) + ": header must be '" +
                                    expected_header + "', found '" + line + "'");
      table.header_line = line;
      table.columns = split_fields(line);
      header_seen = true;
      continue;
    }
    CsvRow row{line_number, split_fields(line)};
    if (row.fields.size() != table.columns.size())
      throw std::invalid_argument(table.where(row) + ": expected " + std::to_string(table.columns.size()) +
                                  " fields, found " + std::to_string(row.fields.size()));
    table.rows.push_back(std::move(row));
  }
  if (!header_seen)
    throw std::invalid_argument(source + ": empty, no header" +
                                (expected_header.empty() ? std::string(" line") : " '" + expected_header + "'"));
  return table;
}

double parse_finite(const std::string& text, const std::string& where) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(value)) throw std::invalid_argument("");
    return value;
  } catch (const std::exception&) {
    throw std::invalid_argument(where + ": '" + text + "' is not a finite number");
  }
}

double parse_number_or_nan(const std::string& text, const std::string& where) {
  return text == "nan" ? std::nan("") : parse_finite(text, where);
}

long long parse_count(const std::string& text, const std::string& where) {
  try {
    std::size_t used = 0;
    const long long value = std::stoll(text, &used);
    if (used != text.size() || value < 0) throw std::invalid_argument("");
    return value;
  } catch (const std::exception&) {
    throw std::invalid_argument(where + ": '" + text + "' is not a non-negative integer");
  }
}

std::size_t NumericTable::column(const std::string& name) const {
  return column_index(columns, name, source);
}

NumericTable read_numeric_csv(const std::filesystem::path& path) {
  const CsvTable text = parse_csv(read_text(path), path.string());
  NumericTable table{text.source, text.columns, {}};
  table.rows.reserve(text.rows.size());
  for (const CsvRow& row : text.rows) {
    std::vector<double> values;
    values.reserve(row.fields.size());
    for (const auto& field : row.fields) values.push_back(parse_finite(field, text.where(row)));
    table.rows.push_back(std::move(values));
  }
  return table;
}

}  // namespace coldblast::common
