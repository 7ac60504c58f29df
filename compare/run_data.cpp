#include "compare/run_data.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace coldblast::compare {

Transform transform_for(const std::string& observable) {
  if (observable == "R_imp" || observable == "V_imp" || observable == "u_flow") return Transform::sqrt;
  static const std::set<std::string> identity = {"C_imp", "u_imp", "n0", "T0", "R", "H"};
  if (identity.count(observable)) return Transform::identity;
  throw std::invalid_argument("observable = " + observable +
                              " is unknown; allowed: R_imp, V_imp, C_imp, u_imp, u_flow, n0, T0, R, H");
}

std::vector<double> BlockSeries::ensemble_values(long excluded) const {
  std::vector<double> values(t.size(), 0.0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    double sum = 0.0, count = 0.0;
    for (std::size_t b = 0; b < sums.size(); ++b) {
      if (static_cast<long>(b) == excluded) continue;
      sum += sums[b][k];
      count += counts[b][k];
    }
    const double mean = count > 0 ? sum / count : std::nan("");
    values[k] = transform == Transform::sqrt ? std::sqrt(mean) : mean;
  }
  return values;
}

double BlockSeries::realizations_at(std::size_t k) const {
  double count = 0.0;
  for (const auto& block : counts) count += block[k];
  return count;
}

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("run directory: cannot read " + path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

double parse_double(const std::string& text, const std::string& where) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(value)) throw std::invalid_argument("");
    return value;
  } catch (const std::exception&) {
    throw std::invalid_argument(where + ": '" + text + "' is not a finite number");
  }
}

}  // namespace

std::map<std::string, BlockSeries> parse_blocks_csv(const std::string& text, const std::string& source) {
  // Collect (observable, block, t) -> (sum, count), then lay out dense arrays.
  struct Cell {
    double sum, count;
  };
  std::map<std::string, std::map<long, std::map<double, Cell>>> cells;
  std::istringstream stream(text);
  std::string line;
  long line_number = 0;
  bool header_seen = false;
  while (std::getline(stream, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::string where = source + " line " + std::to_string(line_number);
    const auto fields = split(line, ',');
    if (!header_seen) {
      if (line != "block,t,observable,sum,count")
        throw std::invalid_argument(where + ": header must be 'block,t,observable,sum,count', found '" + line + "'");
      header_seen = true;
      continue;
    }
    if (fields.size() != 5)
      throw std::invalid_argument(where + ": expected 5 fields, found " + std::to_string(fields.size()));
    const double block = parse_double(fields[0], where + " (block)");
    if (block < 0 || block != std::floor(block))
      throw std::invalid_argument(where + ": block must be a non-negative integer");
    const double t = parse_double(fields[1], where + " (t)");
    transform_for(fields[2]);  // rejects unknown observables
    const double sum = parse_double(fields[3], where + " (sum)");
    const double count = parse_double(fields[4], where + " (count)");
    if (count < 0) throw std::invalid_argument(where + ": count must be >= 0");
    cells[fields[2]][static_cast<long>(block)][t] = Cell{sum, count};
  }
  if (!header_seen) throw std::invalid_argument(source + ": empty, no header 'block,t,observable,sum,count'");

  std::map<std::string, BlockSeries> result;
  for (const auto& [observable, blocks] : cells) {
    std::set<double> times;
    for (const auto& [block, by_time] : blocks)
      for (const auto& [t, cell] : by_time) times.insert(t);
    BlockSeries series;
    series.observable = observable;
    series.transform = transform_for(observable);
    series.t.assign(times.begin(), times.end());
    for (const auto& [block, by_time] : blocks) {
      std::vector<double> sums(series.t.size(), 0.0), counts(series.t.size(), 0.0);
      for (const auto& [t, cell] : by_time) {
        const auto k =
            static_cast<std::size_t>(std::lower_bound(series.t.begin(), series.t.end(), t) - series.t.begin());
        sums[k] = cell.sum;
        counts[k] = cell.count;
      }
      series.sums.push_back(std::move(sums));
      series.counts.push_back(std::move(counts));
    }
    result.emplace(observable, std::move(series));
  }
  return result;
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::invalid_argument(source + ": no column '" + name + "'");
}

CsvTable read_numeric_csv(const std::filesystem::path& path) {
  CsvTable table;
  table.source = path.string();
  std::istringstream stream(read_text(path));
  std::string line;
  long line_number = 0;
  while (std::getline(stream, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto fields = split(line, ',');
    if (table.columns.empty()) {
      table.columns = fields;
      continue;
    }
    const std::string where = table.source + " line " + std::to_string(line_number);
    if (fields.size() != table.columns.size())
      throw std::invalid_argument(where + ": expected " + std::to_string(table.columns.size()) + " fields, found " +
                                  std::to_string(fields.size()));
    std::vector<double> row;
    row.reserve(fields.size());
    for (const auto& field : fields) row.push_back(parse_double(field, where));
    table.rows.push_back(std::move(row));
  }
  if (table.columns.empty()) throw std::invalid_argument(table.source + ": empty, no header line");
  return table;
}

void truncate_run(RunData& run, double until) {
  for (auto& [name, series] : run.series) {
    const double limit = until * (1.0 + 1e-9);
    const auto keep =
        static_cast<std::size_t>(std::upper_bound(series.t.begin(), series.t.end(), limit) - series.t.begin());
    if (keep < 2 || until > series.t.back() * (1.0 + 1e-9)) {
      std::ostringstream message;
      message.precision(10);
      message << "--until = " << until << " is outside the recorded times of " << name << " in "
              << run.directory.string() << ": allowed [" << (series.t.size() > 1 ? series.t[1] : series.t.front())
              << ", " << series.t.back() << "] (the second to the last recorded time)";
      throw std::invalid_argument(message.str());
    }
    series.t.resize(keep);
    for (auto& row : series.sums) row.resize(keep);
    for (auto& row : series.counts) row.resize(keep);
  }
}

RunData read_run(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory))
    throw std::invalid_argument("RUN_DIR = " + directory.string() + " is not a directory");
  RunData run;
  run.directory = directory;
  const auto summary_path = directory / "summary.json";
  try {
    run.summary = common::Json::parse(read_text(summary_path));
  } catch (const common::Json::exception& e) {
    throw std::invalid_argument(summary_path.string() + ": malformed JSON (" + e.what() + ")");
  }
  const common::Json* scene =
      run.summary.contains("scene") && run.summary["scene"].is_object() ? &run.summary["scene"] : nullptr;
  if (run.summary.contains("d") && run.summary["d"].is_number_integer())
    run.d = run.summary["d"].get<int>();
  else if (scene && scene->contains("d") && (*scene)["d"].is_number_integer())
    run.d = (*scene)["d"].get<int>();
  else
    throw std::invalid_argument(summary_path.string() + ": no integer 'd' (top level or in 'scene')");
  if (run.d < 1 || run.d > 3)
    throw std::invalid_argument(summary_path.string() + ": d = " + std::to_string(run.d) + " is outside [1, 3]");
  const auto blocks_path = directory / "blocks.csv";
  run.series = parse_blocks_csv(read_text(blocks_path), blocks_path.string());
  if (run.series.empty()) throw std::invalid_argument(blocks_path.string() + ": no data rows");
  return run;
}

}  // namespace coldblast::compare
