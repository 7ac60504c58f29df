#include "compare/run_data.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "run/checkpoint.hpp"
#include "run/run_directory.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

Transform transform_for(const std::string& observable) {
  const theory::ObservableInfo* info = theory::find_observable(observable);
  if (info && theory::is_block_scalar(*info)) return info->transform;
  throw std::invalid_argument("observable = " + observable + " is unknown; allowed: " +
                              theory::join_names(theory::observable_names(theory::is_block_scalar)));
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
    values[k] = theory::apply_transform(transform, mean);
  }
  return values;
}

double BlockSeries::realizations_at(std::size_t k) const {
  double count = 0.0;
  for (const auto& block : counts) count += block[k];
  return count;
}

std::map<std::string, BlockSeries> parse_blocks_csv(const std::string& text, const std::string& source) {
  // Collect (observable, block, t) -> (sum, count), then lay out dense arrays.
  struct Cell {
    double sum, count;
  };
  std::map<std::string, std::map<long, std::map<double, Cell>>> cells;
  const common::CsvTable table = common::parse_csv(text, source, "block,t,observable,sum,count");
  for (const common::CsvRow& row : table.rows) {
    const std::string where = table.where(row);
    const auto& fields = row.fields;
    const double block = common::parse_finite(fields[0], where + " (block)");
    if (block < 0 || block != std::floor(block))
      throw std::invalid_argument(where + ": block must be a non-negative integer");
    const double t = common::parse_finite(fields[1], where + " (t)");
    transform_for(fields[2]);  // rejects unknown observables
    const double sum = common::parse_finite(fields[3], where + " (sum)");
    const double count = common::parse_finite(fields[4], where + " (count)");
    if (count < 0) throw std::invalid_argument(where + ": count must be >= 0");
    cells[fields[2]][static_cast<long>(block)][t] = Cell{sum, count};
  }

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

bool is_tracer_run(const RunData& run) {
  const auto engine = run.summary.find("engine");
  return engine != run.summary.end() && engine->is_string() && engine->get<std::string>().rfind("tracer", 0) == 0;
}

std::string run_label(const RunData& run) {
  return is_tracer_run(run) ? "tracer" : "MD";
}

RunData read_run(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory))
    throw std::invalid_argument("RUN_DIR = " + directory.string() + " is not a directory");
  run::require_one_run(directory, "RUN_DIR");  // a folder that mixes two runs' files is refused
  RunData run;
  run.directory = directory;
  const auto summary_path = directory / "summary.json";
  if (!std::filesystem::exists(summary_path) &&
      std::filesystem::exists(run::checkpoint_folder(directory) / "scene.toml"))
    throw std::invalid_argument("RUN_DIR = " + directory.string() +
                                " is a run in progress (it holds only its checkpoint): `coldblast md merge " +
                                directory.string() + " --out DIR` gives its finished realizations as a run to compare");
  try {
    run.summary = common::Json::parse(common::read_text(summary_path, "RUN_DIR file"));
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
  run.series = parse_blocks_csv(common::read_text(blocks_path, "RUN_DIR file"), blocks_path.string());
  if (run.series.empty()) throw std::invalid_argument(blocks_path.string() + ": no data rows");
  return run;
}

double md_R_over_lambda(const RunData& run, double t) {
  // The MD's own shock radius (observable R, interpolated in ln t) over λ of the run's summary;
  // without a recorded R, Eq. (1) with the run's E, n and A_d.
  const auto number = [&](const char* key) {
    if (!run.summary.contains(key) || !run.summary[key].is_number())
      throw std::invalid_argument((run.directory / "summary.json").string() + ": no number '" + key + "'");
    return run.summary[key].get<double>();
  };
  const double lambda = number("lambda");
  const auto found = run.series.find("R");
  if (found == run.series.end()) {
    const theory::BlastParameters p{run.d, number("n"), number("a"), number("E"), number("A_d")};
    return theory::shock_radius(p, t) / lambda;
  }
  const BlockSeries& R = found->second;
  const auto values = R.ensemble_values();
  if (t <= R.t.front()) return values.front() / lambda;
  if (t >= R.t.back()) return values.back() / lambda;
  const auto upper = std::upper_bound(R.t.begin(), R.t.end(), t);
  const std::size_t k = static_cast<std::size_t>(upper - R.t.begin());
  const double w = std::log(t / R.t[k - 1]) / std::log(R.t[k] / R.t[k - 1]);
  return std::exp((1 - w) * std::log(values[k - 1]) + w * std::log(values[k])) / lambda;
}

}  // namespace coldblast::compare
