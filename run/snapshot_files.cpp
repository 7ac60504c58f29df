#include "run/snapshot_files.hpp"

#include <sstream>

#include "common/validate.hpp"

namespace coldblast::run {

namespace {
using common::format_number;

std::string snapshot_csv(const md::ResolvedScene& scene, long long index, const md::SnapshotFrame& frame) {
  const int d = scene.config.d;
  std::ostringstream out;
  out << run_file_header(scene, {{"realization", std::to_string(index)}, {"t", format_number(frame.t)}})
      << (d == 2 ? "id,x,y,moving,impurity\n" : "id,x,y,z,moving,impurity\n");
  for (std::size_t i = 0; i < frame.size(); ++i) {
    out << frame.id[i];
    for (int k = 0; k < d; ++k) out << ',' << format_number(frame.position[i * d + k]);
    out << ',' << int{frame.moving[i]} << ',' << int{frame.impurity[i]} << '\n';
  }
  return out.str();
}

std::string trajectories_csv(const md::ResolvedScene& scene, long long index, const std::vector<md::PathPoint>& paths) {
  const int d = scene.config.d;
  std::ostringstream file;
  file << run_file_header(scene, {{"realization", std::to_string(index)}}) << (d == 2 ? "id,t,x,y\n" : "id,t,x,y,z\n");
  for (const auto& p : paths) {
    file << p.id << ',' << format_number(p.t);
    for (int k = 0; k < d; ++k) file << ',' << format_number(p.position[static_cast<std::size_t>(k)]);
    file << '\n';
  }
  return file.str();
}
}  // namespace

md::RealizationExtras realization_extras(const md::ResolvedScene& scene, long long index) {
  md::RealizationExtras extras;
  if (index != 0) return extras;
  if (scene.wants("snapshots")) extras.snapshot_times = scene.snapshot_times;
  extras.paths = scene.wants("trajectories");
  return extras;
}

std::string extxyz_frame(const md::ResolvedScene& scene, const md::SnapshotFrame& frame) {
  const int d = scene.config.d;
  const double L = 2.0 * scene.region_radius, lo = -scene.region_radius;
  const double Lz = d == 3 ? L : 2.0 * scene.config.a;
  const double oz = d == 3 ? lo : -scene.config.a;
  std::ostringstream out;
  out << frame.size() << '\n'
      << "Lattice=\"" << format_number(L) << " 0 0 0 " << format_number(L) << " 0 0 0 " << format_number(Lz)
      << "\" Origin=\"" << format_number(lo) << ' ' << format_number(lo) << ' ' << format_number(oz)
      << "\" Properties=species:S:1:pos:R:3:velo:R:3:mass:R:1:radius:R:1:moving:I:1:collisions:I:1 Time="
      << format_number(frame.t) << " pbc=\"F F F\"\n";
  const double host_radius = scene.config.a, impurity_radius = scene.impurity_radius;
  const double impurity_mass = scene.config.impurities.mass;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const bool impurity = frame.impurity[i] != 0;
    out << (impurity ? 'I' : 'H');
    for (int k = 0; k < 3; ++k) out << ' ' << (k < d ? format_number(frame.position[i * d + k]) : "0");
    for (int k = 0; k < 3; ++k) out << ' ' << (k < d ? format_number(frame.velocity[i * d + k]) : "0");
    out << ' ' << format_number(impurity ? impurity_mass : 1.0) << ' '
        << format_number(impurity ? impurity_radius : host_radius) << ' ' << int{frame.moving[i]} << ' '
        << frame.collisions[i] << '\n';
  }
  return out.str();
}

NamedFiles realization_files(const md::ResolvedScene& scene, long long index, const md::RealizationOutput& output) {
  NamedFiles files;
  std::string extxyz;  // every snapshot as one frame of snapshots.extxyz
  for (const md::SnapshotFrame& frame : output.snapshots) {
    files.push_back({"snapshot_" + format_number(frame.t) + ".csv", snapshot_csv(scene, index, frame)});
    extxyz += extxyz_frame(scene, frame);
  }
  if (!extxyz.empty()) files.push_back({"snapshots.extxyz", extxyz});
  if (!output.paths.empty()) files.push_back({"trajectories.csv", trajectories_csv(scene, index, output.paths)});
  return files;
}

}  // namespace coldblast::run
