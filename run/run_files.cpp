#include "run/run_files.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/jackknife.hpp"
#include "common/validate.hpp"
#include "md/observers.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "run/snapshot_files.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::run {

using md::BlockSums;
using md::ObservableLayout;
using md::ResolvedScene;

namespace {
using common::format_number;
namespace fs = std::filesystem;

const char* units_text = "m = 1 (host mass), k_B = 1, lengths and times in the scene's units (a = host radius)";

std::string number_or_nan(double v) {
  return std::isfinite(v) ? format_number(v) : "nan";
}
}  // namespace

long long BlastResult::realizations() const {
  long long n = 0;
  for (const auto& [b, s] : blocks) n += s.count;
  return n;
}

std::uint64_t BlastResult::collisions() const {
  std::uint64_t n = 0;
  for (const auto& [b, s] : blocks) n += s.collisions;
  return n;
}

double BlastResult::energy_error_max() const {
  double e = 0.0;
  for (const auto& [b, s] : blocks) e = std::max(e, s.energy_error_max);
  return e;
}

EnsembleTotals ensemble_totals(const BlastResult& result) {
  const std::size_t size = ObservableLayout(result.scene).size();
  EnsembleTotals totals;
  totals.sum.assign(size, 0.0);
  totals.sum_squares.assign(size, 0.0);
  for (const auto& [b, s] : result.blocks) {  // block order: identical for any threads/shards
    for (std::size_t e = 0; e < size; ++e) {
      totals.sum[e] += s.sum[e];
      totals.sum_squares[e] += s.sum_squares[e];
    }
    totals.count += s.count;
  }
  return totals;
}

double EnsembleTotals::standard_error(std::size_t e) const {
  if (count < 2) return std::nan("");
  const double mean = sum[e] / count;
  return std::sqrt(std::max(0.0, (sum_squares[e] - sum[e] * mean) / (count - 1)) / count);
}

std::vector<ObservableEstimate> estimate_observables(const BlastResult& result) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  const EnsembleTotals totals = ensemble_totals(result);
  const long long N = totals.count;
  std::vector<ObservableEstimate> rows;
  for (std::size_t k = 0; k < scene.times.size(); ++k)
    for (const theory::ObservableInfo& o : theory::observable_catalogue()) {
      if (!theory::is_md_scalar(o)) continue;
      const int e = layout.scalar(o.id, static_cast<int>(k));
      if (e < 0) continue;
      const double mean = totals.sum[e] / N;
      double value = mean, error = totals.standard_error(e);
      if (o.transform == theory::Transform::sqrt) {
        // Eq. (38) (and u_flow): sqrt of the ensemble mean; delta method. u_flow's mean of
        // |ū|² − s²/N can be <= 0 when the flow is below the noise: reported as 0.
        value = mean > 0.0 ? theory::apply_transform(theory::Transform::sqrt, mean) : 0.0;
        error = value > 0.0 ? error / (2.0 * value) : std::nan("");
      }
      rows.push_back({scene.times[k], o.name, value, error, N});
    }
  return rows;
}

std::string run_file_header(const ResolvedScene& s, const std::string& run_id, const common::HeaderFields& extra) {
  common::HeaderFields fields = {{"run_id", run_id},
                                 {"scene", s.config.name},
                                 {"seed", std::to_string(s.config.seed)},
                                 {"A_d", format_number(s.A_d) + " (" + s.A_d_source + ")"},
                                 {"particles", std::to_string(s.particle_count)},
                                 {"region_radius", format_number(s.region_radius)}};
  fields.insert(fields.end(), extra.begin(), extra.end());
  std::string header = common::provenance_header(fields, units_text) + "# resolved scene (TOML):\n";
  std::istringstream toml_lines(scene_toml(s.config));
  std::string line;
  while (std::getline(toml_lines, line))
    if (!line.empty()) header += "#   " + line + "\n";
  return header;
}

common::Json blast_summary(const BlastResult& result) {
  const ResolvedScene& s = result.scene;
  const md::BlastConfig& c = s.config;
  std::ostringstream scene_json;
  scene_json << toml::json_formatter{toml::parse(std::string_view(scene_toml(c)))};
  // Cost figures count the work done in wall_seconds: without the blocks a resumed run loaded.
  const double collisions = static_cast<double>(result.collisions() - result.resumed_collisions);
  const long long realizations_run = result.realizations() - result.resumed_realizations;
  common::Json j;
  j["run_id"] = result.run_id;
  if (!result.merged_from.empty()) j["merged_from"] = result.merged_from;
  j["scene"] = common::Json::parse(scene_json.str());
  j["seed"] = c.seed;
  j["realizations"] = result.realizations();
  j["collisions_total"] = result.collisions();
  j["wall_seconds"] = result.wall_seconds;
  j["collisions_per_second"] = result.wall_seconds > 0.0 ? collisions / result.wall_seconds : 0.0;
  j["energy_error_max"] = result.energy_error_max();
  j["d"] = c.d;
  j["n"] = c.n;
  j["a"] = c.a;
  j["E"] = c.E;
  j["phi"] = s.phi;
  j["lambda"] = s.lambda;
  j["A_d"] = s.A_d;
  j["A_d_source"] = s.A_d_source;
  j["particles"] = s.particle_count;
  j["region_radius"] = s.region_radius;
  j["R_theory_at_t_max"] = s.shock_radius_at_t_max;
  j["R_over_lambda_at_t_max"] = s.shock_radius_at_t_max / s.lambda;
  j["recording_times"] = s.times.size();
  j["block_size"] = c.block_size;
  j["blocks"] = result.blocks.size();
  j["seconds_per_realization"] =
      realizations_run > 0 ? result.wall_seconds * result.threads * result.ranks / realizations_run : 0.0;
  j["resumed_realizations"] = result.resumed_realizations;
  j["resumed_collisions"] = result.resumed_collisions;
  j["threads"] = result.threads;
  j["ranks"] = result.ranks;
  j["shard"] = std::to_string(result.shard_index) + "/" + std::to_string(result.shard_count);
  j["scene_toml"] = scene_toml(c);
  return j;
}

namespace {

std::string observables_csv(const BlastResult& result, const std::string& header) {
  std::ostringstream out;
  out << header << "t,observable,mean,stderr,count\n";
  for (const auto& row : estimate_observables(result))
    out << format_number(row.t) << ',' << row.observable << ',' << number_or_nan(row.mean) << ','
        << number_or_nan(row.stderr_) << ',' << row.count << '\n';
  return out.str();
}

/// blocks.csv (scalar sums, read by compare/), accumulators.csv and block_totals.csv (every entry
/// and block total, exact: read back by merge_blast_outputs).
void add_block_files(const BlastResult& result, const std::string& header, NamedFiles& files) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  std::ostringstream out, acc, totals;
  out << header << "block,t,observable,sum,count\n";
  acc << header << accumulator_header << '\n';
  totals << header << block_totals_header << '\n';
  for (const auto& [b, s] : result.blocks) {
    for (std::size_t k = 0; k < scene.times.size(); ++k)
      for (const theory::ObservableInfo& o : theory::observable_catalogue()) {
        const int e = theory::is_md_scalar(o) ? layout.scalar(o.id, static_cast<int>(k)) : -1;
        if (e >= 0)
          out << b << ',' << format_number(scene.times[k]) << ',' << o.name << ',' << format_number(s.sum[e]) << ','
              << s.count << '\n';
      }
    for (std::size_t e = 0; e < layout.size(); ++e)
      acc << b << ',' << e << ',' << layout.channel(e) << ',' << format_number(scene.times[layout.time_index(e)]) << ','
          << layout.bin(e) << ',' << format_number(s.sum[e]) << ',' << format_number(s.sum_squares[e]) << '\n';
    totals << b << ',' << s.count << ',' << s.collisions << ',' << format_number(s.energy_error_max) << '\n';
  }
  files.emplace_back("blocks.csv", out.str());
  files.emplace_back("accumulators.csv", acc.str());
  files.emplace_back("block_totals.csv", totals.str());
}

/// A profile bin's temperature from its four channels' sums (n/n∞, Σ u_r, Σ m v², count: the
/// particles of the bin pooled over the realizations): T = (Σ m v²/count − u²)/d, u = Σ u_r/count,
/// m = 1 (the hosts' mass; docs/md-output.md); 0 for an empty bin.
double bin_temperature(const std::vector<double>& sum, int e0, int d) {
  const double count = sum[e0 + 3];
  if (!(count > 0)) return 0.0;
  const double u = sum[e0 + 1] / count;
  return std::max(0.0, (sum[e0 + 2] / count - u * u) / d);
}

/// Every profile bin's temperature with its delete-one-block jackknife error (common/jackknife.hpp;
/// NaN with fewer than 2 blocks): a ratio of pooled sums, so the blocks, not the realizations'
/// sums of squares, carry its error. In the order of layout.profile(k, b, 0) over k, then b.
common::Jackknife profile_temperatures(const BlastResult& result, const EnsembleTotals& totals) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  const int bins = scene.config.profile_bins, times = static_cast<int>(scene.times.size());
  std::vector<const BlockSums*> blocks;
  for (const auto& [b, s] : result.blocks) blocks.push_back(&s);
  return common::block_jackknife(static_cast<long>(blocks.size()), [&](long left_out) {
    std::vector<double> sum = totals.sum;
    if (left_out != common::all_blocks)
      for (std::size_t e = 0; e < sum.size(); ++e) sum[e] -= blocks[static_cast<std::size_t>(left_out)]->sum[e];
    std::vector<double> T;
    for (int k = 0; k < times; ++k)
      for (int b = 0; b < bins; ++b) T.push_back(bin_temperature(sum, layout.profile(k, b, 0), scene.config.d));
    return T;
  });
}

std::string profiles_csv(const BlastResult& result, const EnsembleTotals& totals, const std::string& header) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  const std::vector<double>& S = totals.sum;
  const double N = static_cast<double>(totals.count);
  const common::Jackknife T = profile_temperatures(result, totals);
  std::ostringstream out;
  out << header
      << "t,bin,r_over_R_lo,r_over_R_hi,density_over_n,density_stderr,radial_velocity,temperature,particles,"
         "temperature_stderr\n";
  const int bins = scene.config.profile_bins;
  const double width = 1.5 / bins;
  std::size_t i = 0;
  for (std::size_t k = 0; k < scene.times.size(); ++k)
    for (int b = 0; b < bins; ++b, ++i) {
      const int e0 = layout.profile(static_cast<int>(k), b, 0);
      const double count = S[e0 + 3];
      const double u = count > 0 ? S[e0 + 1] / count : 0.0;
      out << format_number(scene.times[k]) << ',' << b << ',' << format_number(b * width) << ','
          << format_number((b + 1) * width) << ',' << format_number(S[e0] / N) << ','
          << number_or_nan(totals.standard_error(e0)) << ',' << format_number(u) << ',' << format_number(T.value[i])
          << ',' << format_number(count / N) << ',' << number_or_nan(T.error(i)) << '\n';
    }
  return out.str();
}

/// p_imp.csv: Eq. (39) [eq:pr]'s radial density in bins of width R(t)/bins, R(t) of Eq. (1).
std::string p_imp_csv(const BlastResult& result, const EnsembleTotals& totals, const std::string& header) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  const double N = static_cast<double>(totals.count);  // streamed as a double, as always
  std::ostringstream out;
  out << header << "t,bin,r_lo,r_hi,r,p,p_stderr,count\n";
  const int bins = scene.config.p_imp_bins;
  const theory::BlastParameters p{scene.config.d, scene.config.n, scene.config.a, scene.config.E, scene.A_d};
  for (std::size_t k = 0; k < scene.times.size(); ++k) {
    const double width = theory::shock_radius(p, scene.times[k]) / bins;
    for (int b = 0; b < bins; ++b) {
      const int e = layout.p_imp(static_cast<int>(k), b);
      out << format_number(scene.times[k]) << ',' << b << ',' << format_number(b * width) << ','
          << format_number((b + 1) * width) << ',' << format_number((b + 0.5) * width) << ','
          << format_number(totals.sum[e] / N / width) << ',' << number_or_nan(totals.standard_error(e) / width) << ','
          << N << '\n';
    }
  }
  return out.str();
}

}  // namespace

NamedFiles blast_data_files(const BlastResult& result) {
  const ObservableLayout layout(result.scene);
  const std::string header = run_file_header(result.scene, result.run_id);
  NamedFiles files{{"observables.csv", observables_csv(result, header)}};
  add_block_files(result, header, files);
  const EnsembleTotals totals = ensemble_totals(result);
  if (layout.has_profiles() && totals.count > 0)
    files.emplace_back("profiles.csv", profiles_csv(result, totals, header));
  if (layout.has_p_imp() && totals.count > 0) files.emplace_back("p_imp.csv", p_imp_csv(result, totals, header));
  files.insert(files.end(), result.realization_files.begin(), result.realization_files.end());
  return files;
}

NamedFiles blast_files(const BlastResult& result) {
  NamedFiles files = blast_data_files(result);
  files.emplace_back("summary.json", blast_summary(result).dump(2) + "\n");
  return files;
}

void write_run_files(const NamedFiles& files, const std::string& run_id, const std::string& kind,
                     const fs::path& directory) {
  common::remove_stale_temporaries(directory);  // writes of a killed earlier attempt
  std::vector<std::string> names;
  for (const auto& [name, content] : files) {
    common::write_file_atomic(directory / name, content);
    names.push_back(name);
  }
  write_manifest(directory, {run_id, kind, names});
}

void write_blast_outputs(const BlastResult& result, const fs::path& directory) {
  write_run_files(blast_files(result), result.run_id, result.kind, directory);
}

}  // namespace coldblast::run
