#include "md/states.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "md/engine.hpp"
#include "md/ensemble.hpp"
#include "md/event_queue.hpp"

namespace coldblast::md {

namespace {
template <int D>
std::vector<ImpurityState> realization_states(const ResolvedScene& scene, long long index, double t) {
  const InitialState<D> state = blast_initial_state<D>(scene, index);
  // The engine of `md run` (blast_engine_config; bucketed and heap calendars give the same
  // trajectories, tested), without observers: they do not change a trajectory.
  Engine<D, CalendarEventQueue> engine(blast_engine_config<D>(scene), state);
  engine.run_until(t);
  std::vector<ImpurityState> states;
  for (std::size_t id = 0; id < state.size(); ++id) {
    if (state.species[id] != impurity_species) continue;
    const auto i = static_cast<std::int32_t>(id);
    ImpurityState s;
    s.realization = index;
    s.impurity = static_cast<int>(states.size());
    s.collisions = engine.particle(i).collisions;
    const Vec<D> r = engine.position(i), v = engine.velocity(i);
    for (int k = 0; k < D; ++k) {
      s.r.push_back(r[k]);
      s.v.push_back(v[k]);
      s.r0.push_back(state.position[id][k]);
    }
    states.push_back(std::move(s));
  }
  return states;
}

std::string number_text(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}
}  // namespace

std::vector<ImpurityState> impurity_states(const ResolvedScene& scene, double t, long long realizations, int threads,
                                           const std::function<void(long long, long long)>& progress) {
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
    per_realization[slot] = c.d == 2 ? realization_states<2>(scene, index, t) : realization_states<3>(scene, index, t);
    const std::lock_guard<std::mutex> guard(lock);
    ++done;
    if (progress) progress(done, realizations);
  });
  std::vector<ImpurityState> states;
  for (auto& list : per_realization)
    for (auto& s : list) states.push_back(std::move(s));
  return states;
}

std::vector<std::pair<std::string, std::string>> states_scene_keys(const BlastConfig& c) {
  return {{"d", std::to_string(c.d)},
          {"n", number_text(c.n)},
          {"a", number_text(c.a)},
          {"E", number_text(c.E)},
          {"impurities.count", std::to_string(c.impurities.count)},
          {"impurities.mass", number_text(c.impurities.mass)},
          {"impurities.radius", number_text(c.impurities.radius)},
          {"impurities.recollide", c.impurities.recollide ? "true" : "false"}};
}

std::string impurity_states_csv(const std::vector<ImpurityState>& states, const BlastConfig& config, double t) {
  common::HeaderFields fields{{"t", number_text(t)}};
  for (const auto& [key, value] : states_scene_keys(config)) fields.push_back({key, value});
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

ImpurityStatesFile read_impurity_states(const std::filesystem::path& path, int d, const std::string& option) {
  const std::string named = option + " = " + path.string();
  std::error_code error;
  // md states' output directory stands for the file in it.
  const std::filesystem::path file = std::filesystem::is_directory(path, error) ? path / "impurity_states.csv" : path;
  std::ifstream in(file);
  if (!in)
    throw std::invalid_argument(named + ": cannot read the file (an impurity_states.csv of `coldblast md states`)");
  ImpurityStatesFile result;
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

}  // namespace coldblast::md
