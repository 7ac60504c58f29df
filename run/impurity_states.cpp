#include "run/impurity_states.hpp"

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "run/run_directory.hpp"
#include "run/worker_pool.hpp"

namespace coldblast::run {

using md::BlastConfig;
using md::ImpurityState;

std::vector<ImpurityState> impurity_states(const md::ResolvedScene& scene, double t, long long realizations,
                                           int threads, const std::function<void(long long, long long)>& progress) {
  const BlastConfig& c = scene.config;
  common::require_in_range("--time", t, 0.0, c.t_max, common::Bound::open, common::Bound::closed,
                           " (within the scene's (0, t_max])");
  common::require_integer_in_range("--realizations", realizations, 1, 100000000);
  common::require_integer_in_range("--threads", threads, 1, 1024);
  std::vector<std::vector<ImpurityState>> per_realization(static_cast<std::size_t>(realizations));
  std::mutex lock;
  long long done = 0;
  run_slots_in_parallel(per_realization.size(), threads, [&](std::size_t slot, const std::atomic<bool>&) {
    const auto index = static_cast<long long>(slot);
    per_realization[slot] = md::realization_impurity_states(scene, index, t);
    const std::lock_guard<std::mutex> guard(lock);
    ++done;
    if (progress) progress(done, realizations);
  });
  std::vector<ImpurityState> states;
  for (auto& list : per_realization)
    for (auto& s : list) states.push_back(std::move(s));
  return states;
}

std::string impurity_states_csv(const std::vector<ImpurityState>& states, const BlastConfig& config, double t,
                                const std::string& run_id) {
  std::ostringstream t_text;  // 17 digits, as the rows and md::states_scene_keys
  t_text.precision(17);
  t_text << t;
  common::HeaderFields fields{{"run_id", run_id}, {"t", t_text.str()}};
  for (const auto& [key, value] : md::states_scene_keys(config)) fields.push_back({key, value});
  std::ostringstream out;
  out << common::provenance_header(fields, "m = 1 (host), lengths and times of the scene; r from the blast centre");
  const char* axes[] = {"x", "y", "z"};
  out << "realization,impurity,collisions";
  for (int k = 0; k < config.d; ++k) out << ',' << axes[k];
  for (int k = 0; k < config.d; ++k) out << ",v" << axes[k];
  for (int k = 0; k < config.d; ++k) out << ',' << axes[k] << '0';
  out << '\n';
  out.precision(17);
  for (const ImpurityState& s : states) {
    out << s.realization << ',' << s.impurity << ',' << s.collisions;
    for (const auto* part : {&s.r, &s.v, &s.r0})
      for (const double x : *part) out << ',' << x;
    out << '\n';
  }
  return out.str();
}

std::filesystem::path write_impurity_states(const std::filesystem::path& out, const std::vector<ImpurityState>& states,
                                            const BlastConfig& config, double t) {
  const std::string run_id = new_run_id();
  const std::filesystem::path file = out / "impurity_states.csv";
  common::write_file_atomic(file, impurity_states_csv(states, config, t, run_id));
  write_manifest(out, {run_id, "md states", {"impurity_states.csv"}});
  return file;
}

md::ImpurityStates read_impurity_states(const std::filesystem::path& path, int d, const std::string& option) {
  const std::string named = option + " = " + path.string();
  std::error_code error;
  // md states' output directory stands for the file in it.
  const std::filesystem::path file = std::filesystem::is_directory(path, error) ? path / "impurity_states.csv" : path;
  require_one_run(file.parent_path().empty() ? "." : file.parent_path(), option);
  std::ifstream in(file);
  if (!in)
    throw std::invalid_argument(named + ": cannot read the file (an impurity_states.csv of `coldblast md states`)");
  md::ImpurityStates result;
  bool has_t = false, has_columns = false;
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto colon = line.find(": ");
      if (colon == std::string::npos || colon < 3) continue;
      result.header.push_back({line.substr(2, colon - 2), line.substr(colon + 2)});
      if (result.header.back().first == "t") {
        result.t = std::strtod(result.header.back().second.c_str(), nullptr);
        has_t = std::isfinite(result.t) && result.t > 0.0;
      }
      continue;
    }
    if (!has_columns) {
      has_columns = line.rfind("realization,impurity,collisions,", 0) == 0;
      if (!has_columns) throw std::invalid_argument(named + ": no header line realization,impurity,collisions,...");
      continue;
    }
    std::istringstream row(line);
    std::vector<double> values;
    std::string field;
    while (std::getline(row, field, ',')) {
      char* end = nullptr;
      const double x = std::strtod(field.c_str(), &end);
      if (end == field.c_str() || *end != '\0' || !std::isfinite(x))
        throw std::invalid_argument(named + ": line " + std::to_string(number) + ": '" + field + "' is not a number");
      values.push_back(x);
    }
    if (values.size() != static_cast<std::size_t>(3 + 3 * d))
      throw std::invalid_argument(named + ": line " + std::to_string(number) + " has " + std::to_string(values.size()) +
                                  " fields; a d = " + std::to_string(d) + " state has " + std::to_string(3 + 3 * d));
    ImpurityState s;
    s.realization = static_cast<long long>(values[0]);
    s.impurity = static_cast<int>(values[1]);
    s.collisions = static_cast<std::uint64_t>(values[2]);
    s.r.assign(values.begin() + 3, values.begin() + 3 + d);
    s.v.assign(values.begin() + 3 + d, values.begin() + 3 + 2 * d);
    s.r0.assign(values.begin() + 3 + 2 * d, values.end());
    result.states.push_back(std::move(s));
  }
  if (!has_t) throw std::invalid_argument(named + ": no '# t: T' header line with T > 0");
  if (result.states.empty()) throw std::invalid_argument(named + ": no impurity state in it");
  return result;
}

}  // namespace coldblast::run
