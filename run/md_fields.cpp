#include "run/md_fields.hpp"

#include <map>
#include <stdexcept>

#include "common/input.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"

namespace coldblast::run {

namespace fs = std::filesystem;

namespace {

/// summary.json of an `md run` folder (checked to be one).
common::Json md_run_summary(const fs::path& directory, const std::string& option) {
  const std::string named = option + " = " + directory.string();
  if (!fs::is_directory(directory)) throw std::invalid_argument(named + " is not a directory");
  const fs::path path = directory / "summary.json";
  if (!fs::exists(path))
    throw std::invalid_argument(named + " is not an `md run` folder: it has no summary.json (a finished run's)");
  require_one_run(directory, option);
  common::Json summary;
  try {
    summary = common::Json::parse(common::read_text(path, option + " file"));
  } catch (const common::Json::exception& e) {
    throw std::invalid_argument(path.string() + ": malformed JSON (" + e.what() + ")");
  }
  if (!summary.is_object() || !summary.contains("scene_toml") || !summary.at("scene_toml").is_string())
    throw std::invalid_argument(named + " is not an `md run` folder: its summary.json has no scene_toml");
  const auto engine = summary.find("engine");
  if (engine != summary.end() && engine->is_string() && engine->get<std::string>().rfind("tracer", 0) == 0)
    throw std::invalid_argument(named + " is a tracer run; --background md needs the fields of an `md run`");
  return summary;
}

/// The observable R (the ensemble's moving-mass radius) at every recorded time of observables.csv.
std::map<double, double> recorded_R(const fs::path& directory, const std::string& option) {
  const fs::path path = directory / "observables.csv";
  const common::CsvTable table = common::parse_csv(common::read_text(path, option + " file"), path.string());
  const std::size_t t = table.column("t"), name = table.column("observable"), mean = table.column("mean");
  std::map<double, double> R;
  for (const common::CsvRow& row : table.rows)
    if (row.fields[name] == "R")
      R[common::parse_finite(row.fields[t], table.where(row))] =
          common::parse_finite(row.fields[mean], table.where(row));
  return R;
}

/// profiles.csv as bins and frames, each frame's scale R taken from `R` at its time.
kinetic::MeasuredProfiles read_profiles(const fs::path& path, const std::map<double, double>& R,
                                        const std::string& named) {
  const common::CsvTable table = common::parse_csv(common::read_text(path), path.string());
  const std::size_t ct = table.column("t"), cbin = table.column("bin"), clo = table.column("r_over_R_lo"),
                    chi = table.column("r_over_R_hi"), cn = table.column("density_over_n"),
                    cu = table.column("radial_velocity"), cT = table.column("temperature");
  kinetic::MeasuredProfiles p;
  for (const common::CsvRow& row : table.rows) {
    const std::string where = table.where(row);
    const double t = common::parse_finite(row.fields[ct], where);
    const long long bin = common::parse_count(row.fields[cbin], where);
    if (p.frames.empty() || p.frames.back().t != t) {
      const auto found = R.find(t);
      if (found == R.end())
        throw std::invalid_argument(named + ": observables.csv has no R at t = " + common::format_number(t) +
                                    " (the MD must record the observable R, the profiles' scale r/R)");
      p.frames.push_back({t, found->second, {}, {}, {}});
    }
    kinetic::ProfileFrame& f = p.frames.back();
    if (bin != static_cast<long long>(f.density.size()))
      throw std::invalid_argument(where + ": bin " + std::to_string(bin) + " out of order (bins 0, 1, ... per time)");
    const double lo = common::parse_finite(row.fields[clo], where), hi = common::parse_finite(row.fields[chi], where);
    if (p.frames.size() == 1) {
      if (p.edges.empty()) p.edges.push_back(lo);
      p.edges.push_back(hi);
    } else if (bin + 1 >= static_cast<long long>(p.edges.size()) || lo != p.edges[bin] || hi != p.edges[bin + 1]) {
      throw std::invalid_argument(where + ": the bins of r/R differ from the first time's");
    }
    f.density.push_back(common::parse_finite(row.fields[cn], where));
    f.velocity.push_back(common::parse_finite(row.fields[cu], where));
    f.temperature.push_back(common::parse_finite(row.fields[cT], where));
  }
  return p;
}

}  // namespace

std::string md_run_scene_toml(const fs::path& directory, const std::string& option) {
  return md_run_summary(directory, option).at("scene_toml").get<std::string>();
}

MdRunFields read_md_run_fields(const fs::path& directory, const std::string& option) {
  const std::string named = option + " = " + directory.string();
  const common::Json summary = md_run_summary(directory, option);
  MdRunFields run;
  if (summary.contains("run_id") && summary.at("run_id").is_string())
    run.run_id = summary.at("run_id").get<std::string>();
  run.scene_toml = summary.at("scene_toml").get<std::string>();
  run.scene = parse_scene(run.scene_toml, {}, (directory / "summary.json").string());
  const fs::path path = directory / "profiles.csv";
  if (!fs::exists(path))
    throw std::invalid_argument(named +
                                " recorded no profiles (no profiles.csv): run the MD with the observables "
                                "profiles and R (--set 'observables=[..., \"R\", \"profiles\"]')");
  run.profiles = read_profiles(path, recorded_R(directory, option), named);
  run.profiles.d = run.scene.d;
  run.profiles.n = run.scene.n;
  try {
    run.profiles.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(named + ": " + e.what());
  }
  return run;
}

std::string scene_physics_difference(const md::BlastConfig& md_scene, const md::BlastConfig& tracer_scene) {
  const auto& m = md_scene;
  const auto& t = tracer_scene;
  const std::pair<const char*, std::pair<double, double>> keys[] = {
      {"d", {m.d, t.d}},
      {"n", {m.n, t.n}},
      {"a", {m.a, t.a}},
      {"E", {m.E, t.E}},
      {"impurities.count", {m.impurities.count, t.impurities.count}},
      {"impurities.mass", {m.impurities.mass, t.impurities.mass}},
      {"impurities.radius", {m.impurities.radius, t.impurities.radius}}};  // recollide: the tracer has none
  for (const auto& [key, values] : keys)
    if (values.first != values.second)
      return std::string("its ") + key + " is " + common::format_number(values.first) + ", " +
             common::format_number(values.second) + " here";
  return {};
}

}  // namespace coldblast::run
