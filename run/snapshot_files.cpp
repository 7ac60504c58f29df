#include "run/snapshot_files.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/validate.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::run {

namespace {
using common::format_number;

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Realization 0 keeps the names compare's figures read; realization k > 0 adds "_realization_<k>".
std::string file_name(const std::string& stem, long long index, const std::string& extension) {
  return stem + (index == 0 ? "" : "_realization_" + std::to_string(index)) + extension;
}

std::string snapshot_csv(const md::ResolvedScene& scene, const std::string& run_id, long long index,
                         const md::SnapshotFrame& frame) {
  const int d = scene.config.d;
  std::ostringstream out;
  out << run_file_header(scene, run_id, {{"realization", std::to_string(index)}, {"t", format_number(frame.t)}})
      << (d == 2 ? "id,x,y,moving,impurity\n" : "id,x,y,z,moving,impurity\n");
  for (std::size_t i = 0; i < frame.size(); ++i) {
    out << frame.id[i];
    for (int k = 0; k < d; ++k) out << ',' << format_number(frame.position[i * d + k]);
    out << ',' << int{frame.moving[i]} << ',' << int{frame.impurity[i]} << '\n';
  }
  return out.str();
}

std::string trajectories_csv(const md::ResolvedScene& scene, const std::string& run_id, long long index,
                             const std::vector<md::PathPoint>& paths) {
  const int d = scene.config.d;
  std::ostringstream file;
  file << run_file_header(scene, run_id, {{"realization", std::to_string(index)}})
       << (d == 2 ? "id,t,x,y\n" : "id,t,x,y,z\n");
  for (const auto& p : paths) {
    file << p.id << ',' << format_number(p.t);
    for (int k = 0; k < d; ++k) file << ',' << format_number(p.position[static_cast<std::size_t>(k)]);
    file << '\n';
  }
  return file.str();
}
}  // namespace

md::RealizationExtras realization_extras(const md::ResolvedScene& scene, long long index) {
  const md::BlastConfig& c = scene.config;
  md::RealizationExtras extras;
  if (std::find(c.snapshot_realizations.begin(), c.snapshot_realizations.end(), index) == c.snapshot_realizations.end())
    return extras;
  if (scene.wants(theory::Observable::snapshots)) extras.snapshot_times = scene.snapshot_times;
  extras.selection = {c.snapshot_particles == "front", c.snapshot_margin * 2.0 * c.a, c.snapshot_stride};
  extras.paths = scene.wants(theory::Observable::trajectories);
  return extras;
}

double snapshot_bytes_estimate(const md::ResolvedScene& scene) {
  const md::BlastConfig& c = scene.config;
  if (!scene.wants(theory::Observable::snapshots)) return 0.0;
  const theory::BlastParameters blast{c.d, c.n, c.a, c.E, scene.A_d};
  double particles = 0.0;
  for (const double t : scene.snapshot_times) {
    // The front: Eq. (1)'s shock, or the fastest particles' reach while the blast forms (md's bound).
    md::BlastConfig until_t = c;
    until_t.t_max = t;
    const double R = theory::shock_radius(blast, t);  // Eq. (1) [R-shock]
    const double reach = std::max(1.2 * R, md::early_reach_bound(until_t, scene.impurity_radius, R));
    // The region a realization grows to when the reach passes its guard (md/realization.hpp).
    int growths = 0;
    while (md::region_radius_after(scene, growths) - (scene.region_radius - scene.guard_radius) < reach &&
           md::region_radius_after(scene, growths + 1) <= scene.max_region_radius)
      ++growths;
    const double region = md::region_radius_after(scene, growths);
    const double radius = std::min(region, reach + 2.0 * c.a * c.snapshot_margin);
    const double front = c.n * theory::unit_ball_volume(c.d) * std::pow(radius, c.d);
    const auto all = static_cast<double>(md::particles_within(scene, region));
    particles += (c.snapshot_particles == "all" ? all : std::min(all, front)) / c.snapshot_stride;
  }
  return particles * static_cast<double>(c.snapshot_realizations.size()) * (c.d == 2 ? 110.0 : 170.0);
}

std::string snapshot_size_warning(const md::ResolvedScene& scene) {
  const double bytes = snapshot_bytes_estimate(scene);
  if (bytes <= 100e6) return "";
  const md::BlastConfig& c = scene.config;
  std::ostringstream out;
  out << "the snapshots will take about " << common::format_significant(bytes / 1e6, 2) << " MB ("
      << scene.snapshot_times.size() << " times x " << c.snapshot_realizations.size() << " realization"
      << (c.snapshot_realizations.size() == 1 ? "" : "s") << " x about "
      << common::format_significant(
             bytes / (scene.snapshot_times.size() * c.snapshot_realizations.size()) / (c.d == 2 ? 110.0 : 170.0), 2)
      << " particles, in snapshot_<t>.csv and snapshots.extxyz"
      << (c.snapshot_particles == "all" ? ": snapshot_particles = \"all\" writes every particle of the region" : "")
      << "); to write less: " << (c.snapshot_particles == "all" ? "snapshot_particles = \"front\", " : "")
      << "a snapshot_stride, fewer snapshot times or realizations, or leave \"snapshots\" out of observables";
  return out.str();
}

std::string extxyz_frame(const md::ResolvedScene& scene, const std::string& run_id, const md::SnapshotFrame& frame) {
  const int d = scene.config.d;
  const double region = std::max(scene.region_radius, frame.region_radius);  // a grown region is wider
  const double L = 2.0 * region, lo = -region;
  const double Lz = d == 3 ? L : 2.0 * scene.config.a;
  const double oz = d == 3 ? lo : -scene.config.a;
  std::ostringstream out;
  // Z = 0 is ASE's dummy atom X: no reader takes a particle for an element; type_name says what
  // it is. ASE reads `masses` (get_masses) and `momenta` (get_velocities = momenta / masses);
  // OVITO reads `velo` (Velocity), `radius` (Radius), `masses` (Mass) and `id` (Identifier).
  out << frame.size() << '\n'
      << "Lattice=\"" << format_number(L) << " 0 0 0 " << format_number(L) << " 0 0 0 " << format_number(Lz)
      << "\" Origin=\"" << format_number(lo) << ' ' << format_number(lo) << ' ' << format_number(oz)
      << "\" Properties=Z:I:1:type_name:S:1:typeid:I:1:id:I:1:pos:R:3:velo:R:3:momenta:R:3:masses:R:1:radius:R:1:"
         "moving:I:1:collisions:I:1 Time="
      << format_number(frame.t) << " dimensions=" << d << " pbc=\"F F F\" run_id=" << run_id << '\n';
  const double host_radius = scene.config.a, impurity_radius = scene.impurity_radius;
  const double impurity_mass = scene.config.impurities.mass;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const bool impurity = frame.impurity[i] != 0;
    const double mass = impurity ? impurity_mass : 1.0;
    out << "0 " << (impurity ? "impurity 1 " : "host 0 ") << frame.id[i];
    for (int k = 0; k < 3; ++k) out << ' ' << (k < d ? format_number(frame.position[i * d + k]) : "0");
    for (int k = 0; k < 3; ++k) out << ' ' << (k < d ? format_number(frame.velocity[i * d + k]) : "0");
    for (int k = 0; k < 3; ++k) out << ' ' << (k < d ? format_number(mass * frame.velocity[i * d + k]) : "0");
    out << ' ' << format_number(mass) << ' ' << format_number(impurity ? impurity_radius : host_radius) << ' '
        << int{frame.moving[i]} << ' ' << frame.collisions[i] << '\n';
  }
  return out.str();
}

NamedFiles realization_files(const md::ResolvedScene& scene, const std::string& run_id, long long index,
                             const md::RealizationOutput& output) {
  NamedFiles files;
  std::string extxyz;  // every snapshot as one frame of snapshots.extxyz
  for (const md::SnapshotFrame& frame : output.snapshots) {
    files.push_back(
        {file_name("snapshot_" + format_number(frame.t), index, ".csv"), snapshot_csv(scene, run_id, index, frame)});
    extxyz += extxyz_frame(scene, run_id, frame);
  }
  if (!extxyz.empty()) files.push_back({file_name("snapshots", index, ".extxyz"), extxyz});
  if (!output.paths.empty())
    files.push_back({file_name("trajectories", index, ".csv"), trajectories_csv(scene, run_id, index, output.paths)});
  return files;
}

bool is_realization_file_name(const std::string& name) {
  return (starts_with(name, "snapshot_") && ends_with(name, ".csv")) ||
         (starts_with(name, "snapshots") && ends_with(name, ".extxyz")) ||
         (starts_with(name, "trajectories") && ends_with(name, ".csv"));
}

}  // namespace coldblast::run
